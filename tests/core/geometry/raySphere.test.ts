// Ray–sphere intersection: textbook vs robust (Ray Tracing Gems ch. 7) vs references.
//
// Cases covered (three.js Ray.tests.js style list):
//   two hits in front · miss · exactly tangent (Δ = 0 in both methods) · tangent point behind →
//   'behind' · origin inside → hit is t1 · sphere behind → no hit though Δ ≥ 0 · origin on the
//   surface → t = 0 is a hit · non-unit d (t in units of d) · zero direction, r ≤ 0, NaN/∞,
//   overflow → error result (never NaN) · one ulp past tangent (exact: miss) · one ulp inside
//   tangent (exact: two hits 2^-26 apart) · grazing at 1e5 · small sphere at 1e8·r.
//
// Tangent policy under test: 'tangent' ⇔ the method's computed Δ is exactly 0. No tolerance snaps
// a near-tangent ray; `nearTangent` flags |Δ| within the method's rounding-error bound.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all, type BigNumber } from 'mathjs';
import {
  intersectRaySphere,
  intersectRaySphereBatch,
  raySphereReference,
  fillPinholeRays,
  nextUp,
  nextDown,
  ulpDistance,
  NO_HIT,
  RAY_STRIDE,
  type Vec3,
  type RaySphereHit,
  type RaySphereReference,
} from '../../../src/core/geometry';
import { Rng } from '../../../src/core/random';

// ---------------------------------------------------------------------------------------------
// mathjs BigNumber reference: the same quadratic solved with the inputs taken as exact doubles.
const M = create(all, { number: 'BigNumber', precision: 400 });

function big(x: number): BigNumber {
  if (x === 0) return M.bignumber(0);
  const v = new DataView(new ArrayBuffer(8));
  v.setFloat64(0, x);
  const bits = v.getBigUint64(0);
  const expBits = Number((bits >> 52n) & 0x7ffn);
  let mant = bits & 0xfffffffffffffn;
  let e = -1074;
  if (expBits !== 0) {
    mant |= 1n << 52n;
    e = expBits - 1075;
  }
  const abs = M.bignumber(mant.toString()).times(M.bignumber(2).pow(e)) as BigNumber;
  return bits >> 63n ? (abs.neg() as BigNumber) : abs;
}

interface BigSolution {
  sign: number; // sign of Δ
  t0: number | null;
  t1: number | null;
  tHit: number | null;
}

/** Exact (400-digit) solution of a t² + 2β t + c′ = 0, rounded to doubles at the end. */
function bigSolve(o: Vec3, d: Vec3, c: Vec3, r: number): BigSolution {
  const f = [0, 1, 2].map((i) => big(o[i]).minus(big(c[i])) as BigNumber);
  const D = d.map(big);
  const dot = (x: BigNumber[], y: BigNumber[]) =>
    x[0].times(y[0]).plus(x[1].times(y[1])).plus(x[2].times(y[2])) as BigNumber;
  const a = dot(D, D);
  const beta = dot(f, D);
  const cc = dot(f, f).minus(big(r).times(big(r))) as BigNumber;
  const q4 = beta.times(beta).minus(a.times(cc)) as BigNumber;
  const sign = q4.isZero() ? 0 : q4.isNegative() ? -1 : 1;
  if (sign < 0) return { sign, t0: null, t1: null, tHit: null };
  const s = q4.sqrt();
  const t0 = Number(beta.neg().minus(s).div(a));
  const t1 = Number(beta.neg().plus(s).div(a));
  const tHit = t0 >= 0 ? t0 : t1 >= 0 ? t1 : null;
  return { sign, t0, t1, tHit };
}

function hit(res: ReturnType<typeof intersectRaySphere>): RaySphereHit {
  if (!res.ok) throw new Error(`expected a result, got error ${res.kind}`);
  return res;
}
function ref(res: ReturnType<typeof raySphereReference>): RaySphereReference {
  if (!res.ok) throw new Error(`expected a result, got error ${res.kind}`);
  return res;
}
const rel = (x: number, y: number) => Math.abs(x - y) / Math.abs(y);

const O: Vec3 = [0, 0, 0];
const X: Vec3 = [1, 0, 0];

