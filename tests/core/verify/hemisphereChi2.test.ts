import { describe, expect, it } from 'vitest';
import { Rng } from '../../../src/core/random';
import { hemisphereChi2, planarChi2, adaptiveIntegrate2D, gaussLegendre } from '../../../src/core/verify';

// Tiny local samplers (the real ones live in src/core/sampling and are tested there).
type Warp = (u1: number, u2: number, out: Float64Array, o: number) => void;

const cosine: Warp = (u1, u2, out, o) => {
  const r = Math.sqrt(u1);
  const phi = 2 * Math.PI * u2;
  out[o] = r * Math.cos(phi);
  out[o + 1] = r * Math.sin(phi);
  out[o + 2] = Math.sqrt(Math.max(0, 1 - u1));
};
// broken: forgets the square root of the disk radius (Malley's method without sqrt)
const cosineNoSqrt: Warp = (u1, u2, out, o) => {
  const r = u1;
  const phi = 2 * Math.PI * u2;
  out[o] = r * Math.cos(phi);
  out[o + 1] = r * Math.sin(phi);
  out[o + 2] = Math.sqrt(Math.max(0, 1 - r * r));
};
const cosinePdf = (_x: number, _y: number, z: number) => (z > 0 ? z / Math.PI : 0);

const phong =
  (n: number): Warp =>
  (u1, u2, out, o) => {
    const c = Math.pow(1 - u1, 1 / (n + 1));
    const s = Math.sqrt(Math.max(0, 1 - c * c));
    const phi = 2 * Math.PI * u2;
    out[o] = s * Math.cos(phi);
    out[o + 1] = s * Math.sin(phi);
    out[o + 2] = c;
  };
const phongPdf = (n: number) => (_x: number, _y: number, z: number) =>
  z > 0 ? ((n + 1) / (2 * Math.PI)) * Math.pow(z, n) : 0;

// The exam lobe p(ω) = k cos θ e^φ, k = 2/(e^{2π} − 1): sin²θ = ξ1, φ = log(1 + (e^{2π} − 1) ξ2).
const K_EXAM = 2 / Math.expm1(2 * Math.PI);
const exam: Warp = (u1, u2, out, o) => {
  const s = Math.sqrt(u1);
  const c = Math.sqrt(1 - u1);
  const phi = Math.log1p(Math.expm1(2 * Math.PI) * u2);
  out[o] = s * Math.cos(phi);
  out[o + 1] = s * Math.sin(phi);
  out[o + 2] = c;
};
const examPdf = (x: number, y: number, z: number) => {
  if (!(z > 0)) return 0;
  let phi = Math.atan2(y, x);
  if (phi < 0) phi += 2 * Math.PI;
  return K_EXAM * z * Math.exp(phi);
};

function draw(w: Warp, n: number, seed: number): Float64Array {
  const rng = new Rng(seed);
  const out = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) w(rng.nextFloat(), rng.nextFloat(), out, 3 * i);
  return out;
}

const N = 100000;
const SEEDS = [1, 2, 3];

describe('gaussLegendre / adaptiveIntegrate2D', () => {
  it('integrates polynomials of degree 2n−1 exactly and weights sum to 2', () => {
    for (const order of [1, 2, 5, 7, 16]) {
      const { x, w } = gaussLegendre(order);
      let sw = 0;
      let s = 0;
      const deg = 2 * order - 1;
      for (let i = 0; i < order; i++) {
        sw += w[i];
        s += w[i] * Math.pow(x[i], deg - 1); // even power deg-1: ∫ = 2/deg
      }
      expect(sw).toBeCloseTo(2, 14);
      expect(s).toBeCloseTo(2 / deg, 13);
    }
  });
  it('integrates smooth and discontinuous functions', () => {
    expect(adaptiveIntegrate2D((x, y) => Math.exp(x + y), 0, 1, 0, 2)).toBeCloseTo(
      Math.expm1(1) * Math.expm1(2),
      12,
    );
    // a step along x = 1/3 (not a cell boundary): area of [0,1/3]×[0,1]
    const step = adaptiveIntegrate2D((x) => (x < 1 / 3 ? 1 : 0), 0, 1, 0, 1);
    expect(Math.abs(step - 1 / 3)).toBeLessThan(1e-6);
    // an edge singularity in the derivative: ∫∫ x^0.01 dx dy = 1/1.01
    expect(adaptiveIntegrate2D((x) => Math.pow(x, 0.01), 0, 1, 0, 1)).toBeCloseTo(1 / 1.01, 9);
    // a diagonal discontinuity (bisection cannot align with it): the budget bounds the work
    const tri = adaptiveIntegrate2D((x, y) => (y < x ? 1 : 0), 0, 1, 0, 1, { maxEvals: 100000 });
    expect(Math.abs(tri - 0.5)).toBeLessThan(1e-3);
  });
});

