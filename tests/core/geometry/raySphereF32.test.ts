// Ray–sphere intersection in float32 (Math.fround after every operation): hand-worked cases, the
// robust float32 roots against the double-double reference of the same float32 inputs, and the
// textbook form's failure at the distances theory predicts (relative error of Δ ≈ u₃₂ (D/r)²).
import { describe, expect, it } from 'vitest';
import {
  errorInUlpsF32,
  intersectRaySphere,
  intersectRaySphereF32,
  raySphereReference,
  tHitF32,
  toF32,
  ulpDistanceF32,
  ulpF32,
  U32,
  type Vec3,
} from '../../../src/core/geometry';
import { Rng } from '../../../src/core/random';

const fr = Math.fround;

function ok<T extends { ok: boolean }>(r: T): Extract<T, { ok: true }> {
  expect(r.ok).toBe(true);
  return r as Extract<T, { ok: true }>;
}

describe('float32 ulp helpers', () => {
  it('ulp of 1 is 2⁻²³, of 1e4 is 2⁻¹⁰, and the distance counts floats', () => {
    expect(ulpF32(1)).toBe(2 ** -23);
    expect(ulpF32(1e4)).toBe(2 ** -10);
    expect(ulpF32(0)).toBe(2 ** -149);
    expect(ulpDistanceF32(1, 1 + 2 ** -23)).toBe(1);
    expect(ulpDistanceF32(-(2 ** -149), 2 ** -149)).toBe(2);
    expect(ulpDistanceF32(0, -0)).toBe(0);
    expect(ulpDistanceF32(1, NaN)).toBe(Infinity);
    expect(errorInUlpsF32(1 + 2 ** -24, 1)).toBe(0.5);
    expect(errorInUlpsF32(null, 1)).toBe(Infinity);
  });
});

