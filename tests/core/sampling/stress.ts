/** Shared stress inputs for the hemisphere warp tests: ξ ∈ {0, 2⁻⁵³, ½, 1 − 2⁻⁵³}. */
export const TINY = 2 ** -53;
export const NEAR_ONE = 1 - 2 ** -53;
export const STRESS_U = [0, TINY, 0.5, NEAR_ONE] as const;

/** All pairs of stress inputs. */
export const STRESS_PAIRS: [number, number][] = STRESS_U.flatMap((a) =>
  STRESS_U.map((b) => [a, b] as [number, number]),
);

/** |v| for out[o..o+2]. */
export function norm3(v: ArrayLike<number>, o = 0): number {
  return Math.hypot(v[o], v[o + 1], v[o + 2]);
}

/** Distance between two points of [0,1)² on the torus (u = 0 and u → 1 are neighbours in φ). */
export function torusDist(a: number, b: number): number {
  const d = Math.abs(a - b);
  return Math.min(d, 1 - d);
}