describe('hemisphereChi2', () => {
  it('accepts correct samplers (cosine, Phong n = 8, exam lobe) at α = 0.01 with Šidák correction', () => {
    const cases: [string, Warp, (x: number, y: number, z: number) => number][] = [
      ['cosine', cosine, cosinePdf],
      ['phong8', phong(8), phongPdf(8)],
      ['exam', exam, examPdf],
    ];
    const tests = cases.length * SEEDS.length;
    for (const [name, w, pdf] of cases) {
      for (const seed of SEEDS) {
        const r = hemisphereChi2(draw(w, N, seed), N, pdf, { tests });
        expect(r.pass, `${name} seed ${seed}: p = ${r.pValue}, ${r.note ?? ''}`).toBe(true);
        expect(r.outside).toBe(0);
        // expected counts sum to N (the pdf integrates to 1 over the hemisphere)
        let se = 0;
        for (const e of r.expected) se += e;
        expect(se / N).toBeCloseTo(1, 8);
        let so = 0;
        for (const o of r.observed) so += o;
        expect(so).toBe(N);
      }
    }
  });

  it('rejects a cosine sampler with a missing square root', () => {
    const r = hemisphereChi2(draw(cosineNoSqrt, N, 1), N, cosinePdf);
    expect(r.pass).toBe(false);
    expect(r.pValue).toBeLessThan(1e-10);
  });

  it('rejects a Phong sampler with the wrong exponent (n instead of n + 1)', () => {
    const wrong: Warp = (u1, u2, out, o) => phong(7)(u1, u2, out, o); // samples cos^7 …
    const r = hemisphereChi2(draw(wrong, N, 1), N, phongPdf(8)); // … tested against cos^8
    expect(r.pass).toBe(false);
  });

  it('rejects the exam lobe tested against a wrongly normalised pdf (k off by 5 %)', () => {
    const r = hemisphereChi2(draw(exam, N, 1), N, (x, y, z) => 1.05 * examPdf(x, y, z));
    expect(r.pass).toBe(false);
  });

  it('fails when samples leave the hemisphere or are NaN', () => {
    const d = draw(cosine, 1000, 4);
    d[2] = -0.5;
    d[5] = NaN;
    const r = hemisphereChi2(d, 1000, cosinePdf, { cosThetaBins: 4, phiBins: 8 });
    expect(r.outside).toBe(2);
    expect(r.pass).toBe(false);
    expect(r.note).toMatch(/outside/);
  });

  it('bins the whole sphere when asked', () => {
    const n = 50000;
    const rng = new Rng(9);
    const d = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) {
      const z = 1 - 2 * rng.nextFloat();
      const s = Math.sqrt(1 - z * z);
      const phi = 2 * Math.PI * rng.nextFloat();
      d.set([s * Math.cos(phi), s * Math.sin(phi), z], 3 * i);
    }
    const r = hemisphereChi2(d, n, () => 1 / (4 * Math.PI), { sphere: true });
    expect(r.pass).toBe(true);
    const half = hemisphereChi2(d, n, () => 1 / (2 * Math.PI));
    expect(half.pass).toBe(false);
  });
});

describe('planarChi2', () => {
  it('accepts a linear density sampled by inversion and rejects uniform samples against it', () => {
    const n = 50000;
    const rng = new Rng(5);
    const pts = new Float64Array(2 * n);
    const uni = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      pts[2 * i] = Math.sqrt(rng.nextFloat()); // p(x) = 2x on [0,1]
      pts[2 * i + 1] = 2 * rng.nextFloat() - 1; // uniform on [−1, 1]
      uni[2 * i] = rng.nextFloat();
      uni[2 * i + 1] = 2 * rng.nextFloat() - 1;
    }
    const pdf = (x: number, y: number) => (x >= 0 && x <= 1 && y >= -1 && y <= 1 ? x : 0);
    const domain = { x0: 0, x1: 1, y0: -1, y1: 1 };
    expect(planarChi2(pts, n, pdf, { domain, xBins: 10, yBins: 10 }).pass).toBe(true);
    expect(planarChi2(uni, n, pdf, { domain, xBins: 10, yBins: 10 }).pass).toBe(false);
  });
});

describe('χ² expected counts have bounded cost', () => {
  it('a pdf that is discontinuous everywhere finishes quickly and stays accurate enough for χ²', () => {
    // checkerboard in (cos θ, φ) at a resolution unrelated to the bins: 37 × 53 cells, mean 1/(2π)
    const pdf = (x: number, y: number, z: number) => {
      let phi = Math.atan2(y, x);
      if (phi < 0) phi += 2 * Math.PI;
      const a = Math.floor(z * 37) + Math.floor((phi / (2 * Math.PI)) * 53);
      return a % 2 === 0 ? 1.5 / (2 * Math.PI) : 0.5 / (2 * Math.PI);
    };
    let evals = 0;
    const counted = (x: number, y: number, z: number) => {
      evals++;
      return pdf(x, y, z);
    };
    const t0 = performance.now();
    const r = hemisphereChi2(new Float64Array([0, 0, 1]), 1, counted, { maxEvals: 1_000_000 });
    const ms = performance.now() - t0;
    expect(evals).toBeLessThanOrEqual(1_000_000 + 200 * 49);
    expect(ms).toBeLessThan(5000);
    const total = r.expected.reduce((a, b) => a + b, 0);
    expect(Math.abs(total - 1)).toBeLessThan(2e-3);
  });
});
