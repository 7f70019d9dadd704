/**
 * The progressive floor images of #/area-light: every pixel of a floor square estimated with each
 * strategy, pass by pass (the worker runs these), the analytic reference image, and which pass the
 * timeline shows. Pure functions of plain data.
 */
import {
  areaLightTerms,
  lambertianFloorRadiance,
  makeRectLight,
  makeSphericalRect,
  rectProjectedSolidAngleOccluded,
  type AreaLightSetup,
  type LightStrategy,
} from '../../core/lights';
import { Rng } from '../../core/random';
import { makeOccluder, type AreaLightModel, type LightInputs } from './model';
import { STRATEGIES } from './strategies';

/** Plain-data description of the scene for the worker (structured-clonable). */
export interface FloorJob extends LightInputs {
  occluder: boolean;
  /** Image side in pixels and the floor square it covers: [cx − half, cx + half]², z = p.z. */
  size: number;
  cx: number;
  cy: number;
  half: number;
  seed: number;
}

/** The floor square shown by the images: centred under the light's footprint, covering the point. */
export function floorJob(m: AreaLightModel, seed: number, size = 72): FloorJob {
  const cx = (m.p[0] + m.lc[0]) / 2,
    cy = (m.p[1] + m.lc[1]) / 2;
  const reach = Math.hypot(m.lc[0] - m.p[0], m.lc[1] - m.p[1]) / 2 + Math.max(m.w, m.h) / 2;
  const half = Math.min(1e6, Math.max(1.5, reach * 1.3, Math.abs(m.lc[2] - m.p[2]) * 0.9));
  const { lc, w, h, tilt, L, rho, p } = m;
  return {
    lc,
    w,
    h,
    tilt,
    L,
    rho,
    occluder: !!m.occluder,
    p,
    size,
    cx,
    cy,
    half,
    seed,
  };
}

/** World position of pixel (i, j) centre (row j from the top = +y side). */
export function pixelPoint(job: FloorJob, i: number, j: number): [number, number] {
  const s = (2 * job.half) / job.size;
  return [job.cx - job.half + (i + 0.5) * s, job.cy + job.half - (j + 0.5) * s];
}

/** The reference image: analytic L_o per pixel (unoccluded, or occluded where it has a closed form). */
export function referenceImage(job: FloorJob): Float32Array {
  const light = makeRectLight(job.lc, job.w, job.h, job.tilt);
  const img = new Float32Array(job.size * job.size);
  const z = job.p[2];
  for (let j = 0; j < job.size; j++)
    for (let i = 0; i < job.size; i++) {
      const [x, y] = pixelPoint(job, i, j);
      let v = lambertianFloorRadiance(light, x, y, z, job.L, job.rho);
      if (job.occluder) {
        const occ = makeOccluder(job.p, job.lc, job.w, job.h);
        const ps = rectProjectedSolidAngleOccluded(light, occ, x, y, z);
        v = Number.isFinite(ps) ? (job.rho / Math.PI) * job.L * ps : NaN;
      }
      img[j * job.size + i] = v;
    }
  return img;
}

/**
 * One progressive pass: add `spp` samples of `strategy` to every pixel's running sum (sum is
 * caller-owned, length size²). Pass index k selects the random stream, so passes are independent.
 */
export function floorPass(
  job: FloorJob,
  strategy: LightStrategy,
  spp: number,
  pass: number,
  sum: Float64Array,
): void {
  const light = makeRectLight(job.lc, job.w, job.h, job.tilt);
  const occ = job.occluder ? makeOccluder(job.p, job.lc, job.w, job.h) : null;
  const rng = new Rng(job.seed, 1000 + pass * 3 + STRATEGIES.indexOf(strategy));
  const u = new Float64Array(2 * spp);
  const terms = new Float64Array(spp);
  const setup: AreaLightSetup = { light, occluder: occ, px: 0, py: 0, pz: job.p[2], L: job.L, rho: job.rho };
  for (let j = 0; j < job.size; j++)
    for (let i = 0; i < job.size; i++) {
      const [x, y] = pixelPoint(job, i, j);
      setup.px = x;
      setup.py = y;
      rng.fill(u);
      const sph = strategy === 'solid-angle' ? makeSphericalRect(light, x, y, job.p[2]) : undefined;
      areaLightTerms(setup, strategy, u, spp, terms, undefined, sph);
      let s = 0;
      for (let k = 0; k < spp; k++) s += terms[k];
      sum[j * job.size + i] += s;
    }
}

/** RMSE of an image (sum / spp) against the reference, over pixels where the reference is finite. */
export function imageRmse(sum: Float64Array, spp: number, ref: Float32Array): number {
  let s = 0,
    n = 0;
  for (let k = 0; k < ref.length; k++) {
    const r = ref[k];
    if (!Number.isFinite(r)) continue;
    const d = sum[k] / spp - r;
    s += d * d;
    n++;
  }
  return n ? Math.sqrt(s / n) : NaN;
}

/** Samples per pixel added by each progressive pass of the floor images: 1, 1, 2, 4, … (the total doubles). */
export const PASS_SPP = [1, 1, 2, 4, 8, 16, 32] as const;
/** Total samples per pixel after each pass: 1, 2, 4, …, 64. */
export const PASS_TOTAL: readonly number[] = PASS_SPP.map((_, i) =>
  PASS_SPP.slice(0, i + 1).reduce((a, b) => a + b, 0),
);

/**
 * The floor images refine in step with the timeline: at position t of max, show the pass whose
 * samples per pixel are the largest not above the same fraction of the full 64 (at least pass 0).
 */
export function floorPassAt(t: number, max: number): number {
  const total = PASS_TOTAL[PASS_TOTAL.length - 1];
  const want = max > 0 ? (total * Math.max(0, Math.min(max, t))) / max : total;
  let k = 0;
  for (let i = 0; i < PASS_TOTAL.length; i++) if (PASS_TOTAL[i] <= want + 1e-9) k = i;
  return k;
}