// ---------------------------------------------------------------------------------------------
describe('every case, both methods agree on easy inputs', () => {
  const cases: {
    name: string;
    o: Vec3;
    d: Vec3;
    c: Vec3;
    r: number;
    want: string;
    t: [number, number] | null;
    hit: number | null;
  }[] = [
    { name: 'two hits in front', o: [-3, 0, 0], d: X, c: O, r: 1, want: 'two-hits', t: [2, 4], hit: 2 },
    { name: 'miss', o: [-3, 2, 0], d: X, c: O, r: 1, want: 'miss', t: null, hit: null },
    { name: 'tangent (Δ = 0 exactly)', o: [-5, 1, 0], d: X, c: O, r: 1, want: 'tangent', t: [5, 5], hit: 5 },
    {
      name: 'tangent point behind → behind',
      o: [5, 1, 0],
      d: X,
      c: O,
      r: 1,
      want: 'behind',
      t: [-5, -5],
      hit: null,
    },
    {
      name: 'origin inside: hit is t1',
      o: [0.5, 0, 0],
      d: X,
      c: O,
      r: 1,
      want: 'inside',
      t: [-1.5, 0.5],
      hit: 0.5,
    },
    {
      name: 'sphere behind: Δ > 0 but no hit',
      o: [3, 0, 0],
      d: X,
      c: O,
      r: 1,
      want: 'behind',
      t: [-4, -2],
      hit: null,
    },
    {
      name: 'origin on the surface, pointing in: t = 0 is the hit',
      o: [-1, 0, 0],
      d: X,
      c: O,
      r: 1,
      want: 'two-hits',
      t: [0, 2],
      hit: 0,
    },
    {
      name: 'origin on the surface, pointing out: inside with t-hit 0',
      o: [1, 0, 0],
      d: X,
      c: O,
      r: 1,
      want: 'inside',
      t: [-2, 0],
      hit: 0,
    },
    {
      name: 'non-unit d: t in units of d',
      o: [-3, 0, 0],
      d: [2, 0, 0],
      c: O,
      r: 1,
      want: 'two-hits',
      t: [1, 2],
      hit: 1,
    },
    {
      name: 'oblique, offset centre',
      o: [1, 2, 3],
      d: [0, 0, -1],
      c: [1, 2, -4],
      r: 2,
      want: 'two-hits',
      t: [5, 9],
      hit: 5,
    },
  ];
  for (const k of cases) {
    for (const method of ['naive', 'stable'] as const) {
      it(`${k.name} (${method})`, () => {
        const h = hit(intersectRaySphere(k.o, k.d, k.c, k.r, method));
        expect(h.case).toBe(k.want);
        expect(h.tHit).toBe(k.hit);
        if (k.t === null) {
          expect(h.t0).toBeNull();
          expect(h.t1).toBeNull();
          expect(h.discriminant).toBeLessThan(0);
        } else {
          expect(h.t0).toBe(k.t[0]);
          expect(h.t1).toBe(k.t[1]);
        }
        // textbook coefficients are the same numbers whatever the method
        const f = [k.o[0] - k.c[0], k.o[1] - k.c[1], k.o[2] - k.c[2]];
        expect(h.a).toBe(k.d[0] ** 2 + k.d[1] ** 2 + k.d[2] ** 2);
        expect(h.b).toBe(2 * (f[0] * k.d[0] + f[1] * k.d[1] + f[2] * k.d[2]));
        expect(h.c).toBe(f[0] ** 2 + f[1] ** 2 + f[2] ** 2 - k.r * k.r);
        // and so is the reference's case
        expect(ref(raySphereReference(k.o, k.d, k.c, k.r)).case).toBe(k.want);
      });
    }
  }

  it('discriminant means b² − 4ac for both methods', () => {
    const o: Vec3 = [-3, 0.5, 0.25];
    const d: Vec3 = [1, 0.1, -0.2];
    const n = hit(intersectRaySphere(o, d, O, 1, 'naive'));
    const s = hit(intersectRaySphere(o, d, O, 1, 'stable'));
    expect(rel(s.discriminant, n.discriminant)).toBeLessThan(1e-14);
    expect(n.discriminant).toBe(n.b * n.b - 4 * n.a * n.c);
  });
});

