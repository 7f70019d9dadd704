/**
 * The chart every plot draws (src/ui/chart): its axes and ticks, where its marks land for the
 * data they are given, its legend and margins, and its pointer readout. Text is measured at an
 * average glyph width here (the page measures it with a canvas), so every expectation below holds
 * for any text widths the layout is told.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { autoRange, decadeLabel, makeTicks, pxToUnits, unitsToPx, type Axis } from '../../src/ui/chart/axes';
import { binText, dashArray, histogramCounts } from '../../src/ui/chart/marks';
import { layoutChart, readoutAt, type ChartModel, type ChartStyle } from '../../src/ui/chart/model';
import type { ChartLayout, ChartTrace } from '../../src/ui/chart/types';
import { colorCss, DIVERGING, VIRIDIS } from '../../src/core/colormap';

const STYLE: ChartStyle = { font: 13, tick: 13, measure: (s, size) => s.length * size * 0.56 };
const SEED = { seed: 20261207 };

/** Numbers of an SVG path's `d`, as (x, y) pairs (M / L / H / V commands are read as written). */
function pathPoints(d: string): [number, number][] {
  const out: [number, number][] = [];
  for (const m of d.matchAll(/[ML](-?[\d.]+) (-?[\d.]+)/g)) out.push([Number(m[1]), Number(m[2])]);
  return out;
}

function lines(m: ChartModel) {
  return m.marks.filter((k) => k.kind === 'line');
}

/** Whether neighbouring tick labels (widths from STYLE) overlap along an axis. */
function overlaps(ticks: { px: number; label: string }[], extent: (s: string) => number): boolean {
  for (let k = 1; k < ticks.length; k++)
    if (Math.abs(ticks[k].px - ticks[k - 1].px) < (extent(ticks[k].label) + extent(ticks[k - 1].label)) / 2)
      return true;
  return false;
}

describe('chart axes', () => {
  const width = (s: string) => STYLE.measure(s, 13);

  it('linear ticks lie inside the axis, in order, and their labels never overlap', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        fc.double({ min: 1e-6, max: 1e7, noNaN: true }),
        fc.integer({ min: 60, max: 1600 }),
        (lo, span, len) => {
          const hi = lo + span;
          if (!(hi > lo)) return;
          const a: Omit<Axis, 'ticks'> = { kind: 'linear', lo, hi, px0: 50, px1: 50 + len };
          const ticks = makeTicks(a, 80, width);
          for (const t of ticks) {
            expect(t.px).toBeGreaterThanOrEqual(50 - 1e-6 * len);
            expect(t.px).toBeLessThanOrEqual(50 + len + 1e-6 * len);
          }
          for (let k = 1; k < ticks.length; k++) expect(ticks[k].px).toBeGreaterThan(ticks[k - 1].px);
          expect(overlaps(ticks, width)).toBe(false);
        },
      ),
      SEED,
    );
  });

  it('log ticks: decades (with 2 and 5 where there is room), inside the axis, never overlapping, one style per axis', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -300, max: 300, noNaN: true }),
        fc.double({ min: 0.05, max: 40, noNaN: true }),
        fc.integer({ min: 60, max: 1600 }),
        (lo, span, len) => {
          const a: Omit<Axis, 'ticks'> = { kind: 'log', lo, hi: lo + span, px0: 0, px1: len };
          const ticks = makeTicks(a, 80, width);
          for (const t of ticks) {
            const u = pxToUnits(a, t.px);
            expect(u).toBeGreaterThanOrEqual(lo - 1e-6);
            expect(u).toBeLessThanOrEqual(lo + span + 1e-6);
          }
          expect(overlaps(ticks, width)).toBe(false);
          if (span >= 1) {
            const majors = ticks.filter((t) => !t.minor).map((t) => t.label);
            // an axis writes its decades all as powers of ten or all plainly, never both
            const powers = majors.filter((s) => s.startsWith('10') && /[⁰¹²³⁴⁵⁶⁷⁸⁹]/.test(s));
            const plainFractions = majors.filter((s) => s.startsWith('0.'));
            expect(powers.length === 0 || plainFractions.length === 0).toBe(true);
            expect(majors.length).toBeGreaterThanOrEqual(1);
          }
        },
      ),
      SEED,
    );
  });

  it('writes an axis’s decades all plainly (within 0.01 … 1000, or counts 1 … 10000) or all as powers', () => {
    expect([-2, -1, 0, 1, 2, 3].map((e) => decadeLabel(e, -2, 3))).toEqual([
      '0.01',
      '0.1',
      '1',
      '10',
      '100',
      '1000',
    ]);
    expect([-3, 0, 2].map((e) => decadeLabel(e, -3, 2))).toEqual(['10⁻³', '10⁰', '10²']);
    expect([0, 3, 4].map((e) => decadeLabel(e, 0, 4))).toEqual(['1', '1000', '10000']);
    expect([3, 6].map((e) => decadeLabel(e, 0, 6))).toEqual(['10³', '10⁶']);
  });

  it('pixels and axis units map back and forth, reversed axes included', () => {
    const a = { lo: -3, hi: 2, px0: 400, px1: 40 };
    for (const u of [-3, -1.2, 0, 2]) expect(pxToUnits(a, unitsToPx(a, u))).toBeCloseTo(u, 12);
    expect(unitsToPx(a, -3)).toBe(400);
  });

  it('auto ranges pad the data, keep bars on 0, and open up a single value', () => {
    expect(autoRange([0, 10], 'linear', 0.1, true)).toEqual([0, 11]);
    expect(autoRange([2, 10], 'linear', 0.1, true)).toEqual([1.2, 10.8]);
    expect(autoRange([5, 5], 'linear', 0)).toEqual([4.5, 5.5]);
    expect(autoRange([-2, -2], 'log', 0)).toEqual([-2.5, -1.5]);
    expect(autoRange(null, 'log', 0.1)).toEqual([0, 1]);
  });
});

