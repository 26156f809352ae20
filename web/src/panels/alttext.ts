// Text alternatives for the charts (issue 28; docs/web.md, "Keyboard and accessibility"): one sentence per
// chart for a screen reader — what is plotted against what, the ranges shown and the latest point — set as
// the chart's aria-label with role img. No physics: it reads the numbers the chart draws. Units are in the
// axis words given (SI).
import { t } from '../i18n';

const short = (v: number) => (Number.isFinite(v) ? (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(2) : v.toPrecision(3)) : '—');

/** "title: y from a to b against x from c to d; now (x, y)" for the series (xs, ys) (an empty series: "no
 *  data yet"). */
export function chartSummary(title: string, xLabel: string, yLabel: string, xs: readonly number[], ys: readonly (number | null)[]): string {
  let [xLo, xHi, yLo, yHi] = [Infinity, -Infinity, Infinity, -Infinity];
  const n = Math.min(xs.length, ys.length);
  for (let i = 0; i < n; i++) {
    const [x, y] = [xs[i] as number, ys[i] ?? NaN];
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    [xLo, xHi, yLo, yHi] = [Math.min(xLo, x), Math.max(xHi, x), Math.min(yLo, y), Math.max(yHi, y)];
  }
  const head = title ? `${title}: ` : '';
  if (xLo > xHi) return `${head}${t('alt.empty')}`;
  return `${head}${t('alt.summary', {
    y: yLabel,
    x: xLabel,
    yLo: short(yLo),
    yHi: short(yHi),
    xLo: short(xLo),
    xHi: short(xHi),
    xNow: short(xs[n - 1] ?? NaN),
    yNow: short(ys[n - 1] ?? NaN),
  })}`;
}

/** Sets `el`'s text alternative (role img) when it changed. */
export function setAltText(el: Element, text: string): void {
  if (el.getAttribute('role') !== 'img') el.setAttribute('role', 'img');
  if (el.getAttribute('aria-label') !== text) el.setAttribute('aria-label', text);
}
