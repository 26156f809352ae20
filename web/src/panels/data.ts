// The data panel: the numbers at the playhead (t, E, J₃, tension, z, drifts, power), the tension's extremes
// so far, the model (for the swinging spring its length and stretch, for the string whether it is taut or
// slack), and — for the ideal pendulum — the exact-solution quantities of the current orbit
// (POST /api/exact): kind, turning heights, z-period, azimuthal advance, rotation number and its dynamic
// and geometric parts. For the string, the last events (went slack, snapped taut with the energy lost). The
// global position error of the state shown and how it was obtained (errorRows; docs/web.md, "Error estimate").
import type { ExactQuantities, Frame, Status } from '../protocol';
import type { LabStore } from '../state';
import { offSphereNote, tetherStyle } from '../models';
import { eventRow } from '../events';
import { fmt } from '../format';
import { kindWords, methodWords, modelWords, t } from '../i18n';
import { isAdvanced } from '../advanced';

export { fmt };

type Row = [label: string, value: string, unit: string];

/** The rows of the live section. */
export function liveRows(f: Frame | null, store: LabStore): Row[] {
  const ref = store.reference;
  const s = store.status;
  const ex = store.tensionExtremes;
  const rows: Row[] = [
    ['t', fmt(f?.t, 7), 's'],
    [t('data.energy'), fmt(f?.energy, 10), 'J'],
    [t('data.energyChange'), f && ref ? fmt(f.energy - ref.energy, 3) : '—', 'J'],
    [t('data.spin'), fmt(f?.j3, 10), 'kg m²/s'],
    [t('data.spinChange'), f && ref ? fmt(f.j3 - ref.j3, 3) : '—', 'kg m²/s'],
    [t('data.tension'), fmt(f?.tension, 6), 'N'],
    [t('data.tensionMin'), ex ? `${fmt(ex.min, 6)} (t = ${fmt(ex.tMin, 4)} s)` : '—', 'N'],
    [t('data.tensionMax'), ex ? `${fmt(ex.max, 6)} (t = ${fmt(ex.tMax, 4)} s)` : '—', 'N'],
    [t('data.height'), fmt(f?.x[2], 6), 'm'],
    [t('data.method'), s ? `${methodWords(s.method, 0)}${s.adaptive ? '' : `, dt = ${s.dt} s`}` : '—', ''],
    [t('data.state'), s ? `${s.paused ? t('data.paused') : t('data.running')}${s.lagging ? t('data.lagging') : ''}` : '—', ''],
    ...errorRows(f, s),
  ];
  if (s && s.model !== 'ideal') {
    rows.splice(1, 0, [t('data.model'), modelWords(s.model, s.model), '']);
    rows.splice(4, 0, [t('data.power'), fmt(f?.power, 6), 'W']);
  }
  const at = rows.findIndex((r) => r[0] === t('data.tension'));
  const style = tetherStyle(s?.model, f?.taut ?? true);
  if (style === 'coil' && s) {
    // the spring: its force k(|r| − l₀) (> 0 pulling), its length and stretch (l is the rest length l₀)
    const r = f ? Math.hypot(...f.x) : null;
    rows[at] = [t('data.springForce'), fmt(f?.tension, 6), 'N'];
    rows.splice(at + 1, 0, [t('data.springLength'), fmt(r, 6), 'm'], [
      t('data.stretch'),
      r === null ? '—' : fmt(r - s.params.length, 4),
      'm',
    ]);
  } else if (style === 'slack string') {
    rows[at] = [t('data.tension'), t('data.slackZero'), 'N'];
    rows.splice(at + 1, 0, [t('data.string'), t('data.slack', { r: fmt(f ? Math.hypot(...f.x) : null, 5) }), '']);
  } else if (style === 'taut string') {
    rows.splice(at + 1, 0, [t('data.string'), t('data.taut'), '']);
  }
  if (s?.model === 'string') {
    // the last leaves and snaps of this trajectory, newest first (the server's event notices)
    const events = [...store.events].reverse().map(eventRow);
    rows.push(...(events.length > 0 ? events : [[t('data.events'), t('data.noEvents'), ''] as Row]));
  }
  return rows;
}

/** The rows of the error estimate (issue 17): the global position error of the state shown [m] (the
 *  frames' error_x), relative to l, and how it was obtained (the status's error_estimate): the true error
 *  against the exact solution for the ideal pendulum, else Richardson against a companion at dt/2 or, for
 *  dop853, a companion at a tighter tolerance; "estimate paused" while the server's companion is behind. */
