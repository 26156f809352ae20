// Issue 28's inclusion tools: accessible names containing the visible words in every language, the motion
// in words, keys on the 3-D view, the mystery planet's g [m/s²], charts' text alternatives, the plain
// layer's words, the sound's pitch [Hz] and where "Skip to controls" takes the focus.
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/protocol';
import { PeriodTimer } from '../../src/measure';
import { LANGUAGES, setLanguage, t } from '../../src/i18n';
import { GRAVITY_PRESETS, mysteryGravity, soundPitch } from '../../src/panels/tools';
import { describeMotion } from '../../src/describe';
import { stripFormulaRefs } from '../../src/advanced';
import { chartSummary } from '../../src/panels/alttext';
import { viewKey } from '../../src/keyboard';
import { accessibleName } from '../../src/panels/toolbar';
import { frame, planar } from './classroom_fixtures';
import { firstControl } from '../../src/wiring/page';

describe('inclusion (issue 28)', () => {
  it('"Skip to controls" goes to the first shown, enabled control of the settings panel, past folder titles', () => {
    const el = (name: string, { title = false, shown = true, disabled = false } = {}) => ({
      name,
      classList: { contains: (c: string) => title && c === 'lil-title' },
      getClientRects: () => ({ length: shown ? 1 : 0 }),
      matches: (sel: string) => disabled && sel === ':disabled',
    });
    const panel = [el('root title', { title: true }), el('model', { shown: false }), el('pendulum title', { title: true }), el('off', { disabled: true }), el('length'), el('mass')];
    expect(firstControl(panel)?.name).toBe('length');
    expect(firstControl([el('title', { title: true }), el('hidden', { shown: false })])).toBeNull();
    for (const { words } of Object.values(LANGUAGES)) expect(words['page.skip'].length).toBeGreaterThan(5);
  });
  it('a button’s accessible name contains its visible words (axe label-content-name-mismatch) in every language', () => {
    expect(accessibleName('● Record', 'record a video (WebM)')).toBe('record a video (WebM)');
    expect(accessibleName('● Aufnahme', 'Video aufnehmen (WebM)')).toBe('Aufnahme: Video aufnehmen (WebM)');
    expect(accessibleName('A⁺', 'mode présentation : gros caractères pour un vidéoprojecteur')).toBe('A⁺: mode présentation : gros caractères pour un vidéoprojecteur');
    expect(accessibleName('■ Arrêter', 'arrêter de filmer et télécharger la vidéo')).toBe('arrêter de filmer et télécharger la vidéo');
    expect(accessibleName('▾', 'collapse the panel')).toBe('collapse the panel');
    for (const lang of Object.keys(LANGUAGES) as (keyof typeof LANGUAGES)[]) {
      setLanguage(lang);
      for (const [short, long] of [['toolbar.recordShort', 'toolbar.record'], ['toolbar.recordStopShort', 'toolbar.recordStop'], ['toolbar.startShort', 'toolbar.start'], ['toolbar.pauseShort', 'toolbar.pause']] as const) {
        const name = accessibleName(t(short), t(long)).toLocaleLowerCase();
        expect(name).toContain(t(short).replace(/^[^\p{L}]+/u, '').toLocaleLowerCase());
      }
    }
    setLanguage('en');
  });
  it('describes the motion: angle, rising or falling, speed, the energy split', () => {
    setLanguage('en');
    const x: Vec3 = [Math.sin(0.2), 0, -Math.cos(0.2)];
    const text = describeMotion(frame(0, x, [0.5, 0, 0.1]), { kinetic: 3, potential: 1, lost: 0, total: 4 });
    expect(text).toBe('angle 11° from the vertical, rising, speed 0.51 m/s; energy 75 % kinetic, 25 % potential');
    expect(describeMotion(frame(0, x, [0, 0, 0]), null)).toContain('at rest');
    expect(describeMotion(frame(0, x, [1, 0, -0.5]), { kinetic: 1, potential: 1, lost: 2, total: 4 })).toMatch(/falling.*25 % kinetic, 25 % potential, 50 % lost/);
  });
  it('keys on the 3-D view: arrows turn, + − zoom, Shift + ← → the bob', () => {
    expect(viewKey('ArrowLeft', false)).toEqual({ orbit: [(-5 * Math.PI) / 180, 0], zoom: 1 });
    expect(viewKey('ArrowRight', true)).toEqual({ bob: 1 });
    expect(viewKey('-', false)).toEqual({ orbit: [0, 0], zoom: 1.1 });
    expect(viewKey('x', false)).toBeNull();
  });
  it('a mystery planet is 2 … 20.6 m/s², never near a preset', () => {
    for (let k = 0; k < 1000; k++) {
      const g = mysteryGravity(k / 1000);
      expect(g).toBeGreaterThanOrEqual(2);
      expect(g).toBeLessThanOrEqual(20.6);
      for (const [, p] of GRAVITY_PRESETS) expect(Math.abs(g - p)).toBeGreaterThanOrEqual(0.29);
    }
  });
  it('charts have a text alternative: ranges and the latest point', () => {
    setLanguage('en');
    expect(chartSummary('height z(t)', 'time t [s]', 'z [m]', [0, 1, 2], [-1, -0.5, null])).toBe('height z(t): z [m] from -1.00 to -0.500 against time t [s] from 0.00 to 1.00; now — at 2.00');
    expect(chartSummary('T', 'x', 'y', [], [])).toBe('T: no data yet');
  });
  it('the plain layer drops formula numbers from the words, keeping the rest', () => {
    expect(stripFormulaRefs('linear viscous damping (T-7.1), the force −m c v')).toBe('linear viscous damping, the force −m c v');
    expect(stripFormulaRefs('classic RK4 on the Cartesian ODE T-2.4, no projection')).toBe('classic RK4 on the Cartesian ODE, no projection');
    expect(stripFormulaRefs('Holm’s Figure 2 (docs/theory.md §3)')).toBe('Holm’s Figure 2');
    expect(stripFormulaRefs('in a rotating frame (Foucault, T-7.3), optionally damped')).toBe('in a rotating frame (Foucault), optionally damped');
  });
  it('sound: 440 Hz at rest, an octave per 2 m/s, at most 1760 Hz; one count per lowest point', () => {
    expect(soundPitch(0)).toBe(440);
    expect(soundPitch(2)).toBe(880);
    expect(soundPitch(100)).toBe(1760);
    const p = new PeriodTimer();
    for (const f of planar((t) => 0.3 * Math.cos(2 * Math.PI * t), (t) => -0.6 * Math.PI * Math.sin(2 * Math.PI * t), 2.1)) p.push(f);
    expect(p.lowCount).toBe(4); // lowest points at 0.25, 0.75, 1.25, 1.75 s
  });
});
