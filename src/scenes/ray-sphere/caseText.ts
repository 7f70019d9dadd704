/** The five cases of a ray against a sphere, in plain words (shown beside the case name). */
import type { RaySphereCase } from '../../core/geometry';

/** Plain-words explanation of each case, shown beside the case name. */
export const CASE_TEXT: Record<RaySphereCase, string> = {
  miss: 'Δ < 0: the quadratic has no real root, so the line never touches the sphere.',
  tangent: 'Δ = 0: one double root; the ray just touches the sphere at t = −b / 2a.',
  'two-hits':
    'Δ > 0 and both roots ≥ 0: the ray enters at t₀ and leaves at t₁. The hit is the nearest root ≥ 0, t₀.',
  inside:
    'Δ > 0 with t₀ < 0 ≤ t₁: the origin is inside the sphere. t₀ lies behind the origin, so the hit is t₁ (the exit).',
  behind:
    'Δ ≥ 0 but every root is < 0: the line meets the sphere behind the origin. A ray only goes forward (t ≥ 0), so there is no hit.',
};

/** The cases' names, as the banner over the figure writes them. */
export const CASE_NAME: Record<RaySphereCase, string> = {
  miss: 'Miss',
  tangent: 'Tangent',
  'two-hits': 'Two hits',
  inside: 'Origin inside',
  behind: 'Sphere behind',
};

/**
 * What the case banner says: the case the chosen method computed and its meaning, and, when
 * rounding made that case wrong, that the method produced it and what the exact case is.
 */
export function caseBanner(
  chosen: RaySphereCase,
  exact: RaySphereCase | null,
  form: 'textbook' | 'robust',
  arithmetic: 'double' | 'float32',
): { name: string; text: string; wrong: string | null } {
  const wrong =
    exact !== null && exact !== chosen
      ? `This is what the ${form} form computes in ${arithmetic} arithmetic: the exact answer for ` +
        `these inputs is “${CASE_NAME[exact]}”, as the figure draws it. Rounding changed the case.`
      : null;
  return { name: CASE_NAME[chosen], text: CASE_TEXT[chosen], wrong };
}
