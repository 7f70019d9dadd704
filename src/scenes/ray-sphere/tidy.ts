/** Round to a step chosen from the view size (keeps dragged values and URLs tidy). */
export function tidy(x: number, step: number): number {
  const y = Math.round(x / step) * step;
  const digits = Math.max(0, Math.min(15, -Math.floor(Math.log10(step))));
  return Number(y.toFixed(digits));
}
