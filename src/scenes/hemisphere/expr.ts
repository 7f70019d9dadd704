/**
 * The scene's compiler for typed expressions in (theta, phi): core/expr's (mathjs loads lazily),
 * and a synchronous path (`compileThetaPhiFast`) for the default integrand f = cos(theta), so the
 * default page never loads the parser on the main thread (mathjs' `create` and the
 * first parse cost ~350 ms of a phone's main thread on load).
 */
import { compileExpression } from '../../core/expr';
import type { CompileOutcome } from '../../ui/useCompiled';
import type { Integrand } from './integral';

/** The default integrand written as the compiler writes it (its TeX is the compiler's, checked by a unit test). */
const COS_THETA = { src: 'cos(theta)', tex: '\\cos\\left(\\theta\\right)' };

/** Is the integrand cos(theta) (any spacing)? The page's zero-variance remarks depend on it too. */
export function isCosTheta(src: string): boolean {
  return src.replace(/\s+/g, '') === COS_THETA.src;
}

/** cos(theta) (any spacing) without the parser; null for anything else. */
export function compileThetaPhiFast(src: string): CompileOutcome<Integrand> | null {
  if (!isCosTheta(src)) return null;
  return { ok: true, fn: (t) => Math.cos(t), tex: COS_THETA.tex };
}

export async function compileThetaPhi(src: string): Promise<CompileOutcome<Integrand>> {
  const r = await compileExpression(src, ['theta', 'phi']);
  if (!r.ok) return r;
  const fn = r.fn;
  return { ok: true, fn: (t, p) => fn(t, p), tex: r.tex };
}
