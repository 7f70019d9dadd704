/** A number with d significant digits for the page's prose and tables ('—' when it is not finite). */
export const fmt = (x: number, d = 4): string =>
  Number.isFinite(x) ? Number(x.toPrecision(d)).toString() : '—';
