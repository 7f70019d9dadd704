import { describe, expect, it } from 'vitest';
import { compileExpression } from '../../../src/core/expr';
import { repeatJob, statsJob, type Compile2, type StatsArgs } from '../../../src/scenes/hemisphere/jobs';
import { computeDrawStats, lobeFromParams, repeatEstimates } from '../../../src/scenes/hemisphere/model';

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
