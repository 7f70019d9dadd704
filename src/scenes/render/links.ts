/**
 * Where each number of the pixel inspector is taught: links into the exam scenes, in the state
 * that shows the same computation (the same ray and sphere, the same (u, v) and grid, the same
 * light and point, the same sampling density).
 */
import type { SampleRow } from '../../core/render/inspector';
import type { Vec3 } from '../../core/vec3';
import { formatGrid } from '../../core/texture/grid';
import type { RenderModel } from './model';

const list = (v: readonly number[]) => v.map((x) => String(x)).join(',');

function href(path: string, q: Record<string, string>): string {
  return `#${path}?${new URLSearchParams(q).toString()}`;
}

/** The ray–sphere scene with the primary ray and the scene's sphere (Q5). */
export function raySphereHref(sphere: { center: Vec3; radius: number }, o: Vec3, d: Vec3): string {
  return href('/ray-sphere', { o: list(o), d: list(d), c: list(sphere.center), r: String(sphere.radius) });
}

/** The texture scene at the looked-up (u, v) on the same grid (Q3). */
export function textureHref(m: RenderModel, u: number, v: number): string {
  return href('/texture', { u: String(u), v: String(v), grid: formatGrid(m.spec.exam.grid) });
}

/** Where a sample of the estimator is taught: the hemisphere scene's density, or the area-light scene's light. */
export function sampleHref(m: RenderModel, row: SampleRow, p: Vec3 | null): { href: string; label: string } {
  if (row.technique === 'area' || row.technique === 'solid-angle') {
    const e = m.spec.exam;
    const q: Record<string, string> = { strategy: row.technique };
    // the exam scene's light is the area-light scene's; its point lies on its floor z = 0
    if (m.spec.scene === 'exam') {
      Object.assign(q, {
        lc: list(e.lc),
        ls: list(e.ls),
        tilt: String(e.tilt),
        L: String(e.L),
        rho: String(e.rho),
      });
      if (p && p[2] === 0) q.p = list(p);
    }
    return { href: href('/area-light', q), label: 'Q6: sampling the light' };
  }
  const lobe = row.technique === 'uniform' ? 'uniform' : 'cosine';
  return { href: href('/hemisphere', { lobe }), label: `Q1–Q2: the ${lobe} density` };
}
