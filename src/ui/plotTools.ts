/**
 * The tool buttons every plot (./Plot.tsx) carries, apart so that tests can count them without
 * loading React: save the plot as a PNG, zoom in and out, and go back to the axes it opened with
 * (a mouse drag also zooms to a box, a double click goes back). Every button is a tab stop, so
 * there are no more of them than a reader of a small mathematical plot uses.
 */
export const PLOT_TOOLS = ['save', 'zoomIn', 'zoomOut', 'reset'] as const;

export type PlotTool = (typeof PLOT_TOOLS)[number];
