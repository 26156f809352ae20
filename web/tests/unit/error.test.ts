// The data panel's error estimate (issue 17; docs/web.md, "Error estimate"): the frames' error_x with its
// unit, relative to l, how it was obtained (the status's error_estimate), "estimate paused" for −1, in
// every language of the lab; the interpolation keeps an unknown error unknown.
import { afterEach, describe, expect, it } from 'vitest';
import { errorRows, exactNote, liveRows, phasesNote } from '../../src/panels/data';
import type { ErrorEstimateInfo, ExactQuantities, Frame, Status } from '../../src/protocol';
import { LANGUAGES, setLanguage, t } from '../../src/i18n';
import type { Lang } from '../../src/i18n';
import { LabStore, interpolateFrames } from '../../src/state';

function frame(time: number, errorX: number): Frame {
  return {
    t: time,
    x: [0.5, 0, -Math.sqrt(0.75) * 2],
    v: [0, 1, 0],
    energy: -9.81,
    j3: 0.5,
    tension: 10,
    power: 0,
    a: [0, 0, 0],
    pivot: [0, 0, 0],
    taut: true,
    errorX,
  };
}

function status(info: ErrorEstimateInfo | undefined, length = 2): Status {
  const s: Status = {
    type: 'status',
    epoch: 0,
    scenario: 'rosette',
    title: null,
    paused: false,
    time_scale: 1,
    method: 'rattle',
    adaptive: false,
    dt: 0.001,
    params: { length, mass: 1, g: 9.81 },
    model: 'damped',
    model_params: {},
    t: 0,
    t0: 0,
    start: { x: [0, 0, -length], v: [0, 0, 0] },
    lagging: false,
    frame_fields: [],
  };
  if (info !== undefined) s.error_estimate = info;
  return s;
}

const RICHARDSON: ErrorEstimateInfo = { how: 'richardson', order: 2, reference: { dt: 0.0005 }, since: 1.5, note: null };
const EXACT: ErrorEstimateInfo = { how: 'exact', order: null, reference: {}, since: 0, note: null };
const COMPANION: ErrorEstimateInfo = { how: 'companion', order: null, reference: { rtol: 1e-13, atol: 1e-15 }, since: 0, note: null };

afterEach(() => setLanguage('en'));

describe('the error estimate in the data panel', () => {
  it('shows the error in metres, relative to l, and how it was obtained', () => {
    const rows = errorRows(frame(3, 2.5e-7), status(RICHARDSON));
    expect(rows).toEqual([
      ['position error |Δx|', '2.50e-7', 'm'],
      ['position error / l', '1.25e-7', ''],
      ['error obtained by', 'estimate: Richardson against a companion at dt/2 = 5.00e-4 s, order p = 2 (since t = 1.50000 s)', ''],
    ]);
    expect(errorRows(frame(3, 1e-9), status(EXACT))[2]?.[1]).toBe('the true error: against the exact solution (since t = 0 s)');
    expect(errorRows(frame(3, 1e-9), status(COMPANION))[2]?.[1]).toBe('estimate: a companion run at rtol = 1.00e-13 (since t = 0 s)');
    expect(errorRows(frame(0, 0), status(EXACT))[0]).toEqual(['position error |Δx|', '0', 'm']);
  });

  it('says "estimate paused" while the server could not afford it (error_x = −1)', () => {
    const rows = errorRows(frame(3, -1), status(RICHARDSON));
    expect(rows[0]?.[1]).toMatch(/^estimate paused/);
    expect(rows[0]?.[2]).toBe('');
    expect(rows[1]?.[1]).toBe('—');
  });

  it('says why there is none, and shows nothing before a status', () => {
    const none: ErrorEstimateInfo = { how: null, order: null, reference: {}, since: 0, note: 'no estimate: the companion run cannot start (x)' };
    expect(errorRows(frame(3, -1), status(none))).toEqual([['error obtained by', 'no estimate: the companion run cannot start (x)', '']]);
    expect(errorRows(frame(3, 1e-3), null)).toEqual([]);
    expect(errorRows(frame(3, 1e-3), status(undefined))).toEqual([]);
  });

  it('the crane mode, the models and the phases in the page language, not the server’s English (issue 28)', () => {
    const crane = { ...status({ how: null, order: null, reference: {}, since: 0, note: "no estimate: the crane mode runs the crane's DOP853 at the session's rtol, atol" }), model: 'crane' };
    setLanguage('de');
    expect(errorRows(frame(3, -1), crane)[0]?.[1]).toMatch(/^keine Schätzung: der Kranmodus rechnet/);
    const store = new LabStore();
    store.onStatus(crane);
    expect(exactNote(store)).toBe('die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell „Portalkran (Kranmodus)“');
    store.onStatus(status(EXACT));
    expect(exactNote(store)).toContain('„Gedämpft und angetrieben“');
    const planar = { kind: 'planar', phases: null, phases_note: "phases are defined for orbits with J3 != 0 (kinds generic, conical); this orbit is 'planar'" } as unknown as ExactQuantities;
    expect(phasesNote(planar)).toBe('keine Phasen: sie teilen die Drehung einer Bahn, die um die Senkrechte kreist; diese Bahn ' + t('kind.planar'));
    setLanguage('fr');
    expect(phasesNote({ ...planar, kind: 'great_circle' })).toMatch(/^pas de phases : sans pesanteur/);
    expect(phasesNote({ ...planar, phases: { total: 1, dynamic: 0.5, geometric: 0.5 }, phases_note: null })).toBe('');
    expect(phasesNote(null)).toBe('');
    setLanguage('en');
  });

  it('is part of the live rows', () => {
    const store = new LabStore();
    store.onStatus(status(EXACT));
    const labels = liveRows(frame(1, 1e-6), store).map((r) => r[0]);
    expect(labels).toContain('position error |Δx|');
    expect(labels).toContain('error obtained by');
  });

  it('is translated in every language of the lab, with the same placeholders', () => {
    const keys = ['data.error', 'data.errorRel', 'data.errorHow', 'data.errorPaused', 'data.errorNone', 'data.howExact', 'data.howRichardson', 'data.howCompanion'] as const;
    for (const lang of Object.keys(LANGUAGES) as Lang[]) {
      setLanguage(lang);
      const rows = errorRows(frame(3, 2.5e-7), status(RICHARDSON));
      expect(rows[2]?.[1]).toContain('5.00e-4');
      expect(rows[2]?.[1]).not.toMatch(/\{\w+\}/);
      expect(rows[0]?.[2]).toBe('m');
      for (const k of keys) {
        if (lang !== 'en') expect(t(k), `${lang}: ${k}`).not.toBe(LANGUAGES.en.words[k]);
      }
    }
  });

  it('interpolates a known error and keeps an unknown one unknown', () => {
    expect(interpolateFrames(frame(0, 1e-6), frame(1, 3e-6), 0.5).errorX).toBeCloseTo(2e-6, 18);
    expect(interpolateFrames(frame(0, 1e-6), frame(1, -1), 0.5).errorX).toBe(-1);
    expect(interpolateFrames(frame(0, -1), frame(1, 1e-6), 0.5).errorX).toBe(-1);
  });
});
