// The ray–sphere scene model: input fallbacks, per-method rows vs the reference, the 2D frame,
// the distant-sphere image and the error-vs-distance series.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { checkInputs } from '../../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../../src/scenes/ray-sphere/model';
import { canonicalFrame, frameFits, toFrame, fromFrame } from '../../../src/scenes/ray-sphere/frame';
import { gCurve } from '../../../src/scenes/ray-sphere/gCurve';
import { renderDistant } from '../../../src/scenes/ray-sphere/distantImage';
import { errorVsDistance } from '../../../src/scenes/ray-sphere/errorSeries';
import { tidy } from '../../../src/scenes/ray-sphere/tidy';
import { checkValues } from '../../../src/scenes/ray-sphere/check';
import {
  schema,
  CASE_PRESETS,
  PRECISION_PRESETS,
  type RaySphereParams,
} from '../../../src/scenes/ray-sphere/params';
import type { Vec3 } from '../../../src/core/geometry';
import { defaultValues } from '../../../src/kit/params';

// the schema's defaults: o = (−3, −1.2, 0.6), d = (1, 0.4, −0.15), the unit sphere at the origin
const base: RaySphereParams = defaultValues(schema);

describe('input checks: bad input → message + safe fallback', () => {
  it('zero direction falls back to the default direction', () => {
    const k = checkInputs({ ...base, d: [0, 0, 0] });
    expect(k.d).toEqual(schema.d.default);
    expect(k.problems.map((x) => x.message).join(' ')).toMatch(/points nowhere/);
    expect(k.problems.map((x) => x.name)).toEqual(['d']);
  });
  it('zero radius → 1, negative radius → |r|', () => {
    expect(checkInputs({ ...base, r: 0 }).r).toBe(1);
    expect(checkInputs({ ...base, r: -2.5 }).r).toBe(2.5);
    expect(checkInputs({ ...base, r: -2.5 }).problems[0]).toMatchObject({
      name: 'r',
      message: expect.stringMatching(/negative radius/),
    });
  });
  it('non-finite numbers fall back to defaults', () => {
    const k = checkInputs({ ...base, o: [NaN, 0, 0], r: Infinity });
    expect(k.o).toEqual(schema.o.default);
    expect(k.r).toBe(1);
    expect(k.problems.map((x) => x.name)).toEqual(['o', 'r']);
  });
  it('each replaced value names its parameter, and checkValues reports exactly these', () => {
    const p = {
      ...base,
      o: [0, Infinity, 0] as [number, number, number],
      c: [NaN, 0, 0] as [number, number, number],
      d: [1e-200, 0, 0] as [number, number, number],
      r: 0,
    };
    const k = checkInputs(p);
    expect(k.problems.map((x) => x.name)).toEqual(['o', 'c', 'r', 'd']);
    expect(k.problems.map((x) => x.message)).toEqual(k.failures.map((f) => f.message));
    expect(checkValues(p)).toEqual(k.problems);
    expect(checkValues(base)).toEqual([]);
  });
  it('fine inputs pass untouched', () => {
    expect(checkInputs(base).problems).toEqual([]);
  });
  it('the model never throws and never yields NaN readouts, for any numbers', () => {
    const num = fc.oneof(fc.double(), fc.constantFrom(0, -0, 1e300, -1e300, NaN, Infinity));
    fc.assert(
      fc.property(
        fc.tuple(num, num, num),
        fc.tuple(num, num, num),
        fc.tuple(num, num, num),
        num,
        (o, d, c, r) => {
          const m = computeModel({ o, d, c, r, method: 'naive' });
          if (m.fatal) return typeof m.fatal === 'string' && m.chosen === null;
          const x = m.chosen!;
          return (
            [x.a, x.b, x.c, x.discriminant].every(Number.isFinite) && (x.t0 === null || Number.isFinite(x.t0))
          );
        },
      ),
      { seed: 21, numRuns: 300 },
    );
  });
});

