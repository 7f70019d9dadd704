import { describe, expect, it } from 'vitest';
import { defaultValues } from '../../../src/kit/params';
import { EXAM_PRESET, schema, type AreaLightParams } from '../../../src/scenes/area-light/params';
import { animationFrame, sampleRun } from '../../../src/scenes/area-light/animation';
import { buildModel, targetValue } from '../../../src/scenes/area-light/model';
import { patchModel } from '../../../src/scenes/area-light/patch';
import {
  centreView,
  describeAreaLight,
  describeSamples,
  wastedSamples,
} from '../../../src/scenes/area-light/view/describe';
import { formatNumber } from '../../../src/ui/Readout';

/** The description of the main figure for these parameters at position t, and what it was built from. */
function described(patch: Partial<AreaLightParams> = {}, t?: number, hidden = false) {
  const v = { ...defaultValues(schema), ...patch };
  const m = buildModel(v);
  const pt = patchModel(m, v.pu, v.pv, v.psize, v.ptilt);
  const run = sampleRun(m, v.strategy, 1024, v.seed);
  const fr = animationFrame(run, t ?? v.t);
  return {
    text: describeAreaLight(m, pt, { strategy: v.strategy, run, frame: fr, target: targetValue(m), hidden }),
    m,
    pt,
    run,
    fr,
  };
}

describe('describeAreaLight: the main figure in words, with the live numbers', () => {
  it('holds the light’s tilt, the cosines at its centre, the patch’s dω and the estimate ± error', () => {
    const { text, m, pt, fr } = described();
    const cv = centreView(m);
    expect(text).toContain('tilted 30° from the floor (tilt −30° about its x axis)');
    expect(text).toContain(`cos θ = ${formatNumber(cv.cosTheta, 3)} at the point`);
    expect(text).toContain(`cos θₗ = ${formatNumber(cv.cosThetaL, 3)} at the light`);
    expect(cv.cosTheta).not.toBeCloseTo(cv.cosThetaL, 2);
    expect(text).toContain(`dω = dA cos θₗ / r² = ${formatNumber(pt.approx, 4)} sr`);
    expect(text).toContain(`dA⊥ = ${formatNumber(pt.cosThetaL, 3)} dA`);
    expect(text).toContain(`Ω = ${formatNumber(m.solidAngle, 4)} sr`);
    expect(text).toContain('1024 of 1024 arrived');
    expect(text).toContain(
      `running estimate ${formatNumber(fr.estimate, 4)} ± ${formatNumber(fr.stderr, 2)}`,
    );
    expect(text).toContain(`reference ${formatNumber(m.reference, 4)}`);
  });

  it('changes when the light tilts, and says so when it is parallel to the floor', () => {
    const a = described().text;
    const b = described({ tilt: 40 }).text;
    expect(b).not.toBe(a);
    expect(b).toContain('tilted 40° from the floor (tilt 40° about its x axis)');
    const exam = described(EXAM_PRESET.params).text;
    expect(exam).toContain('parallel to the floor');
    expect(exam).not.toContain('tilted');
    expect(exam).toContain('cos θ = cos θₗ = 1;'); // the light's centre straight above the point
  });

  it('changes with the patch and with the position on the timeline (a paused frame has its own numbers)', () => {
    expect(described({ ptilt: 40 }).text).not.toBe(described().text);
    const early = described({}, 10);
    expect(early.text).toContain('10 of 1024 arrived');
    expect(early.text).toContain(formatNumber(early.fr.estimate, 4));
    expect(early.text).not.toBe(described({}, 11).text);
    expect(described({}, 0).text).toContain('none yet (0 of 1024)');
  });

  it('counts the wasted samples as the figure colours them, and hides the estimate when asked to', () => {
    // a vertical light half below the horizon: many samples contribute nothing
    const { run, fr, m } = described({ lc: [0, 1, 0.2], tilt: -90 }, 200);
    const w = wastedSamples(run, fr.k);
    expect(w).toBeGreaterThan(0);
    expect(w).toBe(Array.from(run.terms.slice(0, 200)).filter((x) => !(x > 0)).length);
    const hiddenText = describeSamples({
      strategy: 'area',
      run,
      frame: fr,
      target: targetValue(m),
      hidden: true,
    });
    expect(hiddenText).toContain(`${w} of them wasted`);
    expect(hiddenText).toContain('hidden until you reveal');
    expect(hiddenText).not.toContain(formatNumber(fr.estimate, 4));
  });

  it('tilt as the angle from the floor; minus signs are real minus signs', async () => {
    const { tiltFromFloor, isParallel } = await import('../../../src/scenes/area-light/view/describe');
    expect([0, 30, -30, 150, 180, 270, -360].map(tiltFromFloor)).toEqual([0, 30, 30, 30, 0, 90, 0]);
    expect([0, 180, -180, 360].every(isParallel)).toBe(true);
    expect(isParallel(30)).toBe(false);
    expect(described({ lc: [0, -0.5, 2] }).text).toContain('(0, −0.5, 2)');
  });

  it('stays finite words for a light facing away (estimate 0, no error)', () => {
    const { text } = described({ tilt: 180 });
    expect(text).toContain('facing away');
    expect(text).not.toMatch(/NaN|undefined|Infinity/);
  });
});

