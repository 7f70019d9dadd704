/** The rendered image of a distant sphere, one ray per pixel, by both methods, and its shading. */
import { fillPinholeRays, intersectRaySphereBatch, NO_HIT, RAY_STRIDE } from '../../core/geometry';
import { cross, norm, scale, type Vec3 } from '../../core/vec3';

export interface DistantImage {
  width: number;
  height: number;
  /** t-hit per pixel for each method (NO_HIT = ∞ for none). */
  naive: Float64Array;
  stable: Float64Array;
  /** Pixel counts: hits by each method, and pixels where the two disagree. */
  naiveHits: number;
  stableHits: number;
  disagree: number;
  /** Milliseconds spent filling rays and running both batched kernels. */
  ms: number;
}

/** The camera and sphere of the distant-sphere image: the sphere's centre is `dist` radii away. */
export function distantSetup(dist: number): {
  eye: Vec3;
  centre: Vec3;
  r: number;
  forward: Vec3;
  right: Vec3;
  up: Vec3;
  halfWidth: number;
} {
  const eye: Vec3 = [0.1, -0.2, 0.05];
  const dir = [1, 0.3, 0.2];
  const n = Math.hypot(dir[0], dir[1], dir[2]);
  const forward: Vec3 = [dir[0] / n, dir[1] / n, dir[2] / n];
  const centre: Vec3 = [eye[0] + dist * forward[0], eye[1] + dist * forward[1], eye[2] + dist * forward[2]];
  const rightRaw = cross(forward, [0, 0, 1]);
  const right = scale(rightRaw, 1 / norm(rightRaw));
  const up = cross(right, forward);
  // frame the sphere: it fills ~70% of the width
  const halfWidth = 1.45 / Math.sqrt(dist * dist - 1);
  return { eye, centre, r: 1, forward, right, up, halfWidth };
}

/** Scratch buffers reused between renders (caller-owned in spirit: one image size at a time). */
let scratchRays: Float64Array | null = null;

/**
 * Render the distant sphere with both methods into fresh t buffers. `now` is a clock (injected so
 * the model stays pure of the DOM; pass performance.now in the view).
 */
export function renderDistant(
  dist: number,
  width: number,
  height: number,
  now: () => number = () => 0,
): DistantImage {
  const n = width * height;
  if (!scratchRays || scratchRays.length < n * RAY_STRIDE) scratchRays = new Float64Array(n * RAY_STRIDE);
  const s = distantSetup(dist);
  const naive = new Float64Array(n);
  const stable = new Float64Array(n);
  const t0 = now();
  fillPinholeRays(scratchRays, width, height, s.eye, s.forward, s.right, s.up, s.halfWidth);
  const naiveHits = intersectRaySphereBatch(
    scratchRays,
    n,
    s.centre[0],
    s.centre[1],
    s.centre[2],
    s.r,
    'naive',
    naive,
  );
  const stableHits = intersectRaySphereBatch(
    scratchRays,
    n,
    s.centre[0],
    s.centre[1],
    s.centre[2],
    s.r,
    'stable',
    stable,
  );
  const ms = now() - t0;
  let disagree = 0;
  for (let i = 0; i < n; i++) if ((naive[i] === NO_HIT) !== (stable[i] === NO_HIT)) disagree++;
  return { width, height, naive, stable, naiveHits, stableHits, disagree, ms };
}

/**
 * Shade a t buffer into RGBA pixels (caller-owned `out`, length 4·n): hits get a Lambert-ish shade
 * from the depth offset relative to the nearest hit (front of the sphere brighter), misses the
 * background; `hole` pixels (hit by `other` but not by this method) are marked in `holeRGB`.
 */
export function shadeImage(
  t: Float64Array,
  other: Float64Array | null,
  r: number,
  out: Uint8ClampedArray,
  bg: Vec3,
  fg: Vec3,
  holeRGB: Vec3,
): void {
  let tMin = Infinity;
  for (let i = 0; i < t.length; i++) if (t[i] < tMin) tMin = t[i];
  for (let i = 0, j = 0; i < t.length; i++, j += 4) {
    const ti = t[i];
    let col: Vec3;
    if (ti === NO_HIT) col = other && other[i] !== NO_HIT ? holeRGB : bg;
    else {
      // depth δ behind the nearest point: cos θ = 1 − δ/r between the normal and the view ray
      const cosTheta = Math.min(1, Math.max(0, 1 - (ti - tMin) / r));
      const shade = 0.3 + 0.7 * cosTheta;
      col = [fg[0] * shade, fg[1] * shade, fg[2] * shade];
    }
    out[j] = col[0];
    out[j + 1] = col[1];
    out[j + 2] = col[2];
    out[j + 3] = 255;
  }
}
