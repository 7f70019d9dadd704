/**
 * The exact reference image, pixel by pixel where one exists: the radiance reaching the eye through
 * k × k evenly spread points of each pixel (the midpoints of a k × k grid over it), each by the
 * closed forms of ./reference (a light seen directly: its radiance; the background: the
 * environment's), averaged. That average is the midpoint rule for the pixel's box filter, the filter
 * the renderer's jittered samples integrate. A pixel gets NaN (no reference) when any of its points
 * has no closed form (a shadowed or glossy point, more than one bounce), or when its points do not
 * all see the same kind of object with different radiance (a silhouette, where the midpoint rule is
 * not accurate; the furnace's sphere against its background, both exactly 1, is exact).
 */
import { cameraRay, makeCamera } from './camera';
import { closestHit, newHit, type HitKind } from './intersect';
import { newVertex, shadeVertex } from './material';
import { exactRadiance } from './reference';
import type { RenderScene, View } from './scene';

/** Points per pixel side of the reference. */
export const REFERENCE_POINTS = 3;

export interface ReferenceImage {
  /** Row-major, width × height; NaN where the pixel has no exact reference. */
  values: Float64Array;
  /** How many pixels have one. */
  exact: number;
}

/** The exact radiance through the point (i + sx, j + sy) of the image, or null where there is none. */
function exactThrough(
  scene: RenderScene,
  view: View,
  cam: ReturnType<typeof makeCamera>,
  i: number,
  j: number,
  sx: number,
  sy: number,
  bounces: number,
  d: Float64Array,
  hit: ReturnType<typeof newHit>,
  v: ReturnType<typeof newVertex>,
): { kind: HitKind; value: number | null } {
  cameraRay(cam, i, j, sx, sy, d);
  const o = view.eye;
  const kind = closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, hit);
  if (kind === 'none') return { kind, value: scene.environment };
  if (kind === 'light') {
    const front = hit.nx * d[0] + hit.ny * d[1] + hit.nz * d[2] < 0;
    return { kind, value: front ? scene.lights[hit.index].L : 0 };
  }
  shadeVertex(scene, hit, d[0], d[1], d[2], v);
  return { kind, value: exactRadiance(scene, v, kind, bounces) };
}

export function referenceImage(
  scene: RenderScene,
  view: View,
  width: number,
  height: number,
  bounces: number,
  k = REFERENCE_POINTS,
): ReferenceImage {
  const cam = makeCamera(view, width, height);
  const values = new Float64Array(width * height);
  const d = new Float64Array(3);
  const hit = newHit();
  const v = newVertex();
  let exact = 0;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      let sum = 0;
      let first: HitKind | null = null;
      let mixed = false;
      let lo = Infinity,
        hi = -Infinity;
      let ok = true;
      for (let b = 0; b < k && ok; b++) {
        for (let a = 0; a < k && ok; a++) {
          const r = exactThrough(scene, view, cam, i, j, (a + 0.5) / k, (b + 0.5) / k, bounces, d, hit, v);
          if (r.value === null) ok = false;
          else {
            if (first !== null && r.kind !== first) mixed = true;
            first = r.kind;
            sum += r.value;
            lo = Math.min(lo, r.value);
            hi = Math.max(hi, r.value);
          }
        }
      }
      // a silhouette is exact only where both sides have the same constant radiance (the furnace)
      if (mixed && lo !== hi) ok = false;
      values[j * width + i] = ok ? sum / (k * k) : NaN;
      if (ok) exact++;
    }
  }
  return { values, exact };
}
