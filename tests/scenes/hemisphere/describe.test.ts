import { describe, expect, it } from 'vitest';
import { computeDrawStats } from '../../../src/scenes/hemisphere/drawStats';
import { makeLobe } from '../../../src/scenes/hemisphere/lobe';
import { morphFraction } from '../../../src/scenes/hemisphere/animation';
import { cellCounts, cellImage } from '../../../src/scenes/hemisphere/stratum';
import {
  chi2Bin,
  describeChi2Bins,
  describeHemisphere,
  describeMarginal,
  describeSquare,
  describeStratum,
  whereTheyBunch,
  type HemisphereState,
} from '../../../src/scenes/hemisphere/view/describe';
import { cdfCurve, histogramCdf, marginalShape } from '../../../src/scenes/hemisphere/marginals';
import { EXAM_E2PI_M1, examLobeK } from '../../../src/core/sampling';
import { formatSignificant } from '../../../src/ui/format';

const exam = makeLobe('exam', 8)!;
const f3 = (x: number) => formatSignificant(x, 3, 'times');

function state(over: Partial<HemisphereState> = {}): HemisphereState {
  return {
    lobe: exam,
    noLobe: '',
    kind: 'independent',
    n: 20000,
    anim: 'warp',
    t: 1,
    s: 1,
    shown: 20000,
    chi2: { pValue: 0.4123, pass: true, alpha: 0.01 },
    stratum: '',
    ask: false,
    ...over,
  };
}

describe('where the samples bunch', () => {
  it('finds the peak and median of a marginal', () => {
    const s = marginalShape((t) => Math.sin(2 * t), 0, Math.PI / 2);
    expect(s.peak).toBeCloseTo(Math.PI / 4, 2);
    expect(s.median).toBeCloseTo(Math.PI / 4, 4);
    expect(s.flat).toBe(false);
    expect(marginalShape(() => 1 / (2 * Math.PI), 0, 2 * Math.PI).flat).toBe(true);
  });

  it("the exam lobe: around θ = π/4 and towards φ = 2π, with the inversion's medians", () => {
    const text = whereTheyBunch(exam);
    expect(text).toContain(`around θ = ${f3(Math.PI / 4)} rad`);
    expect(text).toContain('towards φ = 2π');
    // P(φ) = ½ at φ = ln(1 + (e^{2π} − 1)/2)
    expect(text).toContain(`median φ = ${f3(Math.log1p(EXAM_E2PI_M1 / 2))} rad`);
  });

  it('uniform sampling bunches towards the rim and spreads evenly in φ; Phong towards the pole', () => {
    expect(whereTheyBunch(makeLobe('uniform', 8)!)).toMatch(/towards the rim .* and evenly in φ/);
    const phong = whereTheyBunch(makeLobe('phong', 50)!);
    expect(phong).toMatch(/^around θ = 0\.1\d+ rad/);
  });
});

describe('the figure described', () => {
  it('states the density, k, the samples, the morph and the χ² p-value', () => {
    const d = describeHemisphere(state());
    expect(d).toContain('k cos θ eᵠ');
    expect(d).toContain(`k = ${formatSignificant(examLobeK(), 4, 'times')}`);
    expect(d).toContain('20,000 independent samples');
    expect(d).toContain('every point sits on its direction');
    expect(d).toContain('p = 0.412, consistent with p(ω)');
  });

  it('changes when the lobe changes', () => {
    const a = describeHemisphere(state());
    const b = describeHemisphere(state({ lobe: makeLobe('cosine', 8)! }));
    expect(b).not.toBe(a);
    expect(b).toContain('cos θ / π');
    expect(b).toContain('evenly in φ');
  });

  it('follows the animation: the morph fraction mid-way, the count while growing', () => {
    const t = 0.4;
    const mid = describeHemisphere(state({ t, s: morphFraction(t) }));
    expect(mid).toContain(`t = 0.40 (s = ${morphFraction(t).toFixed(2)})`);
    expect(mid).toContain(`${formatSignificant(100 * morphFraction(t), 2, 'times')} % of the way`);
    expect(describeHemisphere(state({ t: 0, s: 0 }))).toContain('all points lie in the unit square');
    const grow = describeHemisphere(state({ anim: 'grow', t: 0.5, shown: 141 }));
    expect(grow).toContain('141 of 20,000 drawn');
  });

  it('asking first: no bunching, no χ²', () => {
    const d = describeHemisphere(state({ ask: true, t: 0, s: 0 }));
    expect(d).not.toContain('bunch');
    expect(d).not.toContain('χ²');
    expect(d).toContain('hidden until you reveal');
  });

  it('nothing sampled says why', () => {
    expect(describeHemisphere(state({ lobe: null, noLobe: 'the density diverges.' }))).toBe(
      'No samples: the density diverges.',
    );
  });
});

