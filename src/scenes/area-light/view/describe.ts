/**
 * The sentences a sighted student reads from the figures of #/area-light, with the live numbers:
 * the main figure (the light, its tilt, the patch, the samples and the running estimate) and the
 * running-estimate plot. Pure functions of the model, the patch and the animation's frame, so the
 * description changes whenever what is drawn changes (a tilt, a patch, a new sample, a pause).
 */
import type { LightStrategy } from '../../../core/lights';
import { formatNumber } from '../../../ui/Readout';
import { summarizeSeries } from '../../../ui/summary';
import type { AnimationFrame, SampleRun } from '../animation';
import type { AreaLightModel } from '../model';
import type { PatchModel } from '../patch';
import { STRATEGY_LABEL } from '../strategies';

/** A number for the description: `d` significant digits, like the readouts, with a real minus sign. */
const num = (x: number, d = 4) => formatNumber(x, d).replace(/^-/, '−');

/** The angle between the light's plane and the floor's (0° … 90°) for a tilt in degrees. */
export function tiltFromFloor(tilt: number): number {
  const a = Math.abs(tilt) % 180;
  return a > 90 ? 180 - a : a;
}

/** Whether a light tilted by `tilt` degrees is parallel to the floor. */
export const isParallel = (tilt: number) => ((tilt % 180) + 180) % 180 === 0;

/** Degrees of the angle whose cosine is c (clamped to [−1, 1]). */
const degOf = (c: number) => (Math.acos(Math.min(1, Math.max(-1, c))) * 180) / Math.PI;

/** Where the light's centre is seen from p: r, cos θ at the point (normal +z) and cos θₗ at the light. */
export function centreView(m: AreaLightModel): { r: number; cosTheta: number; cosThetaL: number } {
  const c = m.light.center;
  const n = m.light.normal;
  const dx = c[0] - m.p[0],
    dy = c[1] - m.p[1],
    dz = c[2] - m.p[2];
  const r = Math.hypot(dx, dy, dz);
  if (!(r > 0)) return { r, cosTheta: NaN, cosThetaL: NaN };
  return { r, cosTheta: dz / r, cosThetaL: -(dx * n[0] + dy * n[1] + dz * n[2]) / r };
}

/** Samples among the first k whose term is zero (below the horizon, blocked, facing away or missing). */
export function wastedSamples(run: SampleRun, k: number): number {
  let w = 0;
  const end = Math.min(k, run.count);
  for (let i = 0; i < end; i++) if (!(run.terms[i] > 0)) w++; // as the figure colours them
  return w;
}

/** The light and the patch (what the figure shows before any sample). */
export function describeSetup(m: AreaLightModel, patch: PatchModel): string {
  const parallel = isParallel(m.tilt);
  const away = m.facing ? '' : ', facing away from the point';
  const orient = parallel
    ? `parallel to the floor${away}`
    : `tilted ${num(tiltFromFloor(m.tilt), 3)}° from the floor (tilt ${num(m.tilt, 3)}° about its x axis)${away}`;
  const cv = centreView(m);
  const cosines = parallel
    ? `cos θ = cos θₗ = ${num(cv.cosTheta, 3)}`
    : `cos θ = ${num(cv.cosTheta, 3)} at the point, cos θₗ = ${num(cv.cosThetaL, 3)} at the light`;
  const [x, y, z] = m.lc;
  return (
    `A ${num(m.w, 3)} × ${num(m.h, 3)} light centred at (${num(x, 3)}, ${num(y, 3)}, ${num(z, 3)}), ${orient}. ` +
    `From the point its centre is ${num(cv.r, 3)} away: ${cosines}; it covers Ω = ${num(m.solidAngle)} sr. ` +
    `The orange patch, side ${num(patch.side, 3)}, turned ${num(degOf(patch.cosThetaL), 3)}° from facing the point, ` +
    `${num(patch.r, 3)} away: cos θₗ = ${num(patch.cosThetaL, 3)}, so dA⊥ = ${num(patch.cosThetaL, 3)} dA, ` +
    `and dω = dA cos θₗ / r² = ${num(patch.approx)} sr (exactly ${num(patch.exact)} sr).`
  );
}

/** The animation at one frame: the samples of a strategy and the value they converge to. */
export interface SamplesAt {
  strategy: LightStrategy;
  run: SampleRun;
  frame: AnimationFrame;
  target: number;
  /** Asked to predict first: the estimate is not given away. */
  hidden?: boolean;
}

