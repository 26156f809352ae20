// Numbers as the panels show them (no DOM).

/** `v` to `digits` significant digits; '—' for none or NaN, ∞ for infinities, exponents outside [1e-3, 1e6). */
export function fmt(v: number | null | undefined, digits = 6): string {
  if (v === null || v === undefined || Number.isNaN(v)) return '—';
  if (!Number.isFinite(v)) return v > 0 ? '∞' : '−∞';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e6 ? v.toPrecision(digits) : v.toExponential(digits - 1);
}
