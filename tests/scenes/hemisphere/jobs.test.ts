import { describe, expect, it } from 'vitest';
import { compileExpression } from '../../../src/core/expr';
import {
  FIRST_CHUNK,
  MAX_CHUNK,
  pointsArgsOf,
  pointsJob,
  repeatJob,
  statsJob,
  type Compile2,
  type PointsChunk,
  type StatsArgs,
} from '../../../src/scenes/hemisphere/jobs';
import { computeDrawStats, drawDirections } from '../../../src/scenes/hemisphere/drawStats';
import { lobeFromParams } from '../../../src/scenes/hemisphere/lobe';
import { repeatEstimates } from '../../../src/scenes/hemisphere/q2Estimates';
import { xiColor } from '../../../src/scenes/hemisphere/view/colors';

const compile: Compile2 = async (src, vars) => {
  const r = await compileExpression(src, vars);
  return r.ok ? { ok: true, fn: r.fn as (...a: number[]) => number } : r;
};
const base: StatsArgs = {
  lobe: 'exam',
  exponent: 8,
  pdf: 'cos(theta)^2',
  f: 'cos(theta)',
  points: 'independent',
  seed: 7,
  n: 2000,
  sampleLobe: true,
};

describe('hemisphere jobs (what the worker runs)', () => {
  it('statsJob gives the numbers of computeDrawStats on the lobe lobeFromParams builds', async () => {
    const got = await statsJob(base, compile);
    const want = computeDrawStats(lobeFromParams('exam', 8).lobe, (t) => Math.cos(t), 'independent', 7, 2000);
    expect(got.chi2!.pValue).toBe(want.chi2!.pValue);
    expect(got.q2.importance.estimate).toBe(want.q2.importance.estimate);
  });
  it('a custom density is tabulated the same way in the job and in lobeFromParams', async () => {
    const got = await statsJob({ ...base, lobe: 'custom' }, compile);
    const lobe = lobeFromParams('custom', 8, (t) => Math.cos(t) ** 2).lobe;
    expect(lobe).not.toBeNull();
    expect(got.chi2!.pValue).toBe(
      computeDrawStats(lobe, (t) => Math.cos(t), 'independent', 7, 2000).chi2!.pValue,
    );
  });
  it('the inverted Jacobian samples nothing; a bad integrand refuses the repeat job', async () => {
    expect((await statsJob({ ...base, sampleLobe: false }, compile)).chi2).toBeNull();
    await expect(repeatJob({ ...base, f: 'cos(', runs: 4, perRun: 8 }, compile)).rejects.toThrow(
      /does not compile/,
    );
  });
  it('repeatJob reports progress and matches repeatEstimates', async () => {
    const seen: number[] = [];
    const got = await repeatJob({ ...base, runs: 128, perRun: 16 }, compile, (x) => seen.push(x));
    const want = repeatEstimates(
      lobeFromParams('exam', 8).lobe,
      (t) => Math.cos(t),
      'independent',
      7,
      128,
      16,
    );
    expect(Array.from(got.importance)).toEqual(Array.from(want.importance));
    expect(seen.length).toBeGreaterThan(0);
  });
});

describe('the 3D view points, streamed from the worker', () => {
  const args = { lobe: 'phong' as const, exponent: 12, pdf: '', points: 'sobol' as const, seed: 5, n: 9000 };
  it('chunks cover [0, n) in order: the directions and (ξ₁, ξ₂) of drawDirections, in float32, and their colours', async () => {
    const chunks: PointsChunk[] = [];
    const r = await pointsJob(args, compile, (_f, c) => chunks.push(c));
    expect(r.n).toBe(9000);
    expect(chunks[0].count).toBe(FIRST_CHUNK);
    let next = 0;
    for (const c of chunks) {
      expect(c.start).toBe(next);
      expect(c.count).toBeLessThanOrEqual(MAX_CHUNK);
      next += c.count;
    }
    expect(next).toBe(9000);
    const { u, dirs } = drawDirections(lobeFromParams('phong', 12).lobe!, 'sobol', 5, 9000);
    const rgb = new Uint8Array(3);
    for (const c of chunks)
      for (const i of [0, c.count >> 1, c.count - 1]) {
        const k = c.start + i;
        expect(c.pos[3 * i + 2]).toBe(Math.fround(dirs[3 * k + 2]));
        expect(c.xi[2 * i]).toBe(Math.fround(u[2 * k]));
        xiColor(u[2 * k], u[2 * k + 1], rgb);
        expect(Array.from(c.col.subarray(3 * i, 3 * i + 3))).toEqual(Array.from(rgb));
      }
  });
  it('refuses without a density; a typed one is compiled and tabulated as on the page', async () => {
    await expect(pointsJob({ ...args, lobe: 'custom', pdf: 'cos(' }, compile, () => {})).rejects.toThrow(
      /no valid density/,
    );
    const chunks: PointsChunk[] = [];
    await pointsJob({ ...args, lobe: 'custom', pdf: 'cos(theta)^2', n: 100 }, compile, (_f, c) =>
      chunks.push(c),
    );
    const { dirs } = drawDirections(
      lobeFromParams('custom', 0, (t) => Math.cos(t) ** 2).lobe!,
      'sobol',
      5,
      100,
    );
    expect(chunks[0].pos[3 * 99]).toBe(Math.fround(dirs[3 * 99]));
  });
  it('pointsArgsOf keeps only what the lobe reads: the exponent outside Phong and the density outside custom do not restart the points', () => {
    const p = {
      lobe: 'exam' as const,
      exponent: 8,
      pdf: 'cos(theta)',
      points: 'halton' as const,
      seed: 3,
      n: 10,
    };
    expect(pointsArgsOf(p)).toEqual(pointsArgsOf({ ...p, exponent: 50, pdf: 'sin(theta)' }));
    expect(pointsArgsOf({ ...p, lobe: 'phong' })).not.toEqual(
      pointsArgsOf({ ...p, lobe: 'phong', exponent: 9 }),
    );
    expect(pointsArgsOf({ ...p, lobe: 'custom' })).not.toEqual(
      pointsArgsOf({ ...p, lobe: 'custom', pdf: 'sin(theta)' }),
    );
  });
});
