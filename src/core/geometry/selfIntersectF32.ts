/**
 * Self-intersection ("shadow acne") in float32: a shadow ray leaves the float32 hit point of a
 * camera ray toward a light, and is tested against the same sphere in float32. A sphere is
 * convex, so a point on its lit side (n·L > 0) can never be shadowed by it: every hit that the
 * shadow ray reports there is the surface intersecting itself, because rounding put the start
 * point a little inside (or the roots' own rounding gives t ≈ 0 a positive sign).
 *
 * The usual cure moves the start point off the surface along the normal by ε. How big ε must be
 * follows from the error of the hit point: its coordinates are float32 numbers of size about D
 * (the distance from the origin), spaced u₃₂·D apart, so ε ≈ a few u₃₂·D; an ε below half a
 * coordinate's ulp does not even change the rounded start point. pbrt (Pharr, Jakob & Humphreys,
 * Physically Based Rendering, 4th ed., §6.8 "Managing Rounding Error") bounds that error per
 * coordinate with γₙ = n u/(1 − n u) terms and offsets by the bound projected on the normal,
 * Σ |nᵢ| δᵢ; {@link pbrtOffsetF32} follows it for this sphere.
 */
import { tHitF32 } from './raySphereF32';
import type { SphereImageSetup } from './raySphereImageF32';
import { U32 } from './ulp32';

const fr = Math.fround;

/** γₙ = n u₃₂ / (1 − n u₃₂) (pbrt's bound on n roundings, float32). */
export function gammaF32(n: number): number {
  return (n * U32) / (1 - n * U32);
}

/** The float32 hit point of a camera ray from the origin: p = t d, each coordinate rounded. */
function hitPoint(t: number, dx: number, dy: number, dz: number): [number, number, number] {
  return [fr(t * dx), fr(t * dy), fr(t * dz)];
}

/**
 * pbrt's offset for a float32 hit point p of the sphere (centre c, radius r): reproject p onto
 * the sphere in object space (p − c scaled by r / |p − c|), bound the object-space error by
 * γ₅|pₒ| per coordinate, carry it through the translation back to world space (error
 * (1 + γ₃)δ + γ₃(|pₒ| + |c|) per coordinate, as pbrt's Transform of a Point3fi), and offset by
 * Σ |nᵢ| δᵢ along the normal. Returns the start point (float32) and the offset distance.
 */
export function pbrtOffsetF32(
  p: readonly [number, number, number],
  c: readonly [number, number, number],
  r: number,
): { origin: [number, number, number]; offset: number; normal: [number, number, number] } {
  const ox = fr(p[0] - c[0]);
  const oy = fr(p[1] - c[1]);
  const oz = fr(p[2] - c[2]);
  const len = fr(Math.sqrt(fr(fr(fr(ox * ox) + fr(oy * oy)) + fr(oz * oz))));
  const s = fr(r / len);
  const po = [fr(ox * s), fr(oy * s), fr(oz * s)];
  const n = [fr(po[0] / r), fr(po[1] / r), fr(po[2] / r)] as [number, number, number];
  const g3 = gammaF32(3);
  const g5 = gammaF32(5);
  let offset = 0;
  const origin: [number, number, number] = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    const delta = (1 + g3) * g5 * Math.abs(po[i]) + g3 * (Math.abs(po[i]) + Math.abs(c[i]));
    offset += Math.abs(n[i]) * delta;
  }
  for (let i = 0; i < 3; i++) {
    const w = fr(po[i] + c[i]);
    const moved = fr(w + fr(offset * n[i]));
    // pbrt then rounds the moved point one float further away from the surface
    origin[i] = n[i] > 0 ? nextFloat32(moved, 1) : n[i] < 0 ? nextFloat32(moved, -1) : moved;
  }
  return { origin, offset, normal: n };
}

const b32 = new Float32Array(1);
const i32 = new Int32Array(b32.buffer);

/** The next float32 above (dir = 1) or below (dir = −1) x (x a finite float32). */
function nextFloat32(x: number, dir: 1 | -1): number {
  if (x === 0) return dir * 2 ** -149;
  b32[0] = x;
  i32[0] += x > 0 === dir > 0 ? 1 : -1;
  return b32[0];
}

