/**
 * The one Plotly config of every plot (./Plot.tsx), apart so that tests can read it without
 * loading React or Plotly.
 *
 * The mode bar holds what a reader of a small mathematical plot uses: save it as a PNG, zoom in
 * and out, and go back to the axes it opened with (a drag still zooms to a box). Plotly's
 * drag-mode toggles (zoom, pan) and autoscale are left out: every button is a tab stop, and a
 * page with four plots would otherwise carry 28 of them.
 *
 * Nothing may leave the site: no "Edit in Chart Studio", "Share chart", "Send data to cloud" or
 * "link to plotly" action (they upload the plot's data to Plotly's servers), and no Plotly logo link.
 */
export const MODEBAR_BUTTONS = ['toImage', 'zoomIn2d', 'zoomOut2d', 'resetScale2d'] as const;

/**
 * Where every plot's legend goes: one row above the plot area, left-aligned, outside the data
 * whatever its shape and at any width (below the plot, a legend met the x-axis title on a phone).
 */
export const PLOT_LEGEND = Object.freeze({
  orientation: 'h',
  x: 0,
  y: 1.02,
  xanchor: 'left',
  yanchor: 'bottom',
  bgcolor: 'rgba(0,0,0,0)',
});

export const PLOT_CONFIG = Object.freeze({
  responsive: true,
  displaylogo: false,
  showLink: false,
  showSendToCloud: false,
  showEditInChartStudio: false,
  sendData: false,
  linkText: '',
  plotlyServerURL: '',
  modeBarButtons: [[...MODEBAR_BUTTONS]],
});
