/** The parabola g(t) = a t² + b t + c of a ray against a sphere, sampled for its plot. */
import type { RaySphereHit } from '../../core/geometry';

/** g(t) = a t² + b t + c sampled for the plot, over a window that shows the vertex and the roots. */
export function gCurve(
  res: RaySphereHit,
  samples = 161,
): { t: number[]; g: number[]; tMin: number; tMax: number } {
  const { a, b } = res;
  const tv = -b / (2 * a);
  let half: number;
  if (res.t0 !== null && res.t1 !== null && res.t1 > res.t0) half = 1.6 * (res.t1 - res.t0);
  else half = Math.sqrt(Math.abs(res.discriminant)) / a;
  // include t = 0 when it is not absurdly far from the action
  if (!(half > 0) || !Number.isFinite(half)) half = 1;
  let tMin = tv - half;
  let tMax = tv + half;
  if (Math.abs(tv) < 4 * half) {
    tMin = Math.min(tMin, -0.15 * half);
    tMax = Math.max(tMax, 0.15 * half);
  }
  const t: number[] = [];
  const g: number[] = [];
  for (let i = 0; i < samples; i++) {
    const x = tMin + ((tMax - tMin) * i) / (samples - 1);
    t.push(x);
    // vertex form: a (t − t_v)² − Δ/4a, accurate where the expanded form would cancel
    g.push(a * (x - tv) * (x - tv) - res.discriminant / (4 * a));
  }
  return { t, g, tMin, tMax };
}