describe('chart layout', () => {
  it('a line goes through every data point at its axis position, and the plot fills the figure', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: -1e3, max: 1e3, noNaN: true }), { minLength: 2, maxLength: 60 }),
        fc.integer({ min: 280, max: 1400 }),
        fc.integer({ min: 160, max: 600 }),
        (ys, w, h) => {
          const x = ys.map((_, i) => i);
          const m = layoutChart([{ x, y: ys, mode: 'lines' }], {}, w, h, STYLE);
          const pts = pathPoints(lines(m)[0].d);
          expect(pts.length).toBe(ys.length);
          pts.forEach(([px, py], i) => {
            // coordinates are written with one decimal
            expect(Math.abs(px - unitsToPx(m.x, x[i]))).toBeLessThanOrEqual(0.051);
            expect(Math.abs(py - unitsToPx(m.y, ys[i]))).toBeLessThanOrEqual(0.051);
            expect(px).toBeGreaterThanOrEqual(m.plot.x - 0.05);
            expect(px).toBeLessThanOrEqual(m.plot.x + m.plot.w + 0.05);
            expect(py).toBeGreaterThanOrEqual(m.plot.y - 0.05);
            expect(py).toBeLessThanOrEqual(m.plot.y + m.plot.h + 0.05);
          });
          // lines only: the x axis runs from the first point to the last
          expect(m.x.lo).toBe(0);
          expect(m.x.hi).toBe(ys.length - 1);
          expect(m.plot.y + m.plot.h).toBeLessThanOrEqual(h);
          expect(m.plot.x + m.plot.w).toBeLessThanOrEqual(w);
        },
      ),
      SEED,
    );
  });

  it('a gap (null, NaN, or a value a log axis cannot show) breaks the line; no coordinate is NaN', () => {
    const m = layoutChart(
      [{ x: [1, 2, 3, 4, 5, 6], y: [1, 2, null, 4, 0, 6], mode: 'lines' }],
      { yaxis: { type: 'log' } },
      600,
      300,
      STYLE,
    );
    const d = lines(m)[0].d;
    expect(d.match(/M/g)?.length).toBe(3);
    expect(pathPoints(d).length).toBe(4);
    expect(JSON.stringify(m)).not.toMatch(/NaN|Infinity/);
  });

  it('empty, single-valued and non-finite data give finite geometry', () => {
    const cases: ChartTrace[][] = [
      [],
      [{ x: [], y: [] }],
      [{ x: [3], y: [3] }],
      [{ x: [1, 2, 3], y: [7, 7, 7] }],
      [{ x: [NaN, Infinity], y: [-Infinity, NaN] }],
      [{ type: 'histogram', x: [], xbins: { start: 0, end: 1, size: 0.1 } }],
      [{ type: 'heatmap', x: [], y: [], z: [], zmin: 0, zmax: 1, colorscale: 'Viridis' }],
    ];
    for (const traces of cases)
      for (const layout of [{}, { xaxis: { type: 'log' }, yaxis: { type: 'log' } }] as ChartLayout[]) {
        const m = layoutChart(traces, layout, 500, 260, STYLE);
        expect(JSON.stringify(m)).not.toMatch(/NaN|Infinity/);
        expect(m.x.hi).toBeGreaterThan(m.x.lo);
        expect(m.y.hi).toBeGreaterThan(m.y.lo);
      }
  });

  it('a histogram counts every sample in its bins once (the last bin closed), bars as tall as the counts', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: -5, max: 5, noNaN: true }), { maxLength: 300 }),
        fc.integer({ min: 1, max: 40 }),
        (xs, nb) => {
          const bins = { start: -3, end: 3, size: 6 / nb };
          const counts = histogramCounts(xs, bins);
          expect(counts.length).toBe(nb);
          const inside = xs.filter((v) => v >= -3 && v <= 3 + 1e-12).length;
          expect(counts.reduce((a, b) => a + b, 0)).toBe(inside);
          const m = layoutChart([{ type: 'histogram', x: xs, xbins: bins }], {}, 600, 300, STYLE);
          const target = m.targets[0];
          if (target.kind !== 'boxes') throw new Error('a histogram reads out as boxes');
          expect(target.boxes.length).toBe(counts.filter((c) => c > 0).length);
          const y0 = unitsToPx(m.y, 0);
          const tallest = Math.max(0, ...counts);
          for (const b of target.boxes) {
            const count = Number(b.text.split(' ')[0]);
            expect(Math.abs(b.r.y + b.r.h - y0)).toBeLessThan(1e-9);
            expect(b.r.h).toBeCloseTo(y0 - unitsToPx(m.y, count), 6);
          }
          if (tallest > 0) expect(m.y.hi).toBeGreaterThanOrEqual(tallest);
          expect(m.y.lo).toBe(0);
        },
      ),
      SEED,
    );
  });

  it('heatmap cells take the colour of their value on the scale, and the colour bar shows only when asked', () => {
    const z = [
      [0, 1],
      [2, 4],
    ];
    const base = { type: 'heatmap' as const, x: [0.5, 1.5], y: [0.5, 1.5], z, zmin: 0, zmax: 4 };
    const viridis = layoutChart([{ ...base, colorscale: 'Viridis' as const }], {}, 400, 300, STYLE);
    const cells = viridis.marks.find((k) => k.kind === 'cells');
    if (cells?.kind !== 'cells') throw new Error('no cells');
    expect(cells.cells.map((c) => c.color)).toEqual([0, 0.25, 0.5, 1].map((t) => colorCss(t, VIRIDIS)));
    expect(viridis.colorbar).toBeNull();
    const diverging = layoutChart(
      [{ ...base, colorscale: 'RdBu' as const, showscale: true }],
      {},
      400,
      300,
      STYLE,
    );
    const c2 = diverging.marks.find((k) => k.kind === 'cells');
    if (c2?.kind !== 'cells') throw new Error('no cells');
    expect(c2.cells[3].color).toBe(colorCss(1, DIVERGING));
    expect(diverging.colorbar).not.toBeNull();
    // the bar sits right of the plot area, inside the figure, with its ticks inside its height
    const bar = diverging.colorbar!;
    expect(bar.r.x).toBeGreaterThan(diverging.plot.x + diverging.plot.w);
    expect(bar.r.x + bar.r.w).toBeLessThan(400);
    for (const t of bar.ticks) expect(t.px).toBeGreaterThanOrEqual(bar.r.y - 1e-9);
    // the colour bar's room comes out of the plot area
    expect(diverging.plot.w).toBeLessThan(viridis.plot.w);
  });

  it('the legend: one entry per named trace shown (one per group), above the plot unless placed', () => {
    const t = (name: string, extra: Partial<ChartTrace> = {}): ChartTrace =>
      ({ x: [1, 2, 3], y: [1, 2, 3], name, ...extra }) as ChartTrace;
    const none = layoutChart([t('only')], {}, 600, 300, STYLE);
    expect(none.legend.items).toEqual([]);
    const traces = [
      t('a', { legendgroup: 'g' }),
      t('a again', { legendgroup: 'g' }),
      t('hidden', { showlegend: false }),
      t('b'),
    ];
    const above = layoutChart(traces, {}, 600, 300, STYLE);
    expect(above.legend.items.map((i) => i.text)).toEqual(['a', 'b']);
    for (const i of above.legend.items) expect(i.y).toBeLessThan(above.plot.y);
    const below = layoutChart(traces, { legend: { y: -0.2, yanchor: 'top' } }, 600, 300, STYLE);
    for (const i of below.legend.items) expect(i.y).toBeGreaterThan(below.plot.y + below.plot.h);
    const inside = layoutChart(traces, { legend: { x: 0.98, y: 0.98, xanchor: 'right' } }, 600, 300, STYLE);
    for (const i of inside.legend.items) {
      expect(i.x).toBeGreaterThan(inside.plot.x);
      expect(i.y).toBeGreaterThan(inside.plot.y);
      expect(i.y).toBeLessThan(inside.plot.y + inside.plot.h);
    }
    expect(layoutChart(traces, { showlegend: false }, 600, 300, STYLE).legend.items).toEqual([]);
  });

  it('a legend too wide for one row wraps, and the plot gives up the rows’ height', () => {
    const many = Array.from({ length: 12 }, (_, i) => ({
      x: [1, 2],
      y: [i, i + 1],
      name: `series number ${i}`,
    }));
    const wide = layoutChart(many, {}, 1400, 400, STYLE);
    const narrow = layoutChart(many, {}, 360, 400, STYLE);
    const rows = (m: ChartModel) => new Set(m.legend.items.map((i) => i.y)).size;
    expect(rows(narrow)).toBeGreaterThan(rows(wide));
    expect(narrow.plot.y).toBeGreaterThan(wide.plot.y);
    for (const i of narrow.legend.items) expect(i.x).toBeLessThan(360);
    // the top row stops short of the tool buttons over the top right corner
    const tools = layoutChart(many, {}, 1400, 400, { ...STYLE, topRight: 600 });
    const top = Math.min(...tools.legend.items.map((i) => i.y));
    for (const i of tools.legend.items.filter((i) => i.y === top))
      expect(i.x + 36 + STYLE.measure(i.text, STYLE.font)).toBeLessThanOrEqual(1400 - 600);
    expect(rows(tools)).toBeGreaterThanOrEqual(rows(wide));
  });

  it('a title clears the tool buttons over the top right corner when it can, and stays in the figure', () => {
    const text = 'P(θ): the CDF vs the samples';
    const w = STYLE.measure(text, STYLE.font * 1.1);
    for (const width of [300, 412, 800]) {
      const m = layoutChart([{ x: [0, 1], y: [0, 1] }], { title: { text } }, width, 260, {
        ...STYLE,
        topRight: 128,
      });
      expect(m.title!.x - w / 2).toBeGreaterThanOrEqual(0);
      if (width - 128 - 4 >= w + 4) expect(m.title!.x + w / 2).toBeLessThanOrEqual(width - 128);
    }
    const free = layoutChart([{ x: [0, 1], y: [0, 1] }], { title: { text } }, 800, 260, STYLE);
    expect(free.title!.x).toBeCloseTo(free.plot.x + free.plot.w / 2, 9);
  });

  it('the left margin grows to fit the y axis’s labels', () => {
    const small = layoutChart([{ x: [0, 1], y: [0, 1] }], { margin: { l: 20 } }, 600, 300, STYLE);
    const long = layoutChart([{ x: [0, 1], y: [1.5e-7, 9.25e-7] }], { margin: { l: 20 } }, 600, 300, STYLE);
    const widest = (m: ChartModel) => Math.max(...m.y.ticks.map((t) => STYLE.measure(t.label, STYLE.tick)));
    for (const m of [small, long]) expect(m.plot.x).toBeGreaterThanOrEqual(widest(m) + 6);
    expect(long.plot.x).toBeGreaterThan(small.plot.x);
  });

  it('given ranges, reversed axes, paper shapes and a zoomed view', () => {
    const tr: ChartTrace[] = [{ x: [1e-3, 1], y: [1, 2], mode: 'lines' }];
    const m = layoutChart(
      tr,
      {
        xaxis: { type: 'log', autorange: 'reversed' },
        yaxis: { range: [0, 4] },
        shapes: [{ type: 'line', x0: 0.1, x1: 0.1, yref: 'paper', y0: 0, y1: 1 }],
      },
      600,
      300,
      STYLE,
    );
    expect(m.x.px0).toBeGreaterThan(m.x.px1);
    expect([m.y.lo, m.y.hi]).toEqual([0, 4]);
    const [[sx, sy0], [, sy1]] = pathPoints(m.shapes[0].d);
    expect(sx).toBeCloseTo(unitsToPx(m.x, -1), 1);
    expect(sy0).toBeCloseTo(m.plot.y + m.plot.h, 1);
    expect(sy1).toBeCloseTo(m.plot.y, 1);
    const zoomed = layoutChart(tr, {}, 600, 300, STYLE, { x: [0.2, 0.4], y: [1.2, 1.4] });
    expect([zoomed.x.lo, zoomed.x.hi, zoomed.y.lo, zoomed.y.hi]).toEqual([0.2, 0.4, 1.2, 1.4]);
  });

  it('tonexty fills between a line and the one before it', () => {
    const m = layoutChart(
      [
        { x: [0, 1, 2], y: [1, 1, 1], mode: 'lines', line: { width: 0 } },
        { x: [0, 1, 2], y: [3, 3, 3], mode: 'lines', line: { width: 0 }, fill: 'tonexty', fillcolor: 'red' },
      ],
      {},
      600,
      300,
      STYLE,
    );
    const area = m.marks.find((k) => k.kind === 'area');
    if (area?.kind !== 'area') throw new Error('no fill');
    const pts = pathPoints(area.d);
    expect(pts.length).toBe(6);
    expect(new Set(pts.map((p) => p[1])).size).toBe(2);
    // width 0: no line drawn
    expect(lines(m)).toEqual([]);
  });

  it('a bin reads with enough digits to tell its ends apart, however narrow it is', () => {
    expect(binText(14, 14.5)).toBe('[14, 14.5)');
    expect(binText(0.500000012, 0.500000022)).toBe('[0.500000012, 0.500000022)');
    fc.assert(
      fc.property(
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        fc.double({ min: 1e-9, max: 1e3, noNaN: true }),
        (l, w) => {
          const r = l + Math.max(w, Math.abs(l) * 1e-12);
          if (!(r > l)) return;
          const [a, b] = binText(l, r).slice(1, -1).split(', ');
          expect(a).not.toBe(b);
        },
      ),
      SEED,
    );
  });

  it('dashes scale with the line width (at least 3 px per unit); a px list is kept', () => {
    expect(dashArray('solid', 2)).toBeUndefined();
    expect(dashArray('dot', 1)).toBe('3 3');
    expect(dashArray('dash', 4)).toBe('12 12');
    expect(dashArray('5px,2px,1px,2px', 2)).toBe('5 2 1 2');
  });
});

describe('chart readout', () => {
  const m = layoutChart(
    [
      { x: [1, 2, 3], y: [10, 20, 30], name: 'walk', mode: 'markers', text: ['N = 1', 'N = 2', 'N = 3'] },
      { x: [1, 3], y: [30, 10], name: 'band', hoverinfo: 'skip', mode: 'lines' },
    ],
    { xaxis: { title: { text: 'N' } }, yaxis: { title: { text: 'RMSE' } } },
    600,
    300,
    STYLE,
  );

  it('reads out the nearest point with its trace’s name, its values and its text', () => {
    const px = unitsToPx(m.x, 2) + 5;
    const py = unitsToPx(m.y, 20) - 5;
    const r = readoutAt(m, px, py);
    expect(r?.lines).toEqual(['walk', 'N 2, RMSE 20', 'N = 2']);
    expect(r?.x).toBeCloseTo(unitsToPx(m.x, 2), 1);
  });

  it('passes over skipped traces, and reads nothing far from every point or outside the plot', () => {
    // on the skipped line's end (3, 10), far from the walk's points
    expect(readoutAt(m, unitsToPx(m.x, 3), unitsToPx(m.y, 10))).toBeNull();
    expect(readoutAt(m, 1, 1)).toBeNull();
  });
});