describe('bad input → error result, never NaN', () => {
  const bad: [string, Vec3, Vec3, Vec3, number, string][] = [
    ['zero direction', O, [0, 0, 0], [5, 0, 0], 1, 'zero-direction'],
    ['direction too short to square (underflow)', O, [1e-200, 0, 0], [5, 0, 0], 1, 'zero-direction'],
    ['zero radius', O, X, [5, 0, 0], 0, 'bad-radius'],
    ['negative radius', O, X, [5, 0, 0], -1, 'bad-radius'],
    ['NaN coordinate', [NaN, 0, 0], X, [5, 0, 0], 1, 'non-finite'],
    ['infinite radius', O, X, [5, 0, 0], Infinity, 'non-finite'],
    ['-Infinity direction', O, [-Infinity, 0, 0], [5, 0, 0], 1, 'non-finite'],
    ['overflowing coefficients', [-1e200, 0, 0], X, [1e200, 0, 0], 1, 'overflow'],
  ];
  for (const [name, o, d, c, r, kind] of bad) {
    it(name, () => {
      for (const method of ['naive', 'stable'] as const) {
        const res = intersectRaySphere(o, d, c, r, method);
        expect(res.ok).toBe(false);
        if (!res.ok) {
          expect(res.kind).toBe(kind);
          expect(res.message.length).toBeGreaterThan(10);
        }
      }
      const rr = raySphereReference(o, d, c, r);
      expect(rr.ok).toBe(false);
    });
  }
});

