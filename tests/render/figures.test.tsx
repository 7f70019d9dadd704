/**
 * The scenes' figures and their words rendered outside the browser (react-dom/server), checked
 * against the model the way a plot library tests its marks: the marks are there, their
 * coordinates are finite and inside the figure, their number follows the data, and the text
 * description carries the model's numbers. No snapshots: every expectation is computed here.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { parseParams } from '../../src/kit/params';
import { EXAM_LOOKUP, examGrid } from '../../src/core/texture';
import { lookupAt } from '../../src/scenes/texture/model';
import { pathOf } from '../../src/scenes/texture/path';
import { pathProfile } from '../../src/scenes/texture/pathProfile';
import { PathPlot } from '../../src/scenes/texture/view/PathPlot';
import { describeLookup, short } from '../../src/scenes/texture/view/describe';
import { schema as areaSchema } from '../../src/scenes/area-light/params';
import { buildModel } from '../../src/scenes/area-light/model';
import { patchModel } from '../../src/scenes/area-light/patch';
import { PatchFigure, patchFigureText } from '../../src/scenes/area-light/view/PatchFigure';
import { schema as raySchema } from '../../src/scenes/ray-sphere/params';
import { computeModel } from '../../src/scenes/ray-sphere/model';
import { describe3D, num } from '../../src/scenes/ray-sphere/view/describe';
import { drawDirections } from '../../src/scenes/hemisphere/drawStats';
import { makeLobe } from '../../src/scenes/hemisphere/lobe';
import { marginalHistograms } from '../../src/scenes/hemisphere/sampleCheck';
import { describeMarginal } from '../../src/scenes/hemisphere/view/describe';
import { RaceHistogram } from '../../src/scenes/monte-carlo/view/RaceHistogram';
import { formatNumber } from '../../src/core/format';

/** The elements of `tag` in the markup, each as its attributes. */
function elements(html: string, tag: string): Record<string, string>[] {
  const out: Record<string, string>[] = [];
  for (const m of html.matchAll(new RegExp(`<${tag}\\b([^>]*?)/?>`, 'g'))) {
    const attrs: Record<string, string> = {};
    for (const a of m[1].matchAll(/([\w:-]+)="([^"]*)"/g)) attrs[a[1]] = a[2];
    out.push(attrs);
  }
  return out;
}

/** The numbers of an SVG path's `d` as (x, y) pairs (absolute M/L commands only). */
function pathPoints(d: string): [number, number][] {
  const nums = (d.match(/-?\d+(\.\d+)?(e[-+]?\d+)?/gi) ?? []).map(Number);
  const pts: [number, number][] = [];
  for (let k = 0; k + 1 < nums.length; k += 2) pts.push([nums[k], nums[k + 1]]);
  return pts;
}

/** Every numeric geometry attribute of every element is a finite number. */
function expectFiniteGeometry(html: string) {
  for (const m of html.matchAll(/\s(x|y|x1|x2|y1|y2|cx|cy|r|width|height)="([^"]*)"/g))
    expect(Number.isFinite(Number(m[2])), `${m[1]}="${m[2]}"`).toBe(true);
  expect(html).not.toMatch(/NaN|Infinity/);
}

describe('texture: the value along the path', () => {
  const path = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
  const profile = pathProfile(examGrid(), EXAM_LOOKUP, path);
  const q = lookupAt(examGrid(), 0.4, 0.24, EXAM_LOOKUP);

  it('draws the bilinear curve and the nearest steps from the profile, inside the plot', () => {
    const html = renderToStaticMarkup(
      <PathPlot
        profile={profile}
        t={0}
        near={q.near.value}
        bil={q.bil.value}
        present={false}
        description="d"
      />,
    );
    expectFiniteGeometry(html);
    const svg = elements(html, 'svg')[0];
    const [, , w, h] = svg.viewBox.split(' ').map(Number);
    const paths = elements(html, 'path');
    const bil = paths.find((p) => p.class === 'tx-plot-bil');
    const near = paths.find((p) => p.class === 'tx-plot-near');
    // an empty plot (no data from the model) would have no points here
    expect(pathPoints(bil!.d).length).toBeGreaterThanOrEqual(profile.ts.length - profile.breaks.length);
    expect(pathPoints(near!.d).length).toBeGreaterThanOrEqual(profile.near.length);
    for (const [x, y] of [...pathPoints(bil!.d), ...pathPoints(near!.d)]) {
      expect(x).toBeGreaterThanOrEqual(0);
      expect(x).toBeLessThanOrEqual(w);
      expect(y).toBeGreaterThanOrEqual(0);
      expect(y).toBeLessThanOrEqual(h);
    }
    // the axis labels: t from 0 to 1 and the title
    expect(html).toContain('position on the path, t');
  });

  it('the curve falls as the values do: L(u, v) = 21 + 4u − 20v drops along the default path', () => {
    const html = renderToStaticMarkup(
      <PathPlot
        profile={profile}
        t={0}
        near={q.near.value}
        bil={q.bil.value}
        present={false}
        description="d"
      />,
    );
    const pts = pathPoints(elements(html, 'path').find((p) => p.class === 'tx-plot-bil')!.d);
    // screen y grows downwards: a falling value climbs down the figure
    expect(pts.at(-1)![1]).toBeGreaterThan(pts[0][1]);
    expect(profile.bil.at(-1)!).toBeLessThan(profile.bil[0]);
  });

  it('the grid’s description names the lookup’s cell, taps and values', () => {
    const text = describeLookup(q, 0.4, 0.24);
    expect(text).toContain(`cell (${q.bil.i0}, ${q.bil.j0})`);
    expect(text).toContain(`bilinear ${short(q.bil.value)}`);
    expect(text).toContain(`nearest ${short(q.near.value)}, the node (${q.near.i}, ${q.near.j})`);
  });
});

