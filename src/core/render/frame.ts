/**
 * An orthonormal frame around a unit vector, to carry directions sampled about +z (the hemisphere
 * and lobe samplers of core/sampling) onto a surface normal or a mirror direction.
 *
 * The branch-free construction of Duff, Burgess, Christensen, Hery, Kensler, Liani and Villemin,
 * "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017 (listing 3; pbrt-v4
 * `CoordinateSystem`): for unit n, with s = sign(n_z), a = −1/(s + n_z), b = n_x n_y a,
 * t = (1 + s n_x² a, s b, −s n_x) and b′ = (b, s + n_y² a, −n_y) complete n to a right-handed
 * basis (t, b′, n) without a division by a small number anywhere on the sphere.
 */

/** A right-handed orthonormal basis (t, b, n), each a unit vector; the local z axis is n. */
export interface Frame {
  tx: number;
  ty: number;
  tz: number;
  bx: number;
  by: number;
  bz: number;
  nx: number;
  ny: number;
  nz: number;
}

/** An empty frame to fill with {@link frameAround} (caller-owned, reused per vertex). */
export function newFrame(): Frame {
  return { tx: 1, ty: 0, tz: 0, bx: 0, by: 1, bz: 0, nx: 0, ny: 0, nz: 1 };
}

/** Fill `f` with a basis whose third axis is the unit vector (nx, ny, nz); returns f. */
export function frameAround(nx: number, ny: number, nz: number, f: Frame): Frame {
  const s = nz >= 0 ? 1 : -1;
  const a = -1 / (s + nz);
  const b = nx * ny * a;
  f.tx = 1 + s * nx * nx * a;
  f.ty = s * b;
  f.tz = -s * nx;
  f.bx = b;
  f.by = s + ny * ny * a;
  f.bz = -ny;
  f.nx = nx;
  f.ny = ny;
  f.nz = nz;
  return f;
}

/**
 * Carry the local direction (x, y, z) (z along the frame's n) into world space: writes
 * x t + y b + z n into out[o..o+2].
 */
export function toWorld(
  f: Frame,
  x: number,
  y: number,
  z: number,
  out: Float64Array | number[],
  o = 0,
): void {
  out[o] = x * f.tx + y * f.bx + z * f.nx;
  out[o + 1] = x * f.ty + y * f.by + z * f.ny;
  out[o + 2] = x * f.tz + y * f.bz + z * f.nz;
}