// ---------------------------------------------------------------------------------------------
describe('stress inputs against mathjs BigNumber (400 digits)', () => {
  it('one ulp past tangent: exact answer is a miss; robust says miss, textbook wrongly says tangent', () => {
    const o: Vec3 = [-5, nextUp(1), 0]; // distance from the axis line to the centre: 1 + 2^-52 > r
    const exact = bigSolve(o, X, O, 1);
    expect(exact.sign).toBe(-1);
    const s = hit(intersectRaySphere(o, X, O, 1, 'stable'));
    expect(s.case).toBe('miss');
    expect(s.nearTangent).toBe(true);
    const n = hit(intersectRaySphere(o, X, O, 1, 'naive'));
    // Documented textbook failure: c′ = 25 + 2^-51 rounds to 25, so b² − 4ac′ = 100 − 100 = 0.
    expect(n.discriminant).toBe(0);
    expect(n.case).toBe('tangent');
    expect(n.tHit).toBe(5);
    expect(ref(raySphereReference(o, X, O, 1)).case).toBe('miss');
  });

  it('one ulp inside tangent: two hits 5 ± 2^-26; robust matches to ≤ 2 ulps, textbook collapses them', () => {
    const o: Vec3 = [-5, nextDown(1), 0];
    const exact = bigSolve(o, X, O, 1);
    expect(exact.sign).toBe(1);
    const s = hit(intersectRaySphere(o, X, O, 1, 'stable'));
    expect(s.case).toBe('two-hits');
    expect(ulpDistance(s.t0!, exact.t0!)).toBeLessThanOrEqual(2);
    expect(ulpDistance(s.t1!, exact.t1!)).toBeLessThanOrEqual(2);
    const n = hit(intersectRaySphere(o, X, O, 1, 'naive'));
    expect(n.case).toBe('tangent');
    // the textbook roots are off by ≈ 2^-26 ≈ 1.5e-8: ~1e7 ulps at t = 5
    expect(rel(n.t0!, exact.t0!)).toBeGreaterThan(1e-9);
    expect(ulpDistance(n.t0!, exact.t0!)).toBeGreaterThan(1e6);
  });

  it('grazing ray at 1e5: robust roots within 1e-12 relative, textbook off by > 1e-10', () => {
    const o: Vec3 = [-1e5, 0.99999, 0];
    const exact = bigSolve(o, X, O, 1);
    const s = hit(intersectRaySphere(o, X, O, 1, 'stable'));
    const n = hit(intersectRaySphere(o, X, O, 1, 'naive'));
    expect(s.case).toBe('two-hits');
    expect(rel(s.t0!, exact.t0!)).toBeLessThan(1e-12);
    expect(rel(s.t1!, exact.t1!)).toBeLessThan(1e-12);
    expect(rel(n.t0!, exact.t0!)).toBeGreaterThan(1e-10);
  });

  it('small sphere at 1e8·r, ray at half a radius off centre: textbook sees a tangent (Δ = 0), robust is exact to ulps', () => {
    const o: Vec3 = [0, 0, 0];
    const d: Vec3 = [1, 5e-9, 0];
    const c: Vec3 = [1e8, 0, 0];
    const exact = bigSolve(o, d, c, 1);
    const s = hit(intersectRaySphere(o, d, c, 1, 'stable'));
    const n = hit(intersectRaySphere(o, d, c, 1, 'naive'));
    expect(exact.sign).toBe(1);
    expect(s.case).toBe('two-hits');
    expect(ulpDistance(s.t0!, exact.t0!)).toBeLessThanOrEqual(4);
    expect(ulpDistance(s.t1!, exact.t1!)).toBeLessThanOrEqual(4);
    // textbook: c′ = 1e16 − 1 rounds to 1e16 and a = 1 + 2.5e-17 rounds to 1, so Δ = 0
    expect(n.discriminant).toBe(0);
    expect(n.case).toBe('tangent');
    expect(Math.abs(n.tHit! - exact.t0!)).toBeGreaterThan(0.5); // lost ~0.87 of depth
  });

  it('random rays at a sphere 1e8 radii away: robust within 1e-12 relative always; textbook loses most of them', () => {
    const rng = new Rng(2024, 7);
    let textbookWrong = 0;
    const N = 60;
    for (let i = 0; i < N; i++) {
      const D = 1e8;
      // centre on a random direction at distance D·r (r = 1), ray aimed at a random point of the disc
      const u = rng.nextFloat() * 2 - 1;
      const phi = rng.nextFloat() * 2 * Math.PI;
      const sxy = Math.sqrt(1 - u * u);
      const c: Vec3 = [D * sxy * Math.cos(phi), D * sxy * Math.sin(phi), D * u];
      const o: Vec3 = [rng.nextFloat(), rng.nextFloat(), rng.nextFloat()];
      const aim: Vec3 = [
        c[0] + 0.9 * (rng.nextFloat() - 0.5),
        c[1] + 0.9 * (rng.nextFloat() - 0.5),
        c[2] + 0.9 * (rng.nextFloat() - 0.5),
      ];
      const d: Vec3 = [aim[0] - o[0], aim[1] - o[1], aim[2] - o[2]];
      const exact = bigSolve(o, d, c, 1);
      if (exact.sign <= 0) continue; // (never happens for |offset| < 0.8, but stay honest)
      const s = hit(intersectRaySphere(o, d, c, 1, 'stable'));
      expect(s.case).toBe('two-hits');
      expect(rel(s.t0!, exact.t0!)).toBeLessThan(1e-12);
      expect(rel(s.t1!, exact.t1!)).toBeLessThan(1e-12);
      const n = hit(intersectRaySphere(o, d, c, 1, 'naive'));
      if (n.case !== 'two-hits' || rel(n.t0!, exact.t0!) > 1e-12) textbookWrong++;
    }
    // Documents the textbook failure: Δ's relative error is ~ε(|f|/r)² ≈ 1, so most rays are wrong.
    expect(textbookWrong).toBeGreaterThan(N / 2);
  });

  it('origin inside and sphere behind, far from the centre scale: robust matches exact roots', () => {
    const inside = {
      o: [1e6 + 0.3, 2e6 - 0.2, -3e6] as Vec3,
      d: [0.3, -0.7, 0.1] as Vec3,
      c: [1e6, 2e6, -3e6] as Vec3,
      r: 1,
    };
    const behind = {
      o: [1e6 + 50, 2e6, -3e6] as Vec3,
      d: [1, 1e-3, 0] as Vec3,
      c: [1e6, 2e6, -3e6] as Vec3,
      r: 1,
    };
    const si = hit(intersectRaySphere(inside.o, inside.d, inside.c, inside.r, 'stable'));
    const ei = bigSolve(inside.o, inside.d, inside.c, inside.r);
    expect(si.case).toBe('inside');
    expect(rel(si.t0!, ei.t0!)).toBeLessThan(1e-9); // origin − centre is formed with absolute error ~ε·3e6
    expect(rel(si.t1!, ei.t1!)).toBeLessThan(1e-9);
    const sb = hit(intersectRaySphere(behind.o, behind.d, behind.c, behind.r, 'stable'));
    const eb = bigSolve(behind.o, behind.d, behind.c, behind.r);
    expect(sb.case).toBe('behind');
    expect(sb.tHit).toBeNull();
    expect(rel(sb.t0!, eb.t0!)).toBeLessThan(1e-12);
    expect(rel(sb.t1!, eb.t1!)).toBeLessThan(1e-12);
  });
});