/** What the samples and the running estimate show at the frame. */
export function describeSamples({ strategy, run, frame, target, hidden = false }: SamplesAt): string {
  const { k } = frame;
  const name = `Samples of ${STRATEGY_LABEL[strategy]} sampling`;
  if (k === 0) return `${name}: none yet (0 of ${run.count}).`;
  const wasted = wastedSamples(run, k);
  const arrived = `${name}: ${k} of ${run.count} arrived, ${wasted} of them wasted (they contribute 0)`;
  if (hidden) return `${arrived}; the estimate is hidden until you reveal it.`;
  const est =
    k > 1
      ? `running estimate ${num(frame.estimate)} ± ${num(frame.stderr, 2)} (one standard error)`
      : `running estimate ${num(frame.estimate)} (no error yet from one sample)`;
  const ref = Number.isFinite(target) ? `; reference ${num(target)}` : '';
  return `${arrived}; ${est}${ref}.`;
}

/** The main figure's description: the setup, then the samples and the estimate. */
export function describeAreaLight(m: AreaLightModel, patch: PatchModel, at: SamplesAt): string {
  return `${describeSetup(m, patch)} ${describeSamples(at)}`;
}

/**
 * The sample counts at which the running estimate is read out (its table and its audio trace):
 * 1, 2, 4, … up to 32, then every 32nd, and always the last, k, itself. Ascending, all ≤ k.
 */
export function runningPoints(k: number): number[] {
  const out: number[] = [];
  for (let j = 1; j <= Math.min(k, 32); j *= 2) out.push(j);
  for (let j = 64; j <= k; j += 32) out.push(j);
  if (k > 0 && out[out.length - 1] !== k) out.push(k);
  return out;
}

/** The running estimate's rows at those counts: k, estimate, its standard error (NaN for one sample). */
export function runningRows(run: SampleRun, k: number): number[][] {
  return runningPoints(Math.min(k, run.count)).map((j) => [j, run.mean[j - 1], run.stderr[j - 1]]);
}

/**
 * Where the running estimate crosses the reference between two of the read-out counts (the count
 * after the crossing): the audio trace's ticks.
 */
export function referenceCrossings(run: SampleRun, ks: readonly number[], reference: number): number[] {
  if (!Number.isFinite(reference)) return [];
  const out: number[] = [];
  let prev = NaN;
  for (const j of ks) {
    const d = run.mean[j - 1] - reference;
    if (Number.isFinite(prev) && Number.isFinite(d) && ((prev < 0 && d >= 0) || (prev > 0 && d <= 0)))
      out.push(j);
    if (Number.isFinite(d) && d !== 0) prev = d;
  }
  return out;
}

/** The running-estimate plot in words: its trend and extremes, where it ends against the reference. */
export function describeRunning(run: SampleRun, k: number, reference: number): string {
  const kk = Math.min(k, run.count);
  if (kk === 0) return 'Running estimate against samples k: no samples yet.';
  const ks = runningPoints(kk);
  const series = summarizeSeries(
    ks,
    ks.map((j) => run.mean[j - 1]),
    { xLabel: 'k', yLabel: 'the running estimate', format: (v) => formatNumber(v, 4) },
  );
  const sentence = `Running estimate against samples k (log scale), ${kk} of ${run.count} samples: ${series}`;
  if (!Number.isFinite(reference)) return sentence;
  const se = run.stderr[kk - 1];
  const est = run.mean[kk - 1];
  const where =
    se > 0
      ? `${num(Math.abs(est - reference) / se, 2)} standard errors from`
      : est === reference
        ? 'exactly at'
        : `${num(Math.abs(est - reference))} (with no spread) from`;
  const band = Number.isFinite(se)
    ? ` The ±2σ band is ${num(4 * se, 2)} wide there; the estimate is ${where} the reference ${num(reference)} (dashed).`
    : ` The reference is ${num(reference)} (dashed).`;
  const crossings = referenceCrossings(run, ks, reference).length;
  const times =
    crossings === 0
      ? 'never crosses the reference'
      : `crosses the reference ${crossings === 1 ? 'once' : crossings === 2 ? 'twice' : `${crossings} times`}`;
  return `${sentence}${band} It ${times} among the counts read out.`;
}
