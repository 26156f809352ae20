// Numbers as the panels show them, and JSON as Python writes it (no DOM).

/** `v` to `digits` significant digits; '—' for none or NaN, ∞ for infinities, exponents outside [1e-3, 1e6). */
export function fmt(v: number | null | undefined, digits = 6): string {
  if (v === null || v === undefined || Number.isNaN(v)) return '—';
  if (!Number.isFinite(v)) return v > 0 ? '∞' : '−∞';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e6 ? v.toPrecision(digits) : v.toExponential(digits - 1);
}

/** The number typed into an `<input type="number">`: NaN when the box is empty or holds what the browser
 *  cannot read as a number ("abc", "1e"; the browser then reports `value` as '' and `validity.badInput`).
 *  `Number('')` is 0, so an emptied or mistyped box read with `Number(input.value)` was taken as 0 (a start
 *  angle of 0°, two pendulums ε = 0 apart) without a word. */
export function typedNumber(input: { readonly value: string; readonly validity: { readonly badInput: boolean } }): number {
  return input.validity.badInput || input.value.trim() === '' ? NaN : Number(input.value);
}

/** `value` as Python's `json.dumps(value, sort_keys=True)` writes it (keys sorted, `", "` and `": "` between
 *  items): the CLI's CSV metadata line, so the lab's reads the same (numbers as JavaScript writes them, each
 *  read back exactly). */
export function pythonJSON(value: unknown): string {
  if (Array.isArray(value)) return `[${value.map(pythonJSON).join(', ')}]`;
  if (value !== null && typeof value === 'object') {
    const entries = Object.entries(value as Record<string, unknown>).filter(([, v]) => v !== undefined);
    entries.sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0));
    return `{${entries.map(([k, v]) => `${JSON.stringify(k)}: ${pythonJSON(v)}`).join(', ')}}`;
  }
  return JSON.stringify(value) ?? 'null';
}
