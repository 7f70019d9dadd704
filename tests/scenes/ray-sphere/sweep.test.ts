// The ray–sphere sweep animation: a pure function of (params, t); the Δ series crosses zero
// where the line is tangent; the far preset's textbook Δ flickers in sign, the robust one does not.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { checkInputs } from '../../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../../src/scenes/ray-sphere/model';
import { makeSweep, paramsAt, sweepAt, sweepXRange } from '../../../src/scenes/ray-sphere/sweep';
import { sweepSeries } from '../../../src/scenes/ray-sphere/sweepSeries';
import { PRECISION_PRESETS, schema, type RaySphereParams } from '../../../src/scenes/ray-sphere/params';
import { defaultValues } from '../../../src/kit/params';

const base: RaySphereParams = { ...defaultValues(schema), o: [-3, 0.3, 0.2], d: [1, 0, 0] };
const sw = (p: RaySphereParams) => makeSweep(checkInputs(p), p.sweep, p.extent);
const dist = (o: readonly number[], d: readonly number[], c: readonly number[]) => {
  // distance of the line o + t d from c
  const f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
  const dd = d[0] ** 2 + d[1] ** 2 + d[2] ** 2;
  const k = (f[0] * d[0] + f[1] * d[1] + f[2] * d[2]) / dd;
  return Math.hypot(f[0] - k * d[0], f[1] - k * d[1], f[2] - k * d[2]);
};

describe('sweepAt', () => {
  it('t = 0.5 is exactly the typed configuration, in both modes', () => {
    for (const mode of ['offset', 'rotate'] as const) {
      const s = sweepAt(sw({ ...base, sweep: mode, o: [-3, -1.2, 0.6], d: [1, 0.4, -0.15] }), 0.5);
      expect(s.o).toEqual([-3, -1.2, 0.6]);
      expect(s.d).toEqual([1, 0.4, -0.15]);
    }
  });
  it('offset: the origin moves perpendicular to d by ±E r; the line passes C at |x| r', () => {
    const p = {
      ...base,
      o: [-3, -1.2, 0.6],
      d: [1, 0.4, -0.15],
      c: [0.5, 0.2, -0.1],
      r: 1.3,
      extent: 2,
    } as RaySphereParams;
    const S = sw(p);
    for (const t of [0, 0.1, 0.37, 0.5, 0.9, 1]) {
      const s = sweepAt(S, t);
      const moved = s.o.map((x, i) => x - p.o[i]);
      expect(Math.abs(moved[0] * p.d[0] + moved[1] * p.d[1] + moved[2] * p.d[2])).toBeLessThan(1e-12);
      expect(Math.hypot(...moved)).toBeCloseTo(Math.abs(2 * t - 1) * 2 * 1.3, 12);
      expect(dist(s.o, s.d, p.c)).toBeCloseTo(Math.abs(s.x) * 1.3, 12);
      expect(s.d).toEqual(p.d);
    }
  });
  it('rotate: the origin stays, |d| is kept, the angle to C is |x| angular radii', () => {
    const p = { ...base, sweep: 'rotate', o: [-4, 1, 0.5], d: [2, 0, 0], extent: 3 } as RaySphereParams;
    const S = sw(p);
    const alpha = Math.asin(1 / Math.hypot(4, 1, 0.5));
    for (const t of [0, 0.25, 0.5, 0.8, 1]) {
      const s = sweepAt(S, t);
      expect(s.o).toEqual(p.o);
      expect(Math.hypot(...s.d)).toBeCloseTo(2, 12);
      const toC = [4, -1, -0.5];
      const cos = (s.d[0] * toC[0] + s.d[1] * toC[1] + s.d[2] * toC[2]) / (2 * Math.hypot(4, 1, 0.5));
      expect(Math.acos(Math.min(1, cos)) / alpha).toBeCloseTo(Math.abs(s.x), 9);
    }
  });
  it('is a pure function of (params, t) (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.constantFrom('offset', 'rotate'),
        (t, mode) => {
          const p = { ...base, sweep: mode } as RaySphereParams;
          expect(sweepAt(sw(p), t)).toEqual(sweepAt(sw(p), t));
          const m1 = computeModel(paramsAt(p, sw(p), t));
          const m2 = computeModel(paramsAt(p, sw(p), t));
          expect(m1.chosen).toEqual(m2.chosen);
        },
      ),
      { numRuns: 50 },
    );
  });
});

/** Sign changes of a sampled Δ (zeros skipped: + 0 − is one crossing). */
const flipsOf = (xs: number[]) => {
  const s = xs.map(Math.sign).filter((x) => x !== 0);
  return s.slice(1).filter((x, i) => x !== s[i]).length;
};

