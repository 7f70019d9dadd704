/** The scene's compiler for typed expressions in (theta, phi): core/expr's (mathjs loads lazily). */
import { compileExpression } from '../../core/expr';
import type { CompileOutcome } from '../../ui/useCompiled';
import type { Integrand } from './model';

export async function compileThetaPhi(src: string): Promise<CompileOutcome<Integrand>> {
  const r = await compileExpression(src, ['theta', 'phi']);
  if (!r.ok) return r;
  const fn = r.fn;
  return { ok: true, fn: (t, p) => fn(t, p), tex: r.tex };
}
