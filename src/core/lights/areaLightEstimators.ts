/**
 * Monte Carlo estimators of the radiance L_o leaving a Lambertian floor point p (normal +z,
 * albedo ρ, BRDF f = ρ/π) lit by a one-sided rectangular emitter of radiance L, optionally
 * shadowed by a rectangular occluder. Three strategies, each a batched kernel that writes one
 * estimator term Yᵢ = f L V cos θ / p(ωᵢ) per sample into a caller-owned buffer:
 *
 * - 'area' (exam key Q6(c)): x uniform on the light, p_A = 1/|A|,
 *   Yᵢ = |A| f L V cos θ cos θ_l / r²  (the rendering equation over area, Q6(b)).
 * - 'solid-angle': ω uniform over the light's spherical rectangle (Ureña et al. 2013), p = 1/Ω,
 *   Yᵢ = Ω f L V cos θ.
 * - 'cosine': ω ~ cos θ/π over the hemisphere, Yᵢ = ρ L V if the ray hits the emitting side, else 0.
 *
 * All three are unbiased for the same integral, so their means agree with the analytic reference
 * ({@link lambertianFloorRadiance}) within a few standard errors. Statistics by Welford's update
 * (core/estimators `Welford`, mergeable).
 * Source: pbrt-v4 sections 13.2–13.4 (direct lighting, light sampling vs BSDF sampling), the exam key.
 */
import { Rng } from '../random';
import { sampleCosineHemisphere } from '../sampling/cosineHemisphere';
import { Welford } from '../estimators/welford';
import { ConvergenceSeries } from '../estimators/convergence';
import { intersectRect, type RectLight } from './rectLight';
import {
  makeSphericalRect,
  sampleSphericalRectangle,
  sphericalRectanglePdf,
  type SphericalRect,
} from './sphericalRectangle';
import { areaToSolidAnglePdf, rectAreaPdf, sampleRectArea } from './areaSampling';

/** The three sampling strategies. */
export type LightStrategy = 'area' | 'solid-angle' | 'cosine';

/** Everything an estimator needs: the light, an optional occluder, the shading point, L, ρ. */
export interface AreaLightSetup {
  light: RectLight;
  occluder: RectLight | null;
  px: number;
  py: number;
  pz: number;
  /** Emitted radiance L ≥ 0. */
  L: number;
  /** Floor albedo ρ ∈ [0, 1]. */
  rho: number;
}

/** Result of an estimate: the mean of the terms and its standard error s/√N. */
export interface AreaLightEstimate {
  estimate: number;
  stderr: number;
  n: number;
  stats: Welford;
}

const INV_PI = 1 / Math.PI;
/** A shadow ray hits the occluder only strictly before the light: t < 1 − this (t in units of x − p). */
const SHADOW_EPS = 1e-9;

/**
 * Batched estimator kernel. Reads 2 uniforms per sample from u (u[2i], u[2i+1] ∈ [0, 1)), writes
 * the term Yᵢ into terms[i] for i ∈ [0, n), and, if `points` is given, the sample into
 * points[3i..3i+2]: the point on the light for 'area' and 'solid-angle', the unit direction for
 * 'cosine'. Caller-owned buffers; no allocation per sample. `sph` may pass a prebuilt
 * {@link SphericalRect} for p (else it is built once per call). Measure of every term: radiance.
 */