describe('the double-double reference against BigNumber', () => {
  const stress: [string, Vec3, Vec3, Vec3, number][] = [
    ['far small sphere', [0, 0, 0], [1, 5e-9, 0], [1e8, 0, 0], 1],
    ['far sphere, oblique', [0.1, 0.2, 0.3], [0.6, 0.8, 1e-9], [6e7, 8e7, 0], 0.7],
    ['one ulp past tangent', [-5, nextUp(1), 0], X, O, 1],
    ['one ulp inside tangent', [-5, nextDown(1), 0], X, O, 1],
    ['grazing 1e5', [-1e5, 0.99999, 0], X, O, 1],
    ['grazing oblique', [-7, 3, 1], [7, -3 + 0.9999999, -1], O, 1],
    ['inside', [0.1, 0.2, -0.3], [1, 2, 3], O, 2],
    ['behind', [5, 0.5, 0], [1, 0.01, 0], O, 1],
  ];
  for (const [name, o, d, c, r] of stress) {
    it(`${name}: same case, roots within 2 ulps`, () => {
      const e = bigSolve(o, d, c, r);
      const x = ref(raySphereReference(o, d, c, r));
      expect(Math.sign(x.discriminant)).toBe(e.sign);
      if (e.t0 === null) {
        expect(x.t0).toBeNull();
      } else {
        expect(ulpDistance(x.t0!, e.t0)).toBeLessThanOrEqual(2);
        expect(ulpDistance(x.t1!, e.t1!)).toBeLessThanOrEqual(2);
      }
      expect(x.tHit === null).toBe(e.tHit === null);
      if (e.tHit !== null) expect(ulpDistance(x.tHit!, e.tHit)).toBeLessThanOrEqual(2);
    });
  }
  it('property: over random rays near tangency, the reference decides the sign of Δ like BigNumber', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e4, max: -1, noNaN: true }),
        fc.double({ min: 0.999, max: 1.001, noNaN: true }),
        fc.double({ min: -0.5, max: 0.5, noNaN: true }),
        fc.double({ min: 0.5, max: 2, noNaN: true }),
        (ox, oy, dz, r) => {
          const o: Vec3 = [ox, oy * r, 0.25];
          const d: Vec3 = [1, 1e-6 * dz, 0];
          const e = bigSolve(o, d, [0, 0, 0.25], r);
          const x = ref(raySphereReference(o, d, [0, 0, 0.25], r));
          if (Math.sign(x.discriminant) !== e.sign) return false;
          if (e.t0 === null) return x.t0 === null;
          return ulpDistance(x.t0!, e.t0) <= 4 && ulpDistance(x.t1!, e.t1!) <= 4;
        },
      ),
      { seed: 11, numRuns: 60 },
    );
  });
});

