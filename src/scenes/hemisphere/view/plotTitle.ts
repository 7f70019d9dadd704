/**
 * A plot title pinned inside the top of the plot's box (container coordinates) with a top margin
 * that fits it at classroom font sizes, so it is never clipped above the plot (present=1); with
 * `legendRow`, the margin also holds a row for the legend between the title and the plot.
 */
export function titled(
  text: string,
  legendRow = false,
): {
  title: Record<string, unknown>;
  margin: { l: number; r: number; t: number; b: number };
} {
  return {
    title: { text, y: 1, yref: 'container', yanchor: 'top', pad: { t: 6 } },
    margin: { l: 56, r: 16, t: legendRow ? 76 : 46, b: 44 },
  };
}

/** Legend inside the plot's top-left corner (where both marginals are low), clear of the axis titles. */
export const LEGEND_INSIDE = {
  orientation: 'v',
  x: 0.02,
  y: 0.98,
  xanchor: 'left',
  yanchor: 'top',
  bgcolor: 'rgba(0,0,0,0)',
};
