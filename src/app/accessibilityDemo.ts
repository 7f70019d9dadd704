/**
 * The worked example of the accessibility page: g(t) = (t − 2)² + b² − r² along a ray whose
 * closest approach to a sphere's centre is b at t = 2 (the ray–sphere quadratic, shifted). Pure.
 */

/** Closest approach of the example ray to the centre. */
export const DEMO_B = 0.5;
/** t range of the example plot. */
export const DEMO_T = [0, 4] as const;

export interface DemoCurve {
  ts: number[];
  gs: number[];
  roots: number[];
}

export function demoCurve(r: number, samples = 41): DemoCurve {
  const ts: number[] = [];
  const gs: number[] = [];
  for (let i = 0; i < samples; i++) {
    const t = DEMO_T[0] + ((DEMO_T[1] - DEMO_T[0]) * i) / (samples - 1);
    ts.push(t);
    gs.push((t - 2) ** 2 + DEMO_B * DEMO_B - r * r);
  }
  const disc = r * r - DEMO_B * DEMO_B;
  const roots = disc > 0 ? [2 - Math.sqrt(disc), 2 + Math.sqrt(disc)] : disc === 0 ? [2] : [];
  return { ts, gs, roots };
}

const f2 = (v: number) => v.toFixed(2).replace(/^-/, '−');

/** What the example figure shows, with its numbers. */
export function describeDemo(r: number): string {
  const { roots } = demoCurve(r, 2);
  const gMin = DEMO_B * DEMO_B - r * r;
  const head = `Radius r = ${f2(r)}, closest approach ${f2(DEMO_B)} at t = 2.`;
  if (roots.length === 2)
    return `${head} The ray hits the sphere at t = ${f2(roots[0]!)} and leaves it at t = ${f2(roots[1]!)}; g is lowest, ${f2(gMin)}, at t = 2.`;
  if (roots.length === 1) return `${head} The ray touches the sphere at t = 2 (g's minimum is 0).`;
  return `${head} The ray misses: g stays above 0, lowest ${f2(gMin)} at t = 2, ${f2(DEMO_B - r)} beyond the radius.`;
}
