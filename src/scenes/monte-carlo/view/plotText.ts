/**
 * The words of the scene's "Explore further" plots, one entry per plot (test ids `${id}-plot` and
 * `${id}-table`): the heading above it, its accessible name, the caption of its "Show as table"
 * (where the caption depends on the data, the plot's own words give it) and its layout. Kept in
 * one place so that the figures' code is about their data and the texts can be read (or
 * translated) together.
 */
import type { PlotLayout } from '../../../ui';
import { L_ERR, L_EST, L_FUNC, L_HIST, L_RMSE, L_TIME } from './plotStyle';

export interface PlotText {
  heading?: string;
  label: string;
  caption?: string;
  layout: PlotLayout;
}

export const PLOT_TEXT = {
  integrand: {
    label: 'The integrand f(x) and the sampling pdf p(x), scaled to the same height, over [a, b]',
    caption: 'f(x) and the pdf p(x) over [a, b]',
    layout: L_FUNC,
  },
  'convergence-estimate': {
    heading: 'Running estimate',
    label:
      'Running estimate against the number of samples N, on a log axis, for several strategies, with the exact value',
    caption: 'Running estimate against N, per strategy',
    layout: L_EST,
  },
  'convergence-error': {
    heading: '|error| of one run, log-log, with N⁻½ and N⁻¹ guides',
    label:
      'Absolute error against N on log-log axes, with guide lines falling as N to the −½ and N to the −1 and fitted slopes',
    caption: '|estimate − exact| against N, per strategy',
    layout: L_ERR,
  },
  rmse: {
    heading: 'RMSE over the runs (band: 10–90 % of |error|)',
    label:
      'Root mean square error over independent runs against N, log-log, with bands from the 10th to the 90th percentile of the absolute error',
    caption: 'RMSE over the runs and the 10–90 % band of |error|, against N, per strategy',
    layout: L_RMSE,
  },
  'rmse-time': {
    heading: 'Accuracy per millisecond: RMSE against run time',
    label: 'RMSE against the measured wall-clock time of one estimate, log-log, per strategy',
    caption: 'Time of one estimate (ms) and its RMSE, against N, per strategy',
    layout: L_TIME,
  },
  'estimates-histogram': {
    label: 'Histogram of many independent estimates at fixed N, with their mean and the exact integral',
    layout: L_HIST,
  },
} satisfies Record<string, PlotText>;

export type PlotId = keyof typeof PLOT_TEXT;
