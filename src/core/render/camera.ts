/**
 * The pinhole camera of the render lab: an eye, the point it looks at and a vertical field of
 * view, over a width × height image. Pixel (i, j) is column i, row j counted from the top left;
 * the ray through a point (i + sx, j + sy) of the pixel (sx, sy ∈ [0, 1), the centre at ½, ½)
 * starts at the eye and has unit direction
 *
 *     d = normalize(f + x · tan(fov/2) · aspect · right + y · tan(fov/2) · up),
 *     x = 2 (i + sx)/width − 1,   y = 1 − 2 (j + sy)/height,
 *
 * with f the unit forward direction, right = f × z (world z is up) and up = right × f (when f is
 * vertical, right = x). Source: Shirley, "Ray Tracing in One Weekend" §11 (positionable camera);
 * pbrt-v4 §5.2 (the perspective projection).
 */
import type { Vec3 } from '../vec3';
import type { View } from './scene';

/** A camera ready to shoot rays (frame and scale precomputed). */
export interface Camera {
  eye: Vec3;
  width: number;
  height: number;
  fx: number;
  fy: number;
  fz: number;
  rx: number;
  ry: number;
  rz: number;
  ux: number;
  uy: number;
  uz: number;
  /** tan(fov/2) · aspect and tan(fov/2). */
  sx: number;
  sy: number;
}

/**
 * Build a camera. Domain: eye ≠ look (else the camera looks along +y), fov in (0°, 180°)
 * (clamped to [1°, 179°]), width, height ≥ 1.
 */
export function makeCamera(view: View, width: number, height: number): Camera {
  let fx = view.look[0] - view.eye[0],
    fy = view.look[1] - view.eye[1],
    fz = view.look[2] - view.eye[2];
  let l = Math.hypot(fx, fy, fz);
  if (!(l > 0) || !Number.isFinite(l)) {
    fx = 0;
    fy = 1;
    fz = 0;
    l = 1;
  }
  fx /= l;
  fy /= l;
  fz /= l;
  // right = f × (0, 0, 1) = (fy, −fx, 0): horizontal, so its z is 0
  let rx = fy,
    ry = -fx;
  const rl = Math.hypot(rx, ry);
  if (rl > 1e-12) {
    rx /= rl;
    ry /= rl;
  } else {
    rx = 1;
    ry = 0;
  }
  const ux = ry * fz,
    uy = -rx * fz,
    uz = rx * fy - ry * fx;
  const fov = Math.min(179, Math.max(1, Number.isFinite(view.fov) ? view.fov : 45));
  const t = Math.tan((fov * Math.PI) / 360);
  return {
    eye: view.eye,
    width,
    height,
    fx,
    fy,
    fz,
    rx,
    ry,
    rz: 0,
    ux,
    uy,
    uz,
    sx: (t * width) / height,
    sy: t,
  };
}

/**
 * The unit direction of the ray through the point (i + sx, j + sy) of the image (column i, row j
 * from the top left; sx = sy = 0.5 is the pixel's centre), written into out[o..o+2].
 */
export function cameraRay(
  cam: Camera,
  i: number,
  j: number,
  sx: number,
  sy: number,
  out: Float64Array | number[],
  o = 0,
): void {
  const x = ((2 * (i + sx)) / cam.width - 1) * cam.sx;
  const y = (1 - (2 * (j + sy)) / cam.height) * cam.sy;
  const dx = cam.fx + x * cam.rx + y * cam.ux,
    dy = cam.fy + x * cam.ry + y * cam.uy,
    dz = cam.fz + x * cam.rz + y * cam.uz;
  const l = Math.hypot(dx, dy, dz);
  out[o] = dx / l;
  out[o + 1] = dy / l;
  out[o + 2] = dz / l;
}
