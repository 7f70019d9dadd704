import { describe, expect, it } from 'vitest';
import {
  animFrame,
  growCount,
  morphFraction,
  squarePoint,
  warpedGrid,
  GRID_LINES,
} from '../../../src/scenes/hemisphere/animation';
import { makeLobe } from '../../../src/scenes/hemisphere/lobe';
import { rmseOverRuns } from '../../../src/scenes/hemisphere/q2Estimates';
import { varianceCheck } from '../../../src/scenes/hemisphere/varianceCheck';
import { exactIntegral } from '../../../src/scenes/hemisphere/integral';
import { computeDrawStats } from '../../../src/scenes/hemisphere/drawStats';
import { fillSequence2D } from '../../../src/core/random';

const cosTheta = (t: number) => Math.cos(t);

describe('hemisphere animation model (pure in params, seed, t)', () => {
  it('growth: 0 at t = 0, n at t = 1, monotone in between', () => {
    expect(growCount(20000, 0)).toBe(0);
    expect(growCount(20000, 1)).toBe(20000);
    expect(growCount(20000, 0.5)).toBe(Math.round(Math.sqrt(20000)));
    let last = 0;
    for (let i = 0; i <= 100; i++) {
      const c = growCount(1e6, i / 100);
      expect(c).toBeGreaterThanOrEqual(last);
      last = c;
    }
  });

  it('morph fraction eases from 0 to 1 and clamps', () => {
    expect(morphFraction(0)).toBe(0);
    expect(morphFraction(1)).toBe(1);
    expect(morphFraction(0.5)).toBe(0.5);
    expect(morphFraction(-3)).toBe(0);
    expect(morphFraction(NaN)).toBe(0);
    expect(morphFraction(0.25)).toBeLessThan(0.25);
  });

  it('the tracked sample starts in the square at its (ξ₁, ξ₂) and ends on the hemisphere at its direction', () => {
    const lobe = makeLobe('exam', 8)!;
    const u = new Float64Array(2);
    fillSequence2D('stratified', 5, 64, u, 0, 1, 0);
    const a = animFrame(lobe, 'stratified', 5, 64, 'warp', 0);
    expect(a.tracked!.xi1).toBe(u[0]);
    expect(a.tracked!.pos).toEqual(Array.from(squarePoint(u[0], u[1])));
    const b = animFrame(lobe, 'stratified', 5, 64, 'warp', 1);
    expect(b.tracked!.pos).toEqual(b.tracked!.dir);
    expect(Math.hypot(...b.tracked!.dir)).toBeCloseTo(1, 12);
    // θ = arcsin √ξ₁ for the exam lobe
    expect(b.tracked!.theta).toBeCloseTo(Math.asin(Math.sqrt(u[0])), 12);
    const mid = animFrame(lobe, 'stratified', 5, 64, 'warp', 0.5);
    for (let i = 0; i < 3; i++)
      expect(mid.tracked!.pos[i]).toBeCloseTo((a.tracked!.pos[i] + b.tracked!.dir[i]) / 2, 12);
    // the growth shows the same sample on the hemisphere once it is drawn
    expect(animFrame(lobe, 'stratified', 5, 64, 'grow', 0).shown).toBe(0);
    expect(animFrame(lobe, 'stratified', 5, 64, 'grow', 1).tracked!.pos).toEqual(b.tracked!.dir);
    expect(animFrame(null, 'stratified', 5, 64, 'warp', 1).tracked).toBeNull();
  });

  it('the warped grid: square at s = 0, unit directions at s = 1', () => {
    const lobe = makeLobe('cosine', 8)!;
    const g0 = warpedGrid(lobe, 0, 8);
    const g1 = warpedGrid(lobe, 1, 8);
    expect(g0.pos.length).toBe(3 * 2 * 2 * (GRID_LINES + 1) * 8);
    for (let k = 0; k < g0.pos.length / 3; k++) {
      expect(g0.pos[3 * k]).toBeCloseTo(2 * g0.xi[2 * k] - 1, 14);
      expect(g0.pos[3 * k + 2]).toBe(0);
      expect(Math.hypot(g1.pos[3 * k], g1.pos[3 * k + 1], g1.pos[3 * k + 2])).toBeCloseTo(1, 9);
    }
  });
});

describe('variance warnings', () => {
  it('Phong with f = cos θ: finite for n ≤ 2, infinite for n ≥ 3 (f/p ∝ cos^{1−n} θ)', () => {
    for (const n of [0, 1, 2])
      expect(varianceCheck(makeLobe('phong', n)!, cosTheta, Math.PI).infinite).toBe(false);
    for (const n of [3, 8, 100]) {
      const v = varianceCheck(makeLobe('phong', n)!, cosTheta, Math.PI);
      expect(v.infinite).toBe(true);
      expect(v.importanceVar).toBe(Infinity);
    }
  });

  it('closed forms: cosine lobe zero variance, uniform Var = 4π²/3 − π², exam lobe (1 − e^{−2π})/(2k) − π²', () => {
    const c = varianceCheck(makeLobe('cosine', 8)!, cosTheta, Math.PI);
    expect(c.infinite).toBe(false);
    expect(c.importanceVar).toBeLessThan(1e-8);
    expect(c.uniformVar).toBeCloseTo((4 * Math.PI ** 2) / 3 - Math.PI ** 2, 8);
    const ex = makeLobe('exam', 8)!;
    const e = varianceCheck(ex, cosTheta, Math.PI);
    expect(e.infinite).toBe(false);
    expect(e.importanceVar / ((1 - Math.exp(-2 * Math.PI)) / (2 * ex.k) - Math.PI ** 2) - 1).toBeLessThan(
      1e-6,
    );
    expect(e.ratio).toBeGreaterThan(10);
  });

  it('RMSE over randomized runs: Sobol beats independent points at equal N', () => {
    const lobe = makeLobe('uniform', 8)!;
    const sob = rmseOverRuns(lobe, cosTheta, 'sobol', 1, 1024, Math.PI, 16);
    const ind = rmseOverRuns(lobe, cosTheta, 'independent', 1, 1024, Math.PI, 16);
    expect(sob.runs).toBe(16);
    expect(sob.uniform).toBeLessThan(ind.uniform / 4);
    expect(computeDrawStats(lobe, cosTheta, 'halton', 1, 256).rmse).not.toBeNull();
    expect(computeDrawStats(lobe, cosTheta, 'independent', 1, 256).rmse).toBeNull();
    expect(exactIntegral(cosTheta)).toBeCloseTo(Math.PI, 12);
  });
});