describe('the running estimate in words, as a table and as ticks', () => {
  it('reads out at 1, 2, 4 … 32, then every 32nd, and at k itself', async () => {
    const { runningPoints } = await import('../../../src/scenes/area-light/view/describe');
    expect(runningPoints(0)).toEqual([]);
    expect(runningPoints(1)).toEqual([1]);
    expect(runningPoints(5)).toEqual([1, 2, 4, 5]);
    const p = runningPoints(1024);
    expect(p.slice(0, 7)).toEqual([1, 2, 4, 8, 16, 32, 64]);
    expect(p[p.length - 1]).toBe(1024);
    expect(p.every((x, i) => i === 0 || x > p[i - 1]!)).toBe(true);
    expect(runningPoints(100)).toEqual([1, 2, 4, 8, 16, 32, 64, 96, 100]);
  });

  it('the rows are the run’s own means and errors; the crossings are where the sign against the reference flips', async () => {
    const { runningRows, referenceCrossings, describeRunning } =
      await import('../../../src/scenes/area-light/view/describe');
    const { run, m, fr } = described();
    const rows = runningRows(run, fr.k);
    for (const [k, mean, se] of rows) {
      expect(mean).toBe(run.mean[k! - 1]);
      expect(Object.is(se, run.stderr[k! - 1])).toBe(true);
    }
    const ks = rows.map((r) => r[0]!);
    const ref = targetValue(m);
    const cross = referenceCrossings(run, ks, ref);
    for (const c of cross) {
      const i = ks.indexOf(c);
      expect(i).toBeGreaterThan(0);
      expect(Math.sign(run.mean[c - 1]! - ref)).not.toBe(Math.sign(run.mean[ks[i - 1]! - 1]! - ref));
    }
    const text = describeRunning(run, fr.k, ref);
    expect(text).toContain(`1024 of 1024 samples`);
    expect(text).toContain(`reference ${formatNumber(ref, 4)}`);
    const times = [
      'never crosses the reference',
      'crosses the reference once',
      'crosses the reference twice',
    ];
    expect(text).toContain(times[cross.length] ?? `crosses the reference ${cross.length} times`);
    // a paused, earlier frame says other numbers
    expect(describeRunning(run, 40, ref)).not.toBe(text);
    expect(describeRunning(run, 0, ref)).toContain('no samples yet');
  });

  it('an exact estimator (a light facing away: every term 0) says so', async () => {
    const { describeRunning } = await import('../../../src/scenes/area-light/view/describe');
    const { run, fr, m } = described({ tilt: 180 });
    const text = describeRunning(run, fr.k, targetValue(m));
    expect(text).toContain('exactly at the reference 0');
    expect(text).not.toMatch(/NaN|Infinity/);
  });
});
