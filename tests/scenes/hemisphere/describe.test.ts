import { describe, expect, it } from 'vitest';
import { makeLobe, morphFraction } from '../../../src/scenes/hemisphere/model';
import { cellImage } from '../../../src/scenes/hemisphere/stratum';
import {
  describeHemisphere,
  describeStratum,
  whereTheyBunch,
  type HemisphereState,
} from '../../../src/scenes/hemisphere/view/describe';
import { marginalShape } from '../../../src/scenes/hemisphere/marginals';
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
