import type { LegendSpec } from '../../../ui';

/** A plot's title, centred above its plot area (the chart makes room for it and the legend). */
export function titled(text: string): { title: { text: string } } {
  return { title: { text } };
}

/** Legend inside the plot's top-left corner (where both marginals are low), clear of the axis titles. */
export const LEGEND_INSIDE: LegendSpec = {
  orientation: 'v',
  x: 0.02,
  y: 0.98,
  xanchor: 'left',
  yanchor: 'top',
  bgcolor: 'rgba(0,0,0,0)',
};