// ---------------------------------------------------------------------------------------------
describe('properties over whole input ranges (fast-check)', () => {
  const coord = fc.double({ min: -100, max: 100, noNaN: true });
  const vec = fc.tuple(coord, coord, coord);
  const dir = vec.filter(([x, y, z]) => x * x + y * y + z * z > 1e-6);
  const radius = fc.double({ min: 0.01, max: 50, noNaN: true });

  it('robust result: sorted roots, t-hit ≥ 0 or none, hit point on the sphere, case consistent', () => {
    fc.assert(
      fc.property(vec, dir, vec, radius, (o, d, c, r) => {
        const h = hit(intersectRaySphere(o, d, c, r, 'stable'));
        if (h.case === 'miss') return h.t0 === null && h.tHit === null && h.discriminant < 0;
        if (!(h.t0! <= h.t1!)) return false;
        if (h.tHit !== null && h.tHit < 0) return false;
        if (h.case === 'behind' && !(h.t1! < 0 && h.tHit === null)) return false;
        if (h.case === 'inside' && !(h.t0! < 0 && h.tHit === h.t1)) return false;
        if (h.case === 'two-hits' && h.tHit !== h.t0) return false;
        // |o + t d − c| = r for both roots, to a tolerance scaled by the problem size
        const scale = Math.hypot(o[0] - c[0], o[1] - c[1], o[2] - c[2]) + r;
        for (const t of [h.t0!, h.t1!]) {
          const p = [o[0] + t * d[0] - c[0], o[1] + t * d[1] - c[1], o[2] + t * d[2] - c[2]];
          const err = Math.abs(Math.hypot(p[0], p[1], p[2]) - r);
          // near tangency the root is ill-conditioned along the ray but the point stays on the sphere
          if (err > 1e-9 * scale + Math.sqrt(1e-15 * scale * r)) return false;
        }
        return true;
      }),
      { seed: 12, numRuns: 500 },
    );
  });

  it('robust roots are within their conditioning bound of the exact roots (BigNumber)', () => {
    // Forward error ≲ (δΔ/(2√Δ) or √δΔ) / a, with δΔ/4 ≈ a·8u(r² + |l|² + |l||f|).
    fc.assert(
      fc.property(vec, dir, vec, radius, (o, d, c, r) => {
        const h = hit(intersectRaySphere(o, d, c, r, 'stable'));
        const e = bigSolve(o, d, c, r);
        const a = d[0] ** 2 + d[1] ** 2 + d[2] ** 2;
        const f = Math.hypot(o[0] - c[0], o[1] - c[1], o[2] - c[2]);
        const u = 2 ** -53;
        const dq = a * 16 * u * (r * r + (f + r) * f);
        if (e.sign < 0 || h.case === 'miss') {
          // may disagree only within the rounding band of tangency
          return e.sign >= 0 === (h.case !== 'miss') || h.nearTangent;
        }
        const q = Math.max(0, h.discriminant / 4);
        const dsq = q > dq ? dq / (2 * Math.sqrt(q)) : Math.sqrt(dq);
        const tol = (4 * dsq) / a + 8 * u * (Math.abs(e.t0!) + Math.abs(e.t1!) + f / Math.sqrt(a));
        return Math.abs(h.t0! - e.t0!) <= tol && Math.abs(h.t1! - e.t1!) <= tol;
      }),
      { seed: 13, numRuns: 150 },
    );
  });

  it('the batched kernel returns the scalar t-hit bit for bit, for both methods', () => {
    const rng = new Rng(99);
    const n = 500;
    const rays = new Float64Array(n * RAY_STRIDE);
    for (let i = 0; i < rays.length; i++) rays[i] = (rng.nextFloat() - 0.5) * 8;
    rays[3] = rays[4] = rays[5] = 0; // one zero direction → NO_HIT, no NaN
    const out = new Float64Array(n);
    const c: Vec3 = [0.3, -0.2, 0.1];
    for (const method of ['naive', 'stable'] as const) {
      const hits = intersectRaySphereBatch(rays, n, c[0], c[1], c[2], 1.5, method, out);
      let count = 0;
      for (let i = 0; i < n; i++) {
        const j = i * RAY_STRIDE;
        const res = intersectRaySphere(
          [rays[j], rays[j + 1], rays[j + 2]],
          [rays[j + 3], rays[j + 4], rays[j + 5]],
          c,
          1.5,
          method,
        );
        const want = res.ok && res.tHit !== null ? res.tHit : NO_HIT;
        expect(out[i]).toBe(want);
        if (want !== NO_HIT) count++;
      }
      expect(hits).toBe(count);
      expect(count).toBeGreaterThan(50);
    }
  });

  it('a pinhole image of a sphere 1e8 radii away: robust fills the disc, textbook leaves holes', () => {
    const w = 48;
    const h = 48;
    const rays = new Float64Array(w * h * RAY_STRIDE);
    const D = 1e8;
    fillPinholeRays(rays, w, h, [0.1, 0.2, 0.3], [1, 0, 0], [0, -1, 0], [0, 0, 1], (1.5 * 1) / D);
    const out = new Float64Array(w * h);
    const robust = intersectRaySphereBatch(rays, w * h, D, 0.2, 0.3, 1, 'stable', out);
    // reference pixel count from the double-double reference
    let refHits = 0;
    for (let i = 0; i < w * h; i++) {
      const j = i * RAY_STRIDE;
      const x = ref(
        raySphereReference(
          [rays[j], rays[j + 1], rays[j + 2]],
          [rays[j + 3], rays[j + 4], rays[j + 5]],
          [D, 0.2, 0.3],
          1,
        ),
      );
      if (x.tHit !== null) refHits++;
    }
    const naive = intersectRaySphereBatch(rays, w * h, D, 0.2, 0.3, 1, 'naive', out);
    // disc of radius 1 in a 3×3 frame of 48² px: π/9 · 2304 ≈ 804 pixels
    expect(Math.abs(refHits - 804)).toBeLessThan(60);
    expect(Math.abs(robust - refHits)).toBeLessThanOrEqual(2);
    expect(Math.abs(naive - refHits)).toBeGreaterThan(80); // speckled holes (or spurious hits)
  });
});
