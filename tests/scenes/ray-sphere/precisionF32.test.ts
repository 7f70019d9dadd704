// The precision switch of #/ray-sphere: float64 by default (existing links unchanged), float32
// readouts from the float32 core for both methods, and the float32 error-against-distance series.
import { describe, expect, it } from 'vitest';
import { parseParams, serializeParams, defaultValues } from '../../../src/kit/params';
import { intersectRaySphereF32, intersectRaySphere } from '../../../src/core/geometry';
import { activeRows, computeModel } from '../../../src/scenes/ray-sphere/model';
import { errorVsDistanceF32 } from '../../../src/scenes/ray-sphere/precisionF32';
import { schema } from '../../../src/scenes/ray-sphere/params';

describe('precision parameter', () => {
  it('defaults to f64 and is left out of links at its default', () => {
    const p = parseParams(schema, 'o=-3,0.3,0.2&method=naive');
    expect(p.values.precision).toBe('f64');
    expect(p.problems).toEqual([]);
    expect(serializeParams(schema, { ...defaultValues(schema), method: 'naive' })).toBe('method=naive');
    expect(parseParams(schema, 'precision=float32').values.precision).toBe('f32');
    expect(serializeParams(schema, { ...defaultValues(schema), precision: 'f32' })).toBe('precision=f32');
    const bad = parseParams(schema, 'precision=f16');
    expect(bad.values.precision).toBe('f64');
    expect(bad.problems.map((x) => x.name)).toContain('precision');
  });
});

describe('computeModel in float32', () => {
  const far = { o: [0, 0, 0], d: [1, 0, 0], c: [1e4, 0.5, 0], r: 1 } as const;
  it.each(['naive', 'stable'] as const)('%s: every readout is the float32 result', (method) => {
    const m = computeModel({ ...far, o: [...far.o], d: [...far.d], c: [...far.c], method, precision: 'f32' });
    const want = intersectRaySphereF32([0, 0, 0], [1, 0, 0], [1e4, 0.5, 0], 1, method);
    expect(want.ok).toBe(true);
    if (!want.ok || !m.chosen) throw new Error('no result');
    for (const k of ['a', 'b', 'c', 'discriminant', 't0', 't1', 'tHit', 'case'] as const)
      expect(m.chosen[k]).toBe(want[k]);
    expect(activeRows(m).rows).toBe(m.f32!.rows);
    expect(m.chosen.case).toBe(method === 'naive' ? 'tangent' : 'two-hits');
  });

  it('f64 (the default) is the float64 result, with the float32 rows beside it', () => {
    const m = computeModel({ o: [0, 0, 0], d: [1, 0, 0], c: [1e4, 0.5, 0], r: 1, method: 'naive' });
    const want = intersectRaySphere([0, 0, 0], [1, 0, 0], [1e4, 0.5, 0], 1, 'naive');
    expect(m.precision).toBe('f64');
    expect(m.chosen).toEqual(want);
    expect(m.f32!.rows.find((r) => r.method === 'naive')!.caseRight).toBe(false);
    expect(m.f32!.rows.find((r) => r.method === 'stable')!.caseRight).toBe(true);
  });

  it('inputs float32 cannot hold give a message, not NaN', () => {
    const m = computeModel({
      o: [0, 0, 0],
      d: [1e12, 0, 0],
      c: [1e12, 0, 0],
      r: 1,
      method: 'stable',
      precision: 'f32',
    });
    expect(m.chosen).toBeNull();
    expect(m.fatal).toMatch(/float32/);
  });
});

describe('float32 error against distance', () => {
  it('the textbook Δ breaks near 1/√u₃₂ ≈ 4096 radii; the robust one stays small', () => {
    const D = [10, 100, 1e3, 1e4, 1e5];
    const s = errorVsDistanceF32(D);
    expect(s.dist).toEqual(D);
    expect(s.discNaive[0]).toBeLessThan(1e-4);
    expect(s.discNaive[3]).toBeGreaterThan(0.1);
    for (let i = 0; i < D.length; i++) expect(s.hitStable[i]).toBeLessThan(1e-5);
    expect(s.discStable[3]).toBeLessThan(0.05);
  });
});
