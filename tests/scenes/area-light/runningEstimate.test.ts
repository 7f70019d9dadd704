import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { geometry } from '../../../src/scenes/area-light/view/RunningEstimate';
import type { SampleRun } from '../../../src/scenes/area-light/animation';

function run(mean: number[], stderr: number[] = mean.map((_, i) => (i ? 0.1 : NaN))): SampleRun {
  const n = mean.length;
  return {
    strategy: 'area',
    count: n,
    points: new Float64Array(3 * n),
    terms: Float64Array.from(mean),
    mean: Float64Array.from(mean),
    stderr: Float64Array.from(stderr),
  } as SampleRun;
}

const NUM = /-?\d+(\.\d+)?/;
/** Every coordinate of an SVG path is a number ("NaN" or "Infinity" in an attribute is a console error). */
function pathOk(d: string): boolean {
  return (
    !/NaN|Infinity/.test(d) &&
    (d === '' ||
      d
        .split(/[MLZ]/)
        .filter(Boolean)
        .every((p) => p.split(',').every((c) => NUM.test(c))))
  );
}

describe('running-estimate plot geometry: never NaN in an attribute', () => {
  it('a finite run: the line has a point per sample and y stays inside the plot', () => {
    const g = geometry(run([1, 2, 1.5, 1.6, 1.55, 1.52, 1.51, 1.5, 1.5, 1.49]), 1.5);
    expect(g.line.split('L').length).toBe(10);
    expect(pathOk(g.line) && pathOk(g.band)).toBe(true);
    expect(Number.isFinite(g.yOf(1.5))).toBe(true);
  });

  it('NaN and infinite means (degenerate configurations) break the line, set no scale and land nowhere', () => {
    const g = geometry(run([1, NaN, 2, Infinity, 3, -Infinity, 2.5, 2.4, 2.45, 2.5]), NaN);
    expect(pathOk(g.line)).toBe(true);
    expect(pathOk(g.band)).toBe(true);
    expect(g.line.match(/M/g)!.length).toBe(4); // restarted after each gap
    expect(g.yTicks.every(Number.isFinite)).toBe(true);
    for (const v of [NaN, Infinity, -Infinity, 1e308]) expect(Number.isFinite(g.yOf(v))).toBe(true);
  });

  it('any means, even past the largest double, and any reference: finite paths, ticks and positions', () => {
    const value = fc.oneof(fc.double(), fc.constantFrom(NaN, Infinity, -Infinity, 1.7e308, -1.7e308, 0));
    fc.assert(
      fc.property(fc.array(value, { minLength: 1, maxLength: 40 }), value, (mean, ref) => {
        const g = geometry(run(mean), ref);
        expect(pathOk(g.line)).toBe(true);
        expect(pathOk(g.band)).toBe(true);
        expect(g.yTicks.every((t) => Number.isFinite(g.yOf(t)))).toBe(true);
        for (const m of mean) expect(Number.isFinite(g.yOf(m))).toBe(true);
      }),
    );
  });
});
