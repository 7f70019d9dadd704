/**
 * The image in words, for people who cannot see it: what the ray through the middle of each ninth
 * of the image (top left … bottom right) meets, the mean brightness and the samples per pixel.
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

/** What each ninth of the image shows (row by row, top first): a hit kind per region. */
export function regionsOf(scene: RenderScene, view: View, res: number): HitKind[] {
  const cam = makeCamera(view, res, res);
  const d = new Float64Array(3);
  const hit = newHit();
  const out: HitKind[] = [];
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) {
      // the middle of region (c, r), in pixel coordinates
      const x = ((c + 0.5) * res) / 3,
        y = ((r + 0.5) * res) / 3;
      cameraRay(cam, Math.floor(x), Math.floor(y), x - Math.floor(x), y - Math.floor(y), d);
      const o = view.eye;
      out.push(closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, hit));
    }
  return out;
}

/** One paragraph describing the image. */
export function describeImage(
  scene: RenderScene,
  view: View,
  res: number,
  stats: { spp: number; mean: number },
): string {
  const regions = regionsOf(scene, view, res);
  const where = regions.map((k, n) => `${ROWS[Math.floor(n / 3)]} ${COLS[n % 3]}: ${NAMES[k]}`).join('; ');
  const scenes = { exam: 'the exam scene', furnace: 'the white furnace', veach: 'Veach’s four plates' };
  const light =
    Number.isFinite(stats.mean) && stats.spp > 0
      ? `Mean brightness ${formatNumber(stats.mean)} (linear radiance) after ${stats.spp} sample${stats.spp === 1 ? '' : 's'} per pixel.`
      : 'No sample has arrived yet.';
  return `A ${res} × ${res} image of ${scenes[scene.id]}. ${where[0].toUpperCase()}${where.slice(1)}. ${light}`;
}
