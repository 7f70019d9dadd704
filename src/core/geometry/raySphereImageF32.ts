/**
 * One ray per pixel against one sphere in float32, as a fragment shader does it, with a float64
 * reference for the same rays: the JavaScript side of the ray–sphere scene's GPU panel (the
 * shader computes the same per-pixel t; ./raySphereF32's tHitF32 is the emulation).
 *
 * The camera is a pinhole at the origin (camera-relative coordinates, as renderers use to keep
 * float32 positions small); the rays' directions are computed once in float64 and rounded to
 * float32, so the shader, the emulation and the reference all start from the same float32 rays.
 */
import { intersectRaySphereBatch, RAY_STRIDE, type Vec3 } from './raySphere';
import { tHitF32 } from './raySphereF32';
import { ulpF32 } from './ulp32';

/** A float32 scene for the image: the sphere's centre D radii away along `forward`. */
export interface SphereImageSetup {
  width: number;
  height: number;
  /** Pinhole at the origin; centre and radius are float32 values. */
  centre: Vec3;
  r: number;
  /** Unit float32 directions, xyz per pixel, row-major, top row first. */
  dirs: Float32Array;
}

/**
 * Directions of a pinhole camera at the origin looking at a sphere of radius 1 whose centre is
 * `dist` radii away along (1, 0.3, 0.2)/‖·‖; the sphere fills about 70% of the image's width.
 * Domain: dist > 1, width, height ≥ 1. Every direction is unit length in float64, then rounded.
 */
export function sphereImageSetup(dist: number, width: number, height: number): SphereImageSetup {
  const n = Math.hypot(1, 0.3, 0.2);
  const fw: Vec3 = [1 / n, 0.3 / n, 0.2 / n];
  const centre: Vec3 = [Math.fround(dist * fw[0]), Math.fround(dist * fw[1]), Math.fround(dist * fw[2])];
  // right = forward × z, up = right × forward (orthonormal)
  const rl = Math.hypot(fw[1], fw[0]);
  const right: Vec3 = [fw[1] / rl, -fw[0] / rl, 0];
  const up: Vec3 = [
    right[1] * fw[2] - right[2] * fw[1],
    right[2] * fw[0] - right[0] * fw[2],
    right[0] * fw[1] - right[1] * fw[0],
  ];
  const halfWidth = 1.45 / Math.sqrt(Math.max(1e-12, dist * dist - 1));
  const halfHeight = (halfWidth * height) / width;
  const dirs = new Float32Array(width * height * 3);
  for (let y = 0, j = 0; y < height; y++) {
    const sy = halfHeight * (1 - (2 * (y + 0.5)) / height);
    for (let x = 0; x < width; x++, j += 3) {
      const sx = halfWidth * ((2 * (x + 0.5)) / width - 1);
      const dx = fw[0] + sx * right[0] + sy * up[0];
      const dy = fw[1] + sx * right[1] + sy * up[1];
      const dz = fw[2] + sx * right[2] + sy * up[2];
      const l = Math.sqrt(dx * dx + dy * dy + dz * dz);
      dirs[j] = dx / l;
      dirs[j + 1] = dy / l;
      dirs[j + 2] = dz / l;
    }
  }
  return { width, height, centre, r: 1, dirs };
}

/** t-hit per pixel (+∞ for none) of both methods in emulated float32. */
export interface SphereImageF32 {
  naive: Float32Array;
  stable: Float32Array;
}

/** The emulated float32 image (tHitF32 per pixel, both methods). Allocates the two outputs. */
export function renderSphereF32(s: SphereImageSetup): SphereImageF32 {
  const n = s.width * s.height;
  const naive = new Float32Array(n);
  const stable = new Float32Array(n);
  const [cx, cy, cz] = s.centre;
  const r2 = Math.fround(s.r * s.r);
  const d = s.dirs;
  for (let i = 0, j = 0; i < n; i++, j += 3) {
    naive[i] = tHitF32(0, 0, 0, d[j], d[j + 1], d[j + 2], cx, cy, cz, r2, false);
    stable[i] = tHitF32(0, 0, 0, d[j], d[j + 1], d[j + 2], cx, cy, cz, r2, true);
  }
  return { naive, stable };
}

/**
 * The float64 reference t-hit per pixel (robust form in double, whose Δ is good to ~u·D/r ≈ 10⁻¹²
 * here: far beyond float32), for the same float32 rays and sphere. +∞ for none.
 */
export function renderSphereReference(s: SphereImageSetup): Float64Array {
  const n = s.width * s.height;
  const rays = new Float64Array(n * RAY_STRIDE);
  for (let i = 0; i < n; i++) {
    rays[i * RAY_STRIDE + 3] = s.dirs[3 * i];
    rays[i * RAY_STRIDE + 4] = s.dirs[3 * i + 1];
    rays[i * RAY_STRIDE + 5] = s.dirs[3 * i + 2];
  }
  const out = new Float64Array(n);
  intersectRaySphereBatch(rays, n, s.centre[0], s.centre[1], s.centre[2], s.r, 'stable', out);
  return out;
}

/** Pixels whose hit/miss differs between two t images (+∞ = none). */
export function countHitMismatch(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let k = 0;
  for (let i = 0; i < a.length; i++) if ((a[i] === Infinity) !== (b[i] === Infinity)) k++;
  return k;
}

/**
 * Per-pixel error of a float32 t image against a reference, in float32 ulps of the reference
 * (into `out`): 0 where both miss, +∞ where exactly one hits.
 */
export function ulpErrors(t: ArrayLike<number>, ref: ArrayLike<number>, out: Float32Array): Float32Array {
  for (let i = 0; i < t.length; i++) {
    const a = t[i];
    const b = ref[i];
    if (a === Infinity || b === Infinity) out[i] = a === b ? 0 : Infinity;
    else out[i] = Math.abs(a - b) / ulpF32(b);
  }
  return out;
}

/**
 * Pixels where two float32 t images differ by more than `maxUlps` float32 ulps (or where one hits
 * and the other does not): the shader against the emulation.
 */
export function countUlpMismatch(a: ArrayLike<number>, b: ArrayLike<number>, maxUlps: number): number {
  let k = 0;
  for (let i = 0; i < a.length; i++) {
    const x = a[i];
    const y = b[i];
    if (x === y) continue;
    if (x === Infinity || y === Infinity) k++;
    else if (Math.abs(x - y) > maxUlps * ulpF32(y)) k++;
  }
  return k;
}
