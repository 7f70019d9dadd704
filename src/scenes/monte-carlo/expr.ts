/**
 * The scene's compiler for typed expressions in x: core/expr's whitelisted compiler (mathjs loads
 * lazily, on first use), adapted to a one-variable function.
 */
import { compileExpression } from '../../core/expr';
import type { Compile } from './jobs';

export const compileX: Compile = async (src) => {
  const r = await compileExpression(src, ['x']);
  if (!r.ok) return { ok: false, message: r.error };
  const g = r.fn as (x: number) => number;
  return { ok: true, fn: (x: number) => g(x), tex: r.tex };
};