export function areaLightTerms(
  setup: AreaLightSetup,
  strategy: LightStrategy,
  u: Float64Array,
  n: number,
  terms: Float64Array,
  points?: Float64Array,
  sph?: SphericalRect,
): void {
  const { light, occluder, px, py, pz, L, rho } = setup;
  const nl = light.normal;
  if (!(light.area > 0) || !(L > 0) || !(rho > 0)) {
    for (let i = 0; i < n; i++) {
      terms[i] = 0;
      if (points) {
        if (strategy === 'cosine') sampleCosineHemisphere(u[2 * i], u[2 * i + 1], points, 3 * i);
        else {
          points[3 * i] = light.center[0];
          points[3 * i + 1] = light.center[1];
          points[3 * i + 2] = light.center[2];
        }
      }
    }
    return;
  }
  if (strategy === 'cosine') {
    // The sample goes straight into `points` when it is given, else into a scratch buffer.
    const buf = points ?? scratchBuf;
    for (let i = 0; i < n; i++) {
      const o = points ? 3 * i : 0;
      sampleCosineHemisphere(u[2 * i], u[2 * i + 1], buf, o);
      const dx = buf[o],
        dy = buf[o + 1],
        dz = buf[o + 2];
      let y = 0;
      // Front face only: the ray must travel against the emitting normal.
      if (dz > 0 && dx * nl[0] + dy * nl[1] + dz * nl[2] < 0) {
        const t = intersectRect(light, px, py, pz, dx, dy, dz, 0);
        if (t < Infinity) {
          y = rho * L;
          if (occluder && intersectRect(occluder, px, py, pz, dx, dy, dz, 0) < t) y = 0;
        }
      }
      terms[i] = y;
    }
    return;
  }
  // 'area' and 'solid-angle' share one loop: a point x on the light from a sampler, its density
  // per unit solid angle at p from the paired pdf, term = f L V cos θ / p_ω.
  const pair =
    strategy === 'area'
      ? new AreaPoints(light)
      : new SphericalRectPoints(sph ?? makeSphericalRect(light, px, py, pz));
  lightPointTerms(pair, setup, u, n, terms, points);
}

/**
 * A strategy that samples a point x on the light, as a sampler/pdf pair: `sample` writes x for
 * (u1, u2) into out[o..o+2]; `pdfW` is the density of that x per unit SOLID ANGLE at the shading
 * point, given r² = |x − p|² and cos θ_l (both computed once by the caller). One class per
 * strategy: the call sites in {@link lightPointTerms} see two classes, which V8 inlines (measured
 * against the two hand-split loops this replaced, interleaved: no slower; `npm run bench`).
 */
interface LightPointSampler {
  sample(u1: number, u2: number, out: Float64Array, o: number): void;
  pdfW(x: number, y: number, z: number, r2: number, cosThetaL: number): number;
}

/**
 * Uniform by area (the key's Q6(c)): the tested triple of ./areaSampling. p_A = 1/|A| is constant
 * on the rectangle, so it is evaluated once (at the centre); every sample lies on the rectangle by
 * construction. Per sample, p_A is converted to solid angle with Q6(a)'s Jacobian,
 * p_ω = p_A r² / cos θ_l, so term = f L V cos θ / p_ω = f L V cos θ cos θ_l / (p_A r²).
 */
class AreaPoints implements LightPointSampler {
  readonly light: RectLight;
  readonly pA: number;
  constructor(light: RectLight) {
    this.light = light;
    this.pA = rectAreaPdf(light, light.center[0], light.center[1], light.center[2]);
  }
  sample(u1: number, u2: number, out: Float64Array, o: number): void {
    sampleRectArea(this.light, u1, u2, out, o);
  }
  pdfW(_x: number, _y: number, _z: number, r2: number, cosThetaL: number): number {
    return areaToSolidAnglePdf(this.pA, r2, cosThetaL);
  }
}

/** Uniform by solid angle over the spherical rectangle: sampleSphericalRectangle + sphericalRectanglePdf. */
class SphericalRectPoints implements LightPointSampler {
  readonly q: SphericalRect;
  constructor(q: SphericalRect) {
    this.q = q;
  }
  sample(u1: number, u2: number, out: Float64Array, o: number): void {
    sampleSphericalRectangle(this.q, u1, u2, out, o);
  }
  pdfW(x: number, y: number, z: number): number {
    return sphericalRectanglePdf(this.q, x, y, z);
  }
}