describe('area light: the Q6(a) cross-section', () => {
  for (const query of ['', 'psize=0.3&ptilt=40', 'psize=0.9&ptilt=-45']) {
    it(`marks and words follow the patch model (${query || 'defaults'})`, () => {
      const p = parseParams(areaSchema, query).values;
      const patch = patchModel(buildModel(p), p.pu, p.pv, p.psize, p.ptilt);
      const html = renderToStaticMarkup(<PatchFigure patch={patch} />);
      expectFiniteGeometry(html);
      expect(html).toContain('data-testid="al-patch-figure"');
      // the two similar triangles and the cone are drawn
      expect(elements(html, 'path').length).toBeGreaterThanOrEqual(2);
      expect(elements(html, 'line').length).toBeGreaterThan(0);
      const text = patchFigureText(patch);
      expect(text).toContain('Cross-section of Q6(a)');
      // the approximation and the exact solid angle, both at 4 significant digits
      expect(text).toContain(`${Number(patch.approx.toPrecision(4))}`.slice(0, 4));
      expect(text).toContain(`${Number(patch.exact.toPrecision(4))}`.slice(0, 4));
    });
  }
});

describe('ray–sphere: the 3D view in words', () => {
  for (const query of ['', 'o=-3,1.5,0.2&d=1,0,0', 'o=0.2,-0.3,0.1&d=1,0.5,0']) {
    it(`names the case, the ray and the sphere of the model (${query || 'defaults'})`, () => {
      const m = computeModel(parseParams(raySchema, query).values);
      const text = describe3D(m);
      const { o, r } = m.input;
      expect(text).toContain(`o = (${o.map((x) => num(x)).join(', ')})`);
      expect(text).toContain(`r = ${num(r)}`);
      if (m.chosen!.tHit === null) expect(text).not.toContain('hit point');
      else expect(text).toContain('The hit point p =');
    });
  }
});

describe('hemisphere: the marginal histograms', () => {
  it('the θ histogram holds every sample and its words say how many, in how many bins', () => {
    const lobe = makeLobe('exam', 8)!;
    const n = 4000;
    const { dirs } = drawDirections(lobe, 'independent', 1, n);
    const h = marginalHistograms(lobe, dirs, n);
    // a density histogram integrates to 1: no sample was lost (an empty plot would integrate to 0)
    const total = h.theta.density.reduce((a, d) => a + d * h.theta.width, 0);
    expect(total).toBeCloseTo(1, 12);
    expect(h.theta.curveY.some((y) => y > 0)).toBe(true);
    const text = describeMarginal(h.theta, 'θ', n, lobe.thetaPdf);
    expect(text).toContain(
      `Histogram of ${n.toLocaleString('en')} sampled θ (rad) in ${h.theta.centers.length} bins`,
    );
  });
});

describe('Monte Carlo: a lane’s histogram', () => {
  it('draws its pdf over [a, b] with the axis ticks of a and b', () => {
    const a = 0;
    const b = 2;
    const px = Array.from({ length: 21 }, (_, k) => a + ((b - a) * k) / 20);
    const py = px.map(() => 1 / (b - a));
    const xs = new Float64Array([1.16, 1.98, 0.54, 1.26]);
    const html = renderToStaticMarkup(
      <RaceHistogram
        id="uniform"
        xs={xs}
        a={a}
        b={b}
        px={px}
        py={py}
        pdfLabel="p(x) = 1/(b − a)"
        yMax={1}
        color="#000"
        tl={{ subscribe: () => () => {}, now: () => 4 }}
        t={4}
        half={null}
        staged={false}
      />,
    );
    expectFiniteGeometry(html);
    // the pdf's curve has a point per grid value (an empty series would draw nothing)
    const curves = elements(html, 'path').filter((p) => p.d && p.d.length > 0);
    expect(curves.some((p) => pathPoints(p.d).length >= px.length)).toBe(true);
    expect(html).toContain(formatNumber(a, 3));
    expect(html).toContain(formatNumber(b, 3));
    expect(html).toContain('race-hist-uniform');
  });
});
