/**
 * The chart's SVG rendered outside the browser (react-dom/server) from a laid-out model: every
 * mark of the model is drawn, with finite coordinates, in resolved colours; tick labels, titles
 * and legend entries carry the model's words, sub- and superscripts as raised and lowered spans.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { layoutChart, type ChartStyle } from '../../src/ui/chart/model';
import { ChartSvg, type ChartColors } from '../../src/ui/chart/ChartSvg';
import { Plot } from '../../src/ui/Plot';
import type { ChartTrace } from '../../src/ui/chart/types';

const STYLE: ChartStyle = { font: 13, tick: 13, measure: (s, size) => s.length * size * 0.56 };
const COLORS: ChartColors = {
  fg: '#111',
  muted: '#555',
  grid: '#ddd',
  bg: '#fff',
  paint: (c) => (c.startsWith('var(') ? '#123456' : c),
};

function render(traces: ChartTrace[], layout = {}, w = 640, h = 300) {
  const model = layoutChart(traces, layout, w, h, STYLE);
  const html = renderToStaticMarkup(
    <ChartSvg model={model} colors={COLORS} tick={13} minorTick={10} font={13} />,
  );
  return { model, html };
}

/** Every numeric geometry attribute is a finite number, and no path carries NaN or Infinity. */
function expectFinite(html: string) {
  for (const m of html.matchAll(/\s(x|y|x1|x2|y1|y2|cx|cy|r|width|height)="([^"]*)"/g))
    expect(Number.isFinite(Number(m[2])), `${m[1]}="${m[2]}"`).toBe(true);
  expect(html).not.toMatch(/NaN|Infinity/);
}

describe('the chart as SVG', () => {
  const n = Array.from({ length: 13 }, (_, i) => 10 * 2 ** i);
  const traces: ChartTrace[] = [
    {
      x: n,
      y: n.map((v) => 1 / Math.sqrt(v)),
      name: 'uniform',
      mode: 'lines+markers',
      line: { color: 'var(--series-1)' },
    },
    { x: n, y: n.map((v) => 0.3 / v), name: 'robust t<sub>hit</sub>', mode: 'lines', line: { dash: 'dot' } },
  ];
  const layout = {
    xaxis: { type: 'log' as const, title: { text: 'N' } },
    yaxis: { type: 'log' as const, title: { text: 'RMSE' } },
    title: { text: 'Convergence' },
  };

  it('draws every mark of the model, in resolved colours, with finite coordinates', () => {
    const { model, html } = render(traces, layout);
    expectFinite(html);
    expect(html).not.toContain('var(');
    expect((html.match(/class="chart-line"/g) ?? []).length).toBe(
      model.marks.filter((m) => m.kind === 'line').length,
    );
    expect((html.match(/class="chart-markers"/g) ?? []).length).toBe(1);
    expect(html).toContain('stroke="#123456"');
    expect(html).toMatch(/stroke-dasharray="3 3"/);
  });

  it('writes the ticks, the titles and the legend, with a subscript as a lowered span', () => {
    const { model, html } = render(traces, layout);
    for (const t of [...model.x.ticks, ...model.y.ticks]) expect(html).toContain(`>${t.label}</text>`);
    expect(model.x.ticks.length).toBeGreaterThanOrEqual(3);
    for (const s of ['>N<', '>RMSE<', '>Convergence<', '>uniform<']) expect(html).toContain(s);
    expect(html).toMatch(/robust t<tspan baseline-shift="sub"[^>]*>hit<\/tspan>/);
    expect(html).not.toContain('&lt;sub&gt;');
  });

  it('a heatmap draws one cell per finite value and a colour bar with its gradient', () => {
    const z = [
      [1, 2, NaN],
      [3, 4, 5],
    ];
    const { html } = render([
      { type: 'heatmap', x: [0, 1, 2], y: [0, 1], z, zmin: -5, zmax: 5, colorscale: 'RdBu', showscale: true },
    ]);
    expectFinite(html);
    const cells = html.slice(html.indexOf('chart-cells'), html.indexOf('</g>', html.indexOf('chart-cells')));
    expect((cells.match(/<rect /g) ?? []).length).toBe(5);
    expect(html).toContain('<linearGradient');
    expect(html).toContain('class="chart-colorbar"');
  });

  it('a plot rendered on the server is a named figure waiting to be measured, never an error', () => {
    const html = renderToStaticMarkup(
      <Plot data={traces} layout={layout} label="RMSE against N" description="Falls as N grows." />,
    );
    expect(html).toContain('role="group"');
    expect(html).toContain('aria-label="RMSE against N"');
    expect(html).toContain('Falls as N grows.');
    expect(html).toContain('Loading plot…');
    expect(html).not.toContain('could not be drawn');
  });
});
