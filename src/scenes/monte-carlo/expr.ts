/**
 * The scene's compiler for typed expressions in x: core/expr's whitelisted compiler (mathjs loads
 * lazily, on first use), adapted to a one-variable function. The exam's (x + c)² takes a fast path
 * that needs no parser, so neither the default page nor its worker loads mathjs.
 */
import { compileExpression } from '../../core/expr';
import { squareShift } from './model';
import type { Compile } from './jobs';

export const compileX: Compile = async (src) => {
  const c = squareShift(src);
  if (c !== null) return { ok: true, fn: (x: number) => (x + c) * (x + c) };
  const r = await compileExpression(src, ['x']);
  if (!r.ok) return { ok: false, message: r.error };
  const g = r.fn as (x: number) => number;
  return { ok: true, fn: (x: number) => g(x), tex: r.tex };
};