/** Counts of one shadow pass over an image. */
export interface AcneResult {
  /** Pixels whose camera ray hits the sphere on its lit side (n·L > 0). */
  lit: number;
  /** Of those, pixels whose shadow ray hit the sphere itself (acne). */
  selfHits: number;
  /** Per pixel: 0 background, 1 unlit side, 2 lit and clean, 3 lit with acne. */
  kind: Uint8Array;
  /** The largest pbrt offset over the lit pixels (only with `offset: 'pbrt'`), in units of r. */
  maxPbrtOffset: number;
}

/**
 * Cast a shadow ray toward the directional light `light` (unit, float32) from every float32 hit
 * point of the image (robust float32 test), started at p + ε n (`offset` a number ε, in units
 * of r) or at pbrt's offset point (`offset: 'pbrt'`), and tested against the same sphere in
 * float32 (robust form). Counts the lit pixels whose shadow ray hits the sphere (t ≥ 0).
 */
export function shadowAcneF32(
  s: SphereImageSetup,
  light: readonly [number, number, number],
  offset: number | 'pbrt',
  stride = 1,
): AcneResult {
  const [cx, cy, cz] = s.centre;
  const r = s.r;
  const r2 = fr(r * r);
  const [lx, ly, lz] = [fr(light[0]), fr(light[1]), fr(light[2])];
  const n = s.width * s.height;
  const kind = new Uint8Array(n);
  const eps = offset === 'pbrt' ? 0 : fr(offset);
  let lit = 0;
  let selfHits = 0;
  let maxPbrt = 0;
  for (let i = 0; i < n; i += stride) {
    const dx = s.dirs[3 * i];
    const dy = s.dirs[3 * i + 1];
    const dz = s.dirs[3 * i + 2];
    const t = tHitF32(0, 0, 0, dx, dy, dz, cx, cy, cz, r2, true);
    if (t === Infinity) continue;
    const p = hitPoint(t, dx, dy, dz);
    let o: [number, number, number];
    let nx: number;
    let ny: number;
    let nz: number;
    if (offset === 'pbrt') {
      const q = pbrtOffsetF32(p, s.centre, r);
      o = q.origin;
      [nx, ny, nz] = q.normal;
      if (q.offset > maxPbrt) maxPbrt = q.offset;
    } else {
      nx = fr(fr(p[0] - cx) / r);
      ny = fr(fr(p[1] - cy) / r);
      nz = fr(fr(p[2] - cz) / r);
      o = [fr(p[0] + fr(eps * nx)), fr(p[1] + fr(eps * ny)), fr(p[2] + fr(eps * nz))];
    }
    if (!(nx * lx + ny * ly + nz * lz > 0)) {
      kind[i] = 1;
      continue;
    }
    lit++;
    const ts = tHitF32(o[0], o[1], o[2], lx, ly, lz, cx, cy, cz, r2, true);
    if (ts !== Infinity) {
      selfHits++;
      kind[i] = 3;
    } else kind[i] = 2;
  }
  return { lit, selfHits, kind, maxPbrtOffset: maxPbrt };
}

/** ε values (in units of r) of the acne sweep: 0 and 10⁻⁸ … 10⁻¹ in steps of 10^¼. */
export const ACNE_EPSILONS: readonly number[] = [
  0,
  ...Array.from({ length: 29 }, (_, i) => 10 ** (-8 + i / 4)),
];

/** One distance of the acne sweep: the fraction of self-hits per ε, and the ε that first has none. */
export interface AcneSweep {
  dist: number;
  eps: number[];
  fraction: number[];
  /** The smallest swept ε > 0 from which on no lit pixel self-intersects (null if none does). */
  epsNeeded: number | null;
  /** The pbrt offset's largest value over the lit pixels, and its self-hits (expected 0). */
  pbrtOffset: number;
  pbrtSelfHits: number;
}

/** The acne sweep for one image setup (every `stride`-th pixel). */
export function acneSweepF32(
  s: SphereImageSetup,
  dist: number,
  light: readonly [number, number, number],
  stride = 1,
  eps: readonly number[] = ACNE_EPSILONS,
): AcneSweep {
  const fraction = eps.map((e) => {
    const a = shadowAcneF32(s, light, e, stride);
    return a.lit ? a.selfHits / a.lit : 0;
  });
  let epsNeeded: number | null = null;
  for (let i = eps.length - 1; i >= 0 && fraction[i] === 0; i--) if (eps[i] > 0) epsNeeded = eps[i];
  const pb = shadowAcneF32(s, light, 'pbrt', stride);
  return {
    dist,
    eps: [...eps],
    fraction,
    epsNeeded,
    pbrtOffset: pb.maxPbrtOffset,
    pbrtSelfHits: pb.selfHits,
  };
}
