/**
 * The scene's compiler for typed expressions in x: core/expr's whitelisted compiler (mathjs loads
 * lazily, on first use), adapted to a one-variable function. The exam's (x + c)² takes a fast path
 * (`compileXFast`) that needs no parser, so neither the default page nor its worker loads mathjs.
 */
import { compileExpression } from '../../core/expr';
import { squareShift, type Fn1 } from './integral';
import type { Compile } from './jobs';

/** The parser-free path: (x + c)² for a literal c, else null. */
export function compileXFast(src: string): { ok: true; fn: Fn1 } | null {
  const c = squareShift(src);
  return c === null ? null : { ok: true, fn: (x: number) => (x + c) * (x + c) };
}

export const compileX: Compile = async (src) => {
  const quick = compileXFast(src);
  if (quick) return quick;
  const r = await compileExpression(src, ['x']);
  if (!r.ok) return r;
  const g = r.fn as (x: number) => number;
  return { ok: true, fn: (x: number) => g(x), tex: r.tex };
};
