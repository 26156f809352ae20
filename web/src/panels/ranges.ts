// Axis ranges that never degenerate (docs/web.md, "Plots"): a flat or nearly flat series at a large value
// (a slewing crane's z ≈ −10 m held to 1e-15, a tension of 4905 N) has a span of a few ulps, and the plotting
// library's tick code then asked for an array of ~1e13 ticks (RangeError: Invalid array length). Every
// range handed to a plot goes through `safeRange`: finite, ordered, and at least MIN_RELATIVE_SPAN of the
// values' size wide (or MIN_SPAN near zero). Pure; unit-tested.

/** Least span relative to max(|lo|, |hi|): below it a plot shows a flat line in the middle. */
export const MIN_RELATIVE_SPAN = 1e-6;
/** Least span in absolute terms (values near 0). */
export const MIN_SPAN = 1e-12;
/** The float64 unit roundoff 2⁻⁵² ≈ 2.2e-16: the floor of relative drifts (marked on the log plots). */
export const FLOAT64_EPS = 2 ** -52;

/** [lo, hi] widened to a plottable range: non-finite ends give [−1, 1]; a span below the least is widened
 *  symmetrically about the middle; otherwise `pad` of the span is added on each side. */
export function safeRange(lo: number | null, hi: number | null, pad = 0.05): [number, number] {
  if (lo === null || hi === null || !Number.isFinite(lo) || !Number.isFinite(hi)) return [-1, 1];
  if (lo > hi) [lo, hi] = [hi, lo];
  const least = Math.max(MIN_RELATIVE_SPAN * Math.max(Math.abs(lo), Math.abs(hi)), MIN_SPAN);
  const span = hi - lo;
  if (span < least) {
    const mid = lo / 2 + hi / 2;
    return [mid - least / 2, mid + least / 2];
  }
  return [lo - pad * span, hi + pad * span];
}

/** |Δ| / scale for a log plot: never 0 (shown at a tenth of the float64 floor) and never negative. */
export function relativeDrift(delta: number, scale: number): number | null {
  if (!Number.isFinite(delta) || !(scale > 0)) return null;
  return Math.max(Math.abs(delta) / scale, FLOAT64_EPS / 10);
}

/** The log axis range [10^a, 10^b] (whole decades) covering the values, always including the float64 floor. */
export function logRange(lo: number | null, hi: number | null): [number, number] {
  const floor = FLOAT64_EPS / 10;
  const a = lo !== null && Number.isFinite(lo) && lo > 0 ? Math.min(lo, floor) : floor;
  const b = hi !== null && Number.isFinite(hi) && hi > 0 ? Math.max(hi, 1e-12) : 1e-12;
  return [10 ** Math.floor(Math.log10(a)), 10 ** Math.ceil(Math.log10(b) + 1e-9)];
}
