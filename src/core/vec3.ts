/**
 * The one 3-vector of the project: a read-only tuple, with the handful of operations the core and
 * the scenes need (pure functions, no allocation beyond the returned tuple). World space is z-up
 * wherever a scene says so; this module does not care.
 *
 * A mutable `[number, number, number]` is assignable to {@link Vec3}, so callers that build
 * vectors in place may keep doing so and pass them here.
 */
export type Vec3 = readonly [number, number, number];

export const vec3 = (x: number, y: number, z: number): Vec3 => [x, y, z];

export const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];

export const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];

export const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];

/** a + s·b, the point a ray reaches at parameter s. */
export const addScaled = (a: Vec3, b: Vec3, s: number): Vec3 => [
  a[0] + s * b[0],
  a[1] + s * b[1],
  a[2] + s * b[2],
];

export const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

export const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** Euclidean length, by Math.hypot (no overflow or underflow in the squares). */
export const norm = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);

/** a / |a|; the zero vector (or one with a non-finite length) is returned as it is. */
export function normalize(a: Vec3): Vec3 {
  const l = norm(a);
  return l > 0 && Number.isFinite(l) ? [a[0] / l, a[1] / l, a[2] / l] : a;
}

/** |a − b|. */
export const distance = (a: Vec3, b: Vec3): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** Component-wise equality by Object.is (so −0 ≠ 0 and NaN = NaN): "was this value used as given?" */
export const sameVec = (a: readonly number[], b: readonly number[]): boolean =>
  a.length === b.length && a.every((x, i) => Object.is(x, b[i]));