describe('hand-worked float32 cases', () => {
  it('an axis-aligned hit is exact in float32 as in float64', () => {
    // f = (−3, 0.5, 0) (0.5 is exact): a = 1, b = −6, c = 9.25 − 1 = 8.25, Δ = 36 − 33 = 3.
    for (const m of ['naive', 'stable'] as const) {
      const h = ok(intersectRaySphereF32([-3, 0.5, 0], [1, 0, 0], [0, 0, 0], 1, m));
      expect([h.a, h.b, h.c, h.discriminant]).toEqual([1, -6, 8.25, 3]);
      expect(h.case).toBe('two-hits');
      // (6 − √3)/2 and (6 + √3)/2, with √3 rounded to float32 once and each root once more
      const s = fr(Math.sqrt(3));
      expect(h.t0).toBe(m === 'naive' ? fr(fr(6 - s) / 2) : fr(8.25 / fr(3 + fr(Math.sqrt(0.75)))));
      expect(ulpDistanceF32(h.t0!, (6 - Math.sqrt(3)) / 2)).toBeLessThanOrEqual(1);
      expect(ulpDistanceF32(h.t1!, (6 + Math.sqrt(3)) / 2)).toBeLessThanOrEqual(1);
    }
  });

  it('0.3 is rounded to float32 first: c = fround(fround(0.09000000357627869 + 9) − 1)', () => {
    const h = ok(intersectRaySphereF32([-3, 0.3, 0], [1, 0, 0], [0, 0, 0], 1, 'naive'));
    const y = fr(0.3);
    expect(y).toBe(0.30000001192092896);
    expect(h.c).toBe(fr(fr(fr(9) + fr(y * y)) - 1));
    expect(h.inputs.o[1]).toBe(y);
  });

  it('a sphere 10⁴ r away: float32 rounds c = 10⁸ − 0.75 to 10⁸ and b² − 4ac = 0 (a false tangent)', () => {
    // f = (−10⁴, −0.5, 0), d = x̂: a = 1, b = −2·10⁴, |f|² = 10⁸ + 0.25, c = 10⁸ − 0.75, Δ = 3.
    // float32 spacing at 10⁸ is 8: c rounds to 10⁸, b² = 4·10⁸ and 4ac = 4·10⁸ are exact, Δ = 0.
    const o: Vec3 = [0, 0, 0];
    const d: Vec3 = [1, 0, 0];
    const c: Vec3 = [1e4, 0.5, 0];
    const naive = ok(intersectRaySphereF32(o, d, c, 1, 'naive'));
    expect(naive.c).toBe(1e8);
    expect(naive.b).toBe(-2e4);
    expect(naive.discriminant).toBe(0);
    expect(naive.case).toBe('tangent');
    expect(naive.tHit).toBe(1e4); // the true hit is 10⁴ − √0.75 ≈ 9999.134
    // the robust form: β = −10⁴, ℓ = f − (β/a) d = (0, −0.5, 0) exactly, Δ/4 = 1 − 0.25 = 0.75
    const stable = ok(intersectRaySphereF32(o, d, c, 1, 'stable'));
    expect(stable.discriminant).toBe(3);
    expect(stable.case).toBe('two-hits');
    const ref = ok(raySphereReference(o, d, c, 1));
    expect(errorInUlpsF32(stable.t0, ref.t0)).toBeLessThanOrEqual(1);
    expect(errorInUlpsF32(stable.t1, ref.t1)).toBeLessThanOrEqual(1);
    // the same ray in float64 is fine with either method
    expect(ok(intersectRaySphere(o, d, c, 1, 'naive')).case).toBe('two-hits');
  });

  it('exactly tangent stays tangent in float32 (every step exact)', () => {
    for (const m of ['naive', 'stable'] as const) {
      const h = ok(intersectRaySphereF32([-5, 1, 0], [1, 0, 0], [0, 0, 0], 1, m));
      expect(h.case).toBe('tangent');
      expect(h.tHit).toBe(5);
    }
  });

  it('the other cases match the double computation on benign inputs', () => {
    const cases: [Vec3, Vec3, string][] = [
      [[-3, 1.5, 0.2], [1, 0, 0], 'miss'],
      [[0.2, -0.3, 0.1], [1, 0.5, 0], 'inside'],
      [[3, 0.3, 0.2], [1, 0, 0], 'behind'],
    ];
    for (const [o, d, want] of cases)
      for (const m of ['naive', 'stable'] as const)
        expect(ok(intersectRaySphereF32(o, d, [0, 0, 0], 1, m)).case).toBe(want);
  });

  it('refuses what float32 cannot hold, with a message', () => {
    const big = intersectRaySphereF32([0, 0, 0], [1e20, 0, 0], [1e20, 0, 0], 1);
    expect(big.ok).toBe(false);
    if (!big.ok) expect(big.kind).toBe('overflow');
    const tiny = intersectRaySphereF32([0, 0, 0], [1e-30, 0, 0], [5, 0, 0], 1);
    expect(tiny.ok).toBe(false);
    if (!tiny.ok) expect(tiny.message).toMatch(/float32/);
    expect(intersectRaySphereF32([0, 0, 0], [1, 0, 0], [5, 0, 0], 1e-50).ok).toBe(false);
    expect(intersectRaySphereF32([NaN, 0, 0], [1, 0, 0], [5, 0, 0], 1).ok).toBe(false);
  });
});

