/**
 * The image in words, for people who cannot see it: what the rays through each ninth of the image
 * (top left … bottom right) meet, the mean brightness and the samples per pixel.
 * Computed from the scene and the camera, as the image is.
 */
import { cameraRay, makeCamera } from '../../core/render/camera';
import { closestHit, newHit, type HitKind } from '../../core/render/intersect';
import type { RenderScene, View } from '../../core/render/scene';
import { formatNumber } from '../../core/format';

const ROWS = ['top', 'middle', 'bottom'] as const;
const COLS = ['left', 'centre', 'right'] as const;

const NAMES: Record<HitKind, string> = {
  floor: 'the floor',
  sphere: 'the textured sphere',
  light: 'a light',
  plate: 'a glossy plate',
  none: 'the background',
};

/** Rays per side of each ninth of the image. */
const PROBES = 4;

/**
 * What each ninth of the image shows (row by row, top first): the kinds of object that a 4 × 4
 * grid of rays through that ninth meets, the most frequent first.
 */
export function regionsOf(scene: RenderScene, view: View, res: number): HitKind[][] {
  const cam = makeCamera(view, res, res);
  const d = new Float64Array(3);
  const hit = newHit();
  const o = view.eye;
  const out: HitKind[][] = [];
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) {
      const counts = new Map<HitKind, number>();
      for (let b = 0; b < PROBES; b++)
        for (let a = 0; a < PROBES; a++) {
          // a point of region (c, r), in pixel coordinates
          const x = ((c + (a + 0.5) / PROBES) * res) / 3,
            y = ((r + (b + 0.5) / PROBES) * res) / 3;
          cameraRay(cam, Math.floor(x), Math.floor(y), x - Math.floor(x), y - Math.floor(y), d);
          const k = closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, hit);
          counts.set(k, (counts.get(k) ?? 0) + 1);
        }
      out.push([...counts.entries()].sort((p, q) => q[1] - p[1]).map(([k]) => k));
    }
  return out;
}

/**
 * One paragraph describing the image: `regions` is {@link regionsOf} the scene and view (it traces
 * rays, so a page computes it once per view, not once per pass of the render).
 */
export function describeImage(
  scene: RenderScene,
  regions: HitKind[][],
  res: number,
  stats: { spp: number; mean: number },
): string {
  const name = (k: HitKind) => (k === 'sphere' && !scene.sphere?.texture ? 'the sphere' : NAMES[k]);
  const where = regions
    .map((ks, n) => `${ROWS[Math.floor(n / 3)]} ${COLS[n % 3]}: ${ks.map(name).join(' and ')}`)
    .join('; ');
  const scenes = { exam: 'the exam scene', furnace: 'the white furnace', veach: 'Veach’s four plates' };
  const light =
    Number.isFinite(stats.mean) && stats.spp > 0
      ? `Mean brightness ${formatNumber(stats.mean)} (linear radiance) after ${stats.spp} sample${stats.spp === 1 ? '' : 's'} per pixel.`
      : 'No sample has arrived yet.';
  return `A ${res} × ${res} image of ${scenes[scene.id]}. ${where[0].toUpperCase()}${where.slice(1)}. ${light}`;
}