export function errorRows(f: Frame | null, s: Status | null): Row[] {
  const info = s?.error_estimate;
  if (!s || !info) return [];
  if (info.how === null) return [[t('data.errorHow'), s.model === 'crane' ? t('data.errorCrane') : (info.note ?? t('data.errorNone')), '']];
  const since = fmt(info.since, 6);
  const how =
    info.how === 'exact'
      ? t('data.howExact', { since })
      : info.how === 'richardson'
        ? t('data.howRichardson', { dt: fmt(info.reference.dt, 3), p: info.order ?? '?', since })
        : t('data.howCompanion', { rtol: fmt(info.reference.rtol, 3), since });
  const e = f?.errorX;
  const known = e !== undefined && e >= 0;
  return [
    [t('data.error'), known ? fmt(e, 3) : e === undefined ? '—' : t('data.errorPaused'), known ? 'm' : ''],
    [t('data.errorRel'), known ? fmt(e / s.params.length, 3) : '—', ''],
    [t('data.errorHow'), how, ''],
  ];
}

/** Why there is no exact solution (null when there is one or it is on its way). */
export function exactNote(store: LabStore): string {
  const s = store.status;
  const off = offSphereNote(s?.model);
  if (off !== null) return off;
  if (s && s.model !== 'ideal') {
    return t('note.exactIdeal', { model: modelWords(s.model, s.model) });
  }
  return store.exactError ?? phasesNote(store.exact);
}

/** Why the exact solution has no phases (T-5.x: they need an oscillation of z about a potential minimum,
 *  J₃ ≠ 0 and g ≠ 0), in the page's words from the orbit's kind; '' when it has them. The server's note
 *  (`phases_note`, English) says the same with the numbers. */
export function phasesNote(exact: ExactQuantities | null): string {
  if (exact === null || exact.phases !== null || exact.phases_note === null) return '';
  return exact.kind === 'great_circle' ? t('note.phasesNoGravity') : t('note.phasesPlanar', { kind: kindWords(exact.kind) });
}

/** The rows of the exact-solution section. */
export function exactRows(q: ExactQuantities | null): Row[] {
  if (q === null) return [];
  const h = q.turning_heights;
  const rows: Row[] = [
    [t('data.kind'), kindWords(q.kind), ''],
    [t('data.turning'), `${fmt(h[0])}, ${fmt(h[1])}`, 'm'],
  ];
  if (h.length > 2 && isAdvanced()) rows.push([t('data.z3'), fmt(h[2]), 'm']);
  rows.push([q.kind === 'planar' ? t('data.swingPeriod') : t('data.periodZ'), q.period_z_infinite ? '∞' : fmt(q.period_z), 's']);
  if (q.azimuth_advance !== null) rows.push([t('data.advance'), fmt(q.azimuth_advance), 'rad']);
  // the rotation number and the split of Δφ are the advanced layer's (advanced.ts)
  if (q.rotation_number !== null && isAdvanced()) rows.push([t('data.rotation'), fmt(q.rotation_number), '']);
  if (q.phases !== null && isAdvanced()) {
    rows.push([t('data.dynamic'), fmt(q.phases.dynamic), 'rad']);
    rows.push([t('data.geometric'), fmt(q.phases.geometric), 'rad']);
  }
  return rows;
}

export class DataPanel {
  private readonly live: HTMLTableElement;
  private readonly exactTable: HTMLTableElement;
  private readonly note: HTMLElement;

  constructor(container: HTMLElement) {
    const title = (text: string) => {
      const h = document.createElement('h3');
      h.textContent = text;
      container.appendChild(h);
    };
    title(t('data.now'));
    this.live = document.createElement('table');
    container.appendChild(this.live);
    title(t('data.exact'));
    this.exactTable = document.createElement('table');
    container.appendChild(this.exactTable);
    this.note = document.createElement('p');
    this.note.className = 'note';
    container.appendChild(this.note);
  }

  private fill(table: HTMLTableElement, rows: Row[]): void {
    while (table.rows.length > rows.length) table.deleteRow(-1);
    rows.forEach(([label, value, unit], i) => {
      const tr = table.rows[i] ?? table.insertRow();
      while (tr.cells.length < 3) tr.insertCell();
      const [a, b, c] = [tr.cells[0], tr.cells[1], tr.cells[2]];
      if (a && a.textContent !== label) a.textContent = label;
      if (b && b.textContent !== value) b.textContent = value;
      if (c && c.textContent !== unit) c.textContent = unit;
    });
  }

  update(f: Frame | null, store: LabStore): void {
    this.fill(this.live, liveRows(f, store));
    this.fill(this.exactTable, exactRows(store.exact));
    const note = exactNote(store);
    if (this.note.textContent !== note) this.note.textContent = note;
  }
}