/** Rays from the origin toward a sphere D radii away, aimed at points ρ r off its centre. */
function raysAt(D: number, count: number, seed: number, maxRho = 0.95): { d: Vec3; c: Vec3 }[] {
  const rng = new Rng(seed);
  const rnd = () => rng.nextFloat();
  const out: { d: Vec3; c: Vec3 }[] = [];
  for (let i = 0; i < count; i++) {
    // a random direction to the centre, a random perpendicular offset of length ρ ∈ [0, maxRho]
    const u = 2 * rnd() - 1;
    const ph = 2 * Math.PI * rnd();
    const s = Math.sqrt(1 - u * u);
    const w: Vec3 = [s * Math.cos(ph), s * Math.sin(ph), u];
    const c = toF32([D * w[0], D * w[1], D * w[2]]);
    const t = Math.abs(w[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
    const p1 = normalize(cross(w, t as unknown as Vec3));
    const p2 = cross(w, p1);
    const rho = maxRho * Math.sqrt(rnd());
    const al = 2 * Math.PI * rnd();
    const aim: Vec3 = [
      c[0] + rho * (Math.cos(al) * p1[0] + Math.sin(al) * p2[0]),
      c[1] + rho * (Math.cos(al) * p1[1] + Math.sin(al) * p2[1]),
      c[2] + rho * (Math.cos(al) * p1[2] + Math.sin(al) * p2[2]),
    ];
    out.push({ d: toF32(normalize(aim)), c });
  }
  return out;
}

// From D/r = 1.5: as D/r → 1 the origin approaches the surface and c = |f|² − r² cancels in any
// form (its float32 rounding error is u₃₂|f|², not u₃₂|c|), so the near root loses relative accuracy.
describe('robust float32 roots against the exact roots of the same float32 inputs', () => {
  const distances = [1.5, 2, 4, 10, 30, 100, 300, 1e3, 3e3, 1e4, 3e4, 1e5];
  it.each(distances)('D/r = %d: t₀, t₁ and t-hit within 4 float32 ulps; case right', (D) => {
    let worst = 0;
    for (const { d, c } of raysAt(D, 200, 1000 + D, 0.9)) {
      const ref = ok(raySphereReference([0, 0, 0], d, c, 1));
      const h = ok(intersectRaySphereF32([0, 0, 0], d, c, 1, 'stable'));
      expect(h.case).toBe(ref.case);
      worst = Math.max(
        worst,
        errorInUlpsF32(h.t0, ref.t0),
        errorInUlpsF32(h.t1, ref.t1),
        errorInUlpsF32(h.tHit, ref.tHit),
      );
    }
    expect(worst).toBeLessThanOrEqual(4);
  });

  it('the hot-loop kernel returns the same t-hit as the full result, bit for bit', () => {
    for (const D of [2, 100, 1e4]) {
      for (const { d, c } of raysAt(D, 100, 7, 1.2)) {
        for (const m of ['naive', 'stable'] as const) {
          const h = ok(intersectRaySphereF32([0, 0, 0], d, c, 1, m));
          const t = tHitF32(0, 0, 0, d[0], d[1], d[2], c[0], c[1], c[2], 1, m === 'stable');
          expect(t).toBe(h.tHit === null ? Infinity : h.tHit);
        }
      }
    }
  });
});

describe('the textbook float32 form fails where theory says: relative error of Δ ≈ u₃₂ (D/r)²', () => {
  /** Median relative error of Δ over a set of rays, and the fraction of wrong cases. */
  function textbookStats(D: number) {
    const errs: number[] = [];
    let wrong = 0;
    const rays = raysAt(D, 200, 77 + D, 0.9);
    for (const { d, c } of rays) {
      const ref = ok(raySphereReference([0, 0, 0], d, c, 1));
      const h = ok(intersectRaySphereF32([0, 0, 0], d, c, 1, 'naive'));
      errs.push(Math.abs(h.discriminant - ref.discriminant) / Math.abs(ref.discriminant));
      if (h.case !== ref.case) wrong++;
    }
    errs.sort((x, y) => x - y);
    return { median: errs[errs.length >> 1], wrongFrac: wrong / rays.length };
  }

  it('close (D/r ≤ 30): Δ is good to a few u₃₂ (D/r)², every case right', () => {
    for (const D of [2, 10, 30]) {
      const s = textbookStats(D);
      expect(s.median).toBeLessThan(20 * U32 * D * D);
      expect(s.wrongFrac).toBe(0);
    }
  });

  it('the error grows like (D/r)²: ten times farther, about a hundred times worse', () => {
    const e1 = textbookStats(30).median;
    const e2 = textbookStats(300).median;
    expect(e2 / e1).toBeGreaterThan(20);
    expect(e2 / e1).toBeLessThan(500);
  });

  it('at D/r = 10⁴ > 1/√u₃₂ ≈ 4096 Δ is noise: relative error ≳ 1 and many cases wrong', () => {
    const s = textbookStats(1e4);
    expect(s.median).toBeGreaterThan(0.3);
    expect(s.wrongFrac).toBeGreaterThan(0.2);
    // the robust float32 form on the very same rays keeps every case
    for (const { d, c } of raysAt(1e4, 200, 77 + 1e4, 0.9)) {
      const ref = ok(raySphereReference([0, 0, 0], d, c, 1));
      expect(ok(intersectRaySphereF32([0, 0, 0], d, c, 1, 'stable')).case).toBe(ref.case);
    }
  });

  it('the same rays in float64 are still fine with the textbook form at 10⁴', () => {
    for (const { d, c } of raysAt(1e4, 50, 5, 0.9)) {
      const ref = ok(raySphereReference([0, 0, 0], d, c, 1));
      expect(ok(intersectRaySphere([0, 0, 0], d, c, 1, 'naive')).case).toBe(ref.case);
    }
  });
});

function cross(a: Vec3, b: Vec3): Vec3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
function normalize(a: Vec3): Vec3 {
  const n = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / n, a[1] / n, a[2] / n];
}
