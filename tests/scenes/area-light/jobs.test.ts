import { describe, expect, it } from 'vitest';
import { PASS_SPP, estimatesJob, renderJob, type FloorFrame } from '../../../src/scenes/area-light/jobs';
import { buildModel, estimateAll } from '../../../src/scenes/area-light/model';
import { floorJob } from '../../../src/scenes/area-light/floor';
import { defaultValues } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/area-light/params';

const defaults = defaultValues(schema);

describe('area-light jobs (what the worker runs)', () => {
  it('estimatesJob gives the main thread’s numbers', async () => {
    const p = { ...defaults, n: 5000 };
    expect(await estimatesJob(p)).toEqual(estimateAll(buildModel(p), 5000, p.seed));
  });
  it('renderJob reports one frame per pass and its samples per pixel double', async () => {
    const job = floorJob(buildModel(defaults), 3, 8);
    const frames: FloorFrame[] = [];
    const last = await renderJob(job, (_f, partial) => frames.push(partial as FloorFrame));
    expect(frames.length).toBe(PASS_SPP.length - 1);
    expect(last.done).toBe(true);
    expect(last.spp).toBe(PASS_SPP.reduce((a, b) => a + b, 0));
    expect(last.images.length).toBe(3);
    for (const r of last.rmse) expect(r).toBeLessThanOrEqual(frames[0].rmse[0] * 10);
  });
});

describe('renderJob keeps every pass for the timeline', () => {
  it('the result carries all passes, their spp are 1, 2, 4, …, 64 and the last equals the result', async () => {
    const { buildModel } = await import('../../../src/scenes/area-light/model');
    const { floorJob, PASS_TOTAL } = await import('../../../src/scenes/area-light/floor');
    const { defaultValues } = await import('../../../src/kit/params');
    const { schema } = await import('../../../src/scenes/area-light/params');
    const job = floorJob(buildModel(defaultValues(schema)), 3, 8);
    const last = await renderJob(job);
    expect(last.passes.map((p) => p.spp)).toEqual([...PASS_TOTAL]);
    expect(Array.from(last.passes.at(-1)!.images[0])).toEqual(Array.from(last.images[0]));
    // earlier passes are noisier on average than the last (RMSE against the reference)
    expect(last.passes[0].rmse[0]).toBeGreaterThan(last.rmse[0]);
  });
});