/** The per-sample loop of the light-point strategies (see {@link areaLightTerms} for the buffers). */
function lightPointTerms(
  pair: LightPointSampler,
  setup: AreaLightSetup,
  u: Float64Array,
  n: number,
  terms: Float64Array,
  points: Float64Array | undefined,
): void {
  const { light, occluder, px, py, pz, L, rho } = setup;
  const nl = light.normal;
  const fL = rho * INV_PI * L;
  const buf = points ?? scratchBuf; // as in the cosine loop: samples straight into `points`
  for (let i = 0; i < n; i++) {
    const o = points ? 3 * i : 0;
    pair.sample(u[2 * i], u[2 * i + 1], buf, o);
    const x = buf[o],
      yy = buf[o + 1],
      z = buf[o + 2];
    const dx = x - px,
      dy = yy - py,
      dz = z - pz;
    const r2 = dx * dx + dy * dy + dz * dz;
    const r = Math.sqrt(r2);
    let term = 0;
    if (r > 0) {
      const cosT = dz / r;
      const cosL = -(dx * nl[0] + dy * nl[1] + dz * nl[2]) / r;
      if (
        cosT > 0 &&
        cosL > 0 &&
        !(occluder && intersectRect(occluder, px, py, pz, dx, dy, dz, 0) < 1 - SHADOW_EPS)
      ) {
        const pw = pair.pdfW(x, yy, z, r2, cosL);
        term = pw > 0 ? (fL * cosT) / pw : 0;
      }
    }
    terms[i] = Number.isFinite(term) ? term : 0;
  }
}

const scratchBuf = new Float64Array(3);
const CHUNK = 4096;

/**
 * Estimate L_o with n samples of `strategy`, uniforms from `new Rng(seed, stream)`. Returns the
 * mean, its standard error and the (mergeable) Welford accumulator. Deterministic for a given
 * (setup, strategy, n, seed, stream). Domain: n ≥ 0 (n < 2 gives stderr NaN).
 */
export function estimateAreaLight(
  setup: AreaLightSetup,
  strategy: LightStrategy,
  n: number,
  seed: number,
  stream = 0,
): AreaLightEstimate {
  const stats = new Welford();
  forEachTermChunk(setup, strategy, n, seed, stream, (terms, k) => stats.addArray(terms, 0, k));
  return { estimate: stats.mean, stderr: stats.standardError(), n: stats.count, stats };
}

/**
 * Draw n estimator terms of `strategy` in chunks of at most CHUNK (uniforms from
 * `new Rng(seed, stream)`, buffers allocated once) and hand each chunk to `sink(terms, count)`.
 */
function forEachTermChunk(
  setup: AreaLightSetup,
  strategy: LightStrategy,
  n: number,
  seed: number,
  stream: number,
  sink: (terms: Float64Array, count: number) => void,
): void {
  const rng = new Rng(seed, stream);
  const m = Math.min(CHUNK, Math.max(1, n));
  const u = new Float64Array(2 * m);
  const terms = new Float64Array(m);
  const sph =
    strategy === 'solid-angle' ? makeSphericalRect(setup.light, setup.px, setup.py, setup.pz) : undefined;
  for (let done = 0; done < n;) {
    const k = Math.min(m, n - done);
    rng.fill(u, 0, 2 * k);
    areaLightTerms(setup, strategy, u, k, terms, undefined, sph);
    sink(terms, k);
    done += k;
  }
}

/**
 * Convergence series of one strategy: estimate, |error| against `exact` and standard error at the
 * given checkpoints (one pass, O(checkpoints) memory). Source: core/estimators ConvergenceSeries.
 */
export function areaLightConvergence(
  setup: AreaLightSetup,
  strategy: LightStrategy,
  checkpoints: ArrayLike<number>,
  exact: number,
  seed: number,
  stream = 0,
): ConvergenceSeries {
  const series = new ConvergenceSeries(checkpoints, exact);
  const nMax = checkpoints.length ? checkpoints[checkpoints.length - 1] : 0;
  forEachTermChunk(setup, strategy, nMax, seed, stream, (terms, k) => series.push(terms, 0, k));
  return series;
}
