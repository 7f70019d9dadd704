/**
 * The plots of "Explore further" for readers who cannot see them: a sentence per plotted
 * series (./../../ui/summary's summarizeSeries, with the fitted slope on log–log axes) and the
 * plotted data as table columns. Pure.
 */
import { formatSignificant } from '../../../ui/format';
import { summarizeSeries, type SummaryOptions } from '../../../ui/summary';

/** One plotted series: its legend name and its points. */
export interface NamedSeries {
  label: string;
  xs: ArrayLike<number>;
  ys: ArrayLike<number>;
}

/**
 * Several series of one plot in words, one summary each ("uniform · independent: |error| falls …");
 * `empty` when there is nothing plotted yet.
 */
export function describeSeriesSet(
  series: readonly NamedSeries[],
  o: SummaryOptions & { empty: string },
): string {
  if (!series.length) return o.empty;
  return series.map((s) => `${s.label}: ${summarizeSeries(s.xs, s.ys, o)}`).join(' ');
}

/**
 * The series as one table: the union of their x values (ascending) in the first column, a column per
 * series, NaN (shown as a dash) where a series has no point at that x.
 */
export function seriesTable(
  xLabel: string,
  series: readonly NamedSeries[],
): { columns: string[]; rows: number[][] } {
  const xs = new Set<number>();
  for (const s of series) for (let k = 0; k < s.xs.length; k++) if (Number.isFinite(s.xs[k])) xs.add(s.xs[k]);
  const sorted = [...xs].sort((p, q) => p - q);
  const maps = series.map((s) => {
    const m = new Map<number, number>();
    for (let k = 0; k < Math.min(s.xs.length, s.ys.length); k++) m.set(s.xs[k], s.ys[k]);
    return m;
  });
  return {
    columns: [xLabel, ...series.map((s) => s.label)],
    rows: sorted.map((x) => [x, ...maps.map((m) => m.get(x) ?? NaN)]),
  };
}

const num = (v: number, d = 4) => (Number.isFinite(v) ? formatSignificant(v, d, 'times') : '—');

/**
 * The unbiasedness histogram in words: how many estimates, their mean against the exact integral
 * in standard errors, their spread, and the bin that holds most of them.
 */
export function describeEstimateHistogram(o: {
  count: number;
  N: number;
  mean: number;
  sd: number;
  sem: number;
  exact: number;
  centers: readonly number[];
  counts: readonly number[];
}): string {
  if (!o.count) return 'Histogram of independent estimates: none yet.';
  let top = 0;
  for (let k = 1; k < o.counts.length; k++) if (o.counts[k] > o.counts[top]) top = k;
  const off = o.sem > 0 ? ` (${num((o.mean - o.exact) / o.sem, 2)} standard errors off)` : '';
  return (
    `Histogram of ${o.count} independent estimates, each from ${o.N} sample${o.N === 1 ? '' : 's'}: ` +
    `mean ${num(o.mean, 6)} against the exact ${num(o.exact, 6)}${off}, spread (sd) ${num(o.sd, 3)}; ` +
    `the tallest bar, ${o.counts[top]} estimates, is at ${num(o.centers[top], 4)}.`
  );
}
