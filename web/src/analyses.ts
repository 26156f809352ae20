// What the page asks the server to compute about the current orbit (REST, docs/web.md): the exact
// solution (POST /api/exact, ideal pendulum), V_eff(θ) (POST /api/effective_potential), the energy–
// momentum map's boundary (POST /api/em_map) and the reduced view (POST /api/reduced, ideal pendulum).
// Each is fetched when what it depends on changes, and a late answer for an older epoch is dropped.
import type { EMView, EffectivePotential, ExactQuantities, Frame, ReducedCurves, Status } from './protocol';
import type { ReducedView } from './scene/reduced';
import type { LabStore } from './state';
import { offSphereNote, staysOnSphere } from './models';
import { httpProblem, modelWords, t } from './i18n';

/** GET or POST JSON; an HTTP error becomes an Error with the server's words (`httpProblem`: keyed ones in
 *  the page's language). */
export async function getJSON<T>(path: string, init?: RequestInit): Promise<T> {
  const r = await fetch(path, init);
  const body: unknown = await r.json();
  if (!r.ok) throw new Error(httpProblem(body, `${path}: HTTP ${r.status}`));
  return body as T;
}

/** A request that was no longer wanted when its turn came (a newer epoch or parameters): not sent. */
export class Stale extends Error {}

/** The server computes at most 2 requests per client at once and answers 429 beyond (docs/web.md, "A pupil
 *  in the room"); a page asks one at a time (two pages or a page and its second pendulum's fit stay within
 *  the limit), in order, and skips a request that is `stale()` when its turn comes. */
const MAX_IN_FLIGHT = 1;
let inFlight = 0;
const waiting: (() => void)[] = [];

async function post<T>(path: string, body: unknown, stale: () => boolean = () => false): Promise<T> {
  if (inFlight >= MAX_IN_FLIGHT) await new Promise<void>((go) => waiting.push(go));
  inFlight++;
  try {
    if (stale()) throw new Stale(`${path}: no longer needed`);
    return await getJSON<T>(path, { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(body) });
  } finally {
    inFlight--;
    waiting.shift()?.();
  }
}

/** Resolves once no computation of this page is under way or waiting (at most `timeoutMs`): a reload (the
 *  language switch) then leaves none running on the server, which counts a client's computations across
 *  its pages and answers 429 beyond 2. */
export function computationsIdle(timeoutMs: number): Promise<void> {
  const end = Date.now() + timeoutMs;
  return new Promise((resolve) => {
    const check = () => (inFlight === 0 && waiting.length === 0) || Date.now() >= end ? resolve() : setTimeout(check, 20);
    check();
  });
}

/** Reports `e` unless the request was skipped as stale. */
const unlessStale = (report: (e: unknown) => void) => (e: unknown) => {
  if (!(e instanceof Stale)) report(e);
};

const message = (e: unknown): string => (e instanceof Error ? e.message : String(e));

export class Analyses {
  /** V_eff(θ) for the current l, m, g and J₃, or null while it is on its way. */
  veff: EffectivePotential | null = null;
  /** The energy–momentum map's boundary for the current l, m, g (none for g = 0). */
  em: EMView | null = null;
  private veffKey = '';
  private veffAt = -Infinity;
  private veffJ3: number | null = null;
  private emKey = '';
  private exactEpoch = -1;
  private reducedEpoch = -1;

  constructor(
    private readonly store: LabStore,
    private readonly reduced: ReducedView,
    private readonly explain: (text: string) => void,
  ) {}

  /** After frames arrived: fetch what the new epoch, parameters or J₃ call for. */
  onFrames(): void {
    const s = this.store.status;
    const first = this.store.trajectory[0];
    const last = this.store.latest();
    if (s === null || first === undefined || last === null) return;
    if (this.exactEpoch !== s.epoch) this.fetchExact(s, first);
    if (this.reducedEpoch !== s.epoch) this.fetchReduced(s, first);
    if (!staysOnSphere(s.model)) {
      // the spring and the string leave the sphere: V_eff and the map are the rod's, not theirs
      [this.veff, this.em, this.veffKey, this.emKey] = [null, null, '', ''];
      return;
    }
    this.fetchEM(s, first);
    this.fetchPotential(s, last);
  }

  /** V_eff: at each epoch's first frame, and again while J₃ changes (models that do not conserve it), at
   *  most once a second. */
  private fetchPotential(status: Status, f: Frame): void {
    const p = status.params;
    const key = `${status.epoch}:${p.length}:${p.mass}:${p.g}`;
    const now = performance.now();
    const stale = Math.abs(f.j3 - (this.veffJ3 ?? NaN)) > 1e-3 * Math.max(Math.abs(f.j3), 1e-9);
    if (key === this.veffKey && !(stale && now - this.veffAt > 1000)) return;
    if (key !== this.veffKey) this.veff = null;
    [this.veffKey, this.veffAt, this.veffJ3] = [key, now, f.j3];
    post<EffectivePotential>('api/effective_potential', { length: p.length, mass: p.mass, g: p.g, j3: f.j3 }, () => this.veffKey !== key).then(
      (q) => {
        if (this.veffKey === key) this.veff = q;
      },
      unlessStale((e) => this.explain(t('msg.veffFailed', { why: message(e) }))),
    );
  }

  /** The map's boundary depends on l, m, g only (the point comes from the frames). */
  private fetchEM(status: Status, f: Frame): void {
    const p = status.params;
    const key = `${p.length}:${p.mass}:${p.g}`;
    if (key === this.emKey) return;
    this.emKey = key;
    this.em = null;
    if (p.g === 0) return; // no potential, no map
    post<EMView>('api/em_map', { length: p.length, mass: p.mass, g: p.g, x: f.x, v: f.v }, () => this.emKey !== key).then(
      (q) => {
        if (this.emKey === key) this.em = q;
      },
      unlessStale((e) => this.explain(t('msg.emFailed', { why: message(e) }))),
    );
  }

  /** The reduced view of the epoch's orbit (the ideal pendulum's: its J₃ and E are the invariants). */
  private fetchReduced(status: Status, f: Frame): void {
    this.reducedEpoch = status.epoch;
    if (status.model !== 'ideal') {
      this.reduced.setNote(
        offSphereNote(status.model) ?? t('note.reducedIdeal', { model: modelWords(status.model, status.model) }),
      );
      return;
    }
    this.reduced.setNote(null);
    const p = status.params;
    const gone = () => this.store.status?.epoch !== status.epoch;
    post<ReducedCurves>('api/reduced', { length: p.length, mass: p.mass, g: p.g, x: f.x, v: f.v }, gone).then(
      (q) => {
        if (!gone()) this.reduced.set(q);
      },
      unlessStale((e) => this.reduced.setNote(`reduced view: ${message(e)}`)),
    );
  }

  /** The exact solution of the epoch's orbit (the closed form is the ideal pendulum's). */
  private fetchExact(status: Status, f: Frame): void {
    this.exactEpoch = status.epoch;
    if (status.model !== 'ideal') return;
    const p = status.params;
    post<ExactQuantities>('api/exact', { length: p.length, mass: p.mass, g: p.g, x: f.x, v: f.v }, () => this.store.status?.epoch !== status.epoch).then(
      (q) => {
        if (this.store.status?.epoch === status.epoch) this.store.setExact(q);
      },
      (e: unknown) => {
        if (this.store.status?.epoch === status.epoch) this.store.setExact(null, message(e));
      },
    );
  }
}