describe('the stratum described', () => {
  it('the cell, its patch, how dense, and the count against n/64', () => {
    const c = { i: 6, j: 5 };
    const img = cellImage(exam, c);
    const d = describeStratum(c, img, 318, 20000);
    expect(d).toContain('Stratum (6, 5): ξ₁ from 0.75 to 0.875, ξ₂ from 0.625 to 0.75');
    expect(d).toContain(`θ ${f3(img.theta[0])} to ${f3(img.theta[1])} rad`);
    expect(d).toContain(`${f3(img.densityRatio)} times as dense as uniform`);
    expect(d).toContain('318 of the 20,000 samples lie in it (expected 312.5)');
    expect(describeStratum(c, img, null, 20000)).toContain('Counting its samples');
    const sparse = describeStratum({ i: 4, j: 0 }, cellImage(exam, { i: 4, j: 0 }), 70, 20000);
    expect(sparse).toMatch(/times sparser than uniform/);
  });

  it('asking first hides where it lands; none followed says so', () => {
    const c = { i: 1, j: 2 };
    const d = describeStratum(c, cellImage(exam, c), 300, 20000, true);
    expect(d).toContain('hidden until you reveal');
    expect(d).not.toContain('sr');
    expect(describeStratum(null, null, null, 100)).toBe('No stratum followed.');
  });
});

describe('the plots described', () => {
  it("the CDF by trapezoids is the exam's sin²θ and (eᵠ − 1)/(e²ᵖ − 1)", () => {
    const th = cdfCurve(exam.thetaPdf, 0, Math.PI / 2, 576);
    for (let k = 0; k <= 576; k += 48) expect(th.y[k]).toBeCloseTo(Math.sin(th.x[k]) ** 2, 5);
    const ph = cdfCurve(exam.phiPdf, 0, 2 * Math.PI, 576);
    for (let k = 0; k <= 576; k += 48) expect(ph.y[k]).toBeCloseTo(Math.expm1(ph.x[k]) / EXAM_E2PI_M1, 5);
    expect(th.y[576]).toBe(1);
  });

  it("the samples' CDF climbs by each bin's share and ends at 1", () => {
    const h = histogramCdf([0.5, 1.5, 2], 0.25, 0);
    expect(Array.from(h.x)).toEqual([0, 0.25, 0.5, 0.75]);
    expect(Array.from(h.y)).toEqual([0, 0.125, 0.5, 1]);
  });

  it('a marginal histogram: both series, and where they differ most', () => {
    const stats = computeDrawStats(exam, Math.cos, 'independent', 1, 2000);
    const h = stats.hist!.theta;
    const d = describeMarginal(h, 'θ', 2000, exam.thetaPdf);
    expect(d).toContain('Histogram of 2,000 sampled θ (rad) in 36 bins');
    expect(d).toContain(`maximum 1 at θ = ${f3(Math.PI / 4)}`);
    let gap = 0;
    for (let b = 0; b < 36; b++) gap = Math.max(gap, Math.abs(h.density[b] - exam.thetaPdf(h.centers[b])));
    expect(d).toContain(`by ${f3(gap)}.`);
  });

  it('the χ² bins: ranges, and the worst bin with its counts', () => {
    const c = computeDrawStats(exam, Math.cos, 'independent', 1, 2000).chi2!;
    const d = describeChi2Bins(c);
    expect(d).toMatch(/^200 bins of equal solid angle, 10 in cos θ by 20 in φ/);
    let worst = 0;
    for (let k = 0; k < 200; k++) if (Math.abs(chi2Bin(c, k).z) > Math.abs(chi2Bin(c, worst).z)) worst = k;
    expect(d).toContain(`φ = ${f3(chi2Bin(c, worst).phi)} rad`);
    expect(chi2Bin(c, 0)).toMatchObject({ cosTheta: 0.05, phi: Math.PI / 20 });
  });

  it('the square: how evenly its cells share the points', () => {
    const counts = cellCounts('stratified', 1, 4096, 4096);
    expect(describeSquare(counts, 4096, 4096, 'stratified')).toContain(
      'each of its 64 cells holds from 64 to 64',
    );
    const ind = describeSquare(cellCounts('independent', 1, 20000, 4096), 4096, 20000, 'independent');
    expect(ind).toContain('(the first of 20,000)');
    expect(ind).toContain('(64 expected)');
  });
});