describe('presets', () => {
  it('each case preset produces its case with both methods and the reference', () => {
    for (const p of CASE_PRESETS) {
      const m = computeModel({ ...base, ...p.params });
      expect(m.reference!.case).toBe(p.id);
      for (const row of m.rows) expect(row.res.case).toBe(p.id);
    }
  });
  it('each precision preset breaks the textbook form and not the robust one', () => {
    for (const p of PRECISION_PRESETS) {
      const m = computeModel({ ...base, ...p.params });
      const naive = m.rows.find((r) => r.method === 'naive')!;
      const stable = m.rows.find((r) => r.method === 'stable')!;
      expect(stable.caseRight).toBe(true);
      if (stable.errHit !== null) expect(stable.errHit).toBeLessThan(1e-14);
      const naiveBad = !naive.caseRight || (naive.errT0 ?? 0) > 1e-10;
      expect(naiveBad, p.id).toBe(true);
    }
  });
});

describe('2D frame through the ray and the centre', () => {
  it('puts the ray on a horizontal line at height |l| above the centre', () => {
    const o: Vec3 = [-3, -1.2, 0.6];
    const d: Vec3 = [1, 0.4, -0.15];
    const fr = canonicalFrame(o, d, [0, 0, 0]);
    const [x0, y0] = toFrame(fr, o);
    const [x1, y1] = toFrame(fr, [o[0] + d[0], o[1] + d[1], o[2] + d[2]]);
    expect(Math.abs(y1 - y0)).toBeLessThan(1e-12);
    expect(x1 - x0).toBeCloseTo(Math.hypot(...d), 12);
    expect(y0).toBeGreaterThan(0);
    const back = fromFrame(fr, x0, y0);
    back.forEach((v, i) => expect(v).toBeCloseTo(o[i], 12));
    expect(frameFits(fr, o, d, [0, 0, 0], 1e-9)).toBe(true);
    expect(frameFits(fr, o, d, [0, 1, 0], 1e-9)).toBe(false);
  });
  it('handles a ray through the centre', () => {
    const fr = canonicalFrame([-3, 0, 0], [1, 0, 0], [0, 0, 0]);
    expect(fr.e2).toEqual([0, 0, 1]);
  });
  it('tidy rounds to the step without binary noise', () => {
    expect(tidy(0.30000000000000004, 0.01)).toBe(0.3);
    expect(tidy(-1.2345, 0.001)).toBe(-1.234);
  });
});

describe('g(t) curve', () => {
  it('is zero at the roots (vertex form) and spans them', () => {
    const m = computeModel({ ...base, ...CASE_PRESETS[0].params });
    const g = gCurve(m.chosen!);
    expect(g.tMin).toBeLessThan(m.chosen!.t0!);
    expect(g.tMax).toBeGreaterThan(m.chosen!.t1!);
    const { a, b, c } = m.chosen!;
    for (const t of [m.chosen!.t0!, m.chosen!.t1!])
      expect(Math.abs(a * t * t + b * t + c)).toBeLessThan(1e-12);
  });
});

describe('distant sphere image and error vs distance', () => {
  it('at 10⁸ radii the textbook image has holes the robust one does not', () => {
    const img = renderDistant(1e8, 64, 64);
    const near = renderDistant(10, 64, 64);
    // near: both agree almost everywhere; far: thousands of pixels differ
    expect(near.disagree).toBeLessThanOrEqual(2);
    expect(img.disagree).toBeGreaterThan(200);
    // the robust disc covers ≈ π·(0.7·32)² ≈ 1580 pixels at any distance
    expect(Math.abs(img.stableHits - near.stableHits)).toBeLessThan(30);
  });
  it('textbook Δ error grows like ε(D/r)², robust stays far below', () => {
    const s = errorVsDistance([1, 4, 6, 8]);
    expect(s.discNaive[3]).toBeGreaterThan(0.1); // garbage at 1e8
    expect(s.discStable[3]).toBeLessThan(1e-6);
    expect(s.discNaive[2]).toBeGreaterThan(100 * s.discNaive[0]);
    expect(s.hitStable.every((e) => e < 1e-14)).toBe(true);
  });
});
