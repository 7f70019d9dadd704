/**
 * What ../Plot.tsx loads when its first plot comes near the screen: the chart's layout, its
 * readout, its SVG and the axes' pixel mapping, one chunk that no page needs before a plot shows.
 */
export { layoutChart, readoutAt } from './model';
export { ChartSvg } from './ChartSvg';
export { pxToUnits } from './axes';