describe('sweepSeries', () => {
  it('offset across a unit sphere: miss → two hits → miss, tangent where the line is at distance r', () => {
    const p = { ...base, o: [-3, 0, 0], d: [1, 0, 0], extent: 2 } as RaySphereParams;
    const S = sw(p);
    const ser = sweepSeries(p, S);
    expect(ser.cases[0]).toBe('miss');
    expect(ser.cases[ser.cases.length >> 1]).toBe('two-hits');
    expect(ser.cases[ser.cases.length - 1]).toBe('miss');
    expect(ser.tangents).toHaveLength(2);
    for (const t of ser.tangents) {
      const s = sweepAt(S, t);
      expect(dist(s.o, s.d, p.c)).toBeCloseTo(1, 12);
    }
    // x range: h / r from −2 to 2 (e2 from C towards the line; here the line passes through C)
    const [x0, x1] = sweepXRange(S);
    expect(Math.abs(x1 - x0)).toBeCloseTo(4, 12);
    // Δ of both methods agree here, and equal 4a(r² − h²)
    ser.x.forEach((x, i) => {
      expect(ser.discStable[i]).toBeCloseTo(4 * (1 - x * x), 10);
      expect(ser.discNaive[i]).toBeCloseTo(4 * (1 - x * x), 10);
    });
    expect(ser.naiveSignWrong).toBe(0);
  });
  it('the far preset: the textbook Δ has the wrong sign somewhere in the sweep, the robust Δ changes sign only at tangency', () => {
    const far = PRECISION_PRESETS.find((x) => x.id === 'far')!;
    const p = { ...base, ...far.params } as RaySphereParams;
    const S = sw(p);
    const ser = sweepSeries(p, S);
    expect(ser.naiveSignWrong).toBeGreaterThan(5);
    expect(ser.tangents).toHaveLength(2);
    expect(flipsOf(ser.discStable)).toBe(2);
    // turning the direction instead: the same
    const pr = { ...p, sweep: 'rotate' } as RaySphereParams;
    const sr = sweepSeries(pr, sw(pr));
    expect(flipsOf(sr.discStable)).toBe(sr.tangents.length);
    expect(sr.naiveSignWrong).toBeGreaterThan(5);
  });
  it('the g window holds every root of the sweep', () => {
    const p = { ...base, sweep: 'rotate', o: [-3, -1.2, 0.6], d: [1, 0.4, -0.15] } as RaySphereParams;
    const S = sw(p);
    const ser = sweepSeries(p, S);
    for (let i = 0; i <= 20; i++) {
      const m = computeModel(paramsAt(p, S, i / 20));
      for (const t of [m.chosen!.t0, m.chosen!.t1]) {
        if (t === null) continue;
        expect(t).toBeGreaterThanOrEqual(ser.gWindow.tMin);
        expect(t).toBeLessThanOrEqual(ser.gWindow.tMax);
      }
    }
  });
  it('never throws or yields NaN, for any inputs (property)', () => {
    const num = fc.oneof(
      fc.double({ min: -1e6, max: 1e6, noNaN: true }),
      fc.constantFrom(0, -0, 1e12, NaN, Infinity),
    );
    fc.assert(
      fc.property(
        fc.tuple(num, num, num),
        fc.tuple(num, num, num),
        num,
        fc.constantFrom('offset', 'rotate'),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (o, d, r, mode, t) => {
          const S = makeSweep(checkInputs({ o, d, c: [0, 0, 0], r }), mode, 2.5);
          const ser = sweepSeries({ method: 'stable' }, S, 24);
          // (x = h / r is ±∞ only for a subnormal radius)
          expect(ser.x.some(Number.isNaN)).toBe(false);
          expect(Number.isNaN(sweepAt(S, t).x)).toBe(false);
          expect(sweepAt(S, t).o.every(Number.isFinite)).toBe(true);
          expect(ser.gWindow.tMax).toBeGreaterThan(ser.gWindow.tMin);
        },
      ),
      { numRuns: 80 },
    );
  });
  it('the schema opens at t = 0.5 (the typed configuration) and offers both modes', () => {
    expect(schema.t.default).toBe(0.5);
    expect(schema.sweep.values).toEqual(['offset', 'rotate']);
  });
});

describe('t_min: secondary rays leaving the surface', () => {
  it('with t ≥ 0 many surface points hit themselves (a root t ≈ 0); with t > t_min none do', async () => {
    const { selfIntersectionSurvey } = await import('../../../src/scenes/ray-sphere/secondaryRay');
    for (const [c, r] of [
      [[0, 0, 0], 1],
      [[0.3, -1.7, 2.9], 0.7],
      [[1e8, 0, 0], 1],
    ] as const) {
      for (const method of ['naive', 'stable'] as const) {
        const s = selfIntersectionSurvey(c as unknown as [number, number, number], r, method, 400);
        expect(s.count).toBe(400);
        expect(s.withZero, `${c} ${method}`).toBeGreaterThan(40);
        expect(s.withTMin).toBe(0);
      }
    }
  });
  it('the survey cast in ranges (as the page does, in short tasks) adds up to the whole survey', async () => {
    const { selfIntersectionSurvey, selfIntersectionSurveyRange } =
      await import('../../../src/scenes/ray-sphere/secondaryRay');
    const c: [number, number, number] = [0.3, -1.7, 2.9];
    for (const method of ['naive', 'stable'] as const) {
      const whole = selfIntersectionSurvey(c, 0.7, method, 1000);
      const sum = { count: 0, withZero: 0, withTMin: 0 };
      for (let k = 0; k < 1000; k += 200) {
        const part = selfIntersectionSurveyRange(c, 0.7, method, 1000, k, k + 200);
        expect(part.count).toBe(200);
        sum.count += part.count;
        sum.withZero += part.withZero;
        sum.withTMin += part.withTMin;
      }
      expect(sum).toEqual(whole);
      // a range past the end is empty
      expect(selfIntersectionSurveyRange(c, 0.7, method, 1000, 1000, 1200).count).toBe(0);
    }
  });
  it('the secondary ray from the current hit: its small root is the starting point itself', async () => {
    const { secondaryFromHit, tMinFor } = await import('../../../src/scenes/ray-sphere/secondaryRay');
    const p = { ...base } as RaySphereParams;
    const m = computeModel(p);
    const sec = secondaryFromHit(m.input, m.chosen, 'stable')!;
    expect(Math.abs(sec.offSurface)).toBeLessThan(1e-15);
    // roots: ≈ 0 (the point itself) and ≈ −2r (the far side, behind)
    expect(Math.abs(sec.res.t1!)).toBeLessThan(1e-15);
    expect(sec.res.t0!).toBeCloseTo(-2, 12);
    expect(sec.hitWithTMin).toBeNull();
    expect(tMinFor(2)).toBe(2e-4);
  });
});
