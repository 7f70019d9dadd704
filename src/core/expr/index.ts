/**
 * User expressions (the pdf or integrand a student types): parse with mathjs (loaded lazily, only
 * when an expression is first used), check against a whitelist, compile to a closure tree.
 *
 *   const r = await compileExpression('cos(θ) * exp(phi)', ['theta', 'phi']);
 *   if (r.ok) r.fn(0.3, 1.2); else show(r.message);
 */
import type { Failure } from '../failure';
import { treeToTex } from './tex';
import {
  checkAndCompile,
  canonicalizeTree,
  ExpressionError,
  MAX_EXPRESSION_LENGTH,
  type CompiledFn,
} from './compile';

export * from './compile';
export { treeToTex } from './tex';

type Engine = typeof import('./engine');
let enginePromise: Promise<Engine> | null = null;

/**
 * Load the parser chunk (a minimal mathjs instance) once; later calls return the same promise.
 * A failed load (e.g. offline) is not cached, so a retry can succeed.
 */
export function loadExpressionEngine(): Promise<Engine> {
  if (!enginePromise) {
    enginePromise = import('./engine').catch((e: unknown) => {
      enginePromise = null;
      throw e;
    });
  }
  return enginePromise;
}

/** Result of {@link compileExpression}. */
export type CompileResult =
  | {
      ok: true;
      /** Evaluate with the variables positionally, in the order given to compileExpression. */
      fn: CompiledFn;
      /** Normalized source text (aliases replaced, mathjs formatting), e.g. "cos(theta) * exp(phi)". */
      text: string;
      /** LaTeX for display with KaTeX. */
      tex: string;
    }
  | Failure<CompileFailureKind>;

/** Why an expression was refused: empty, too long, parser not loadable, syntax, not allowed (whitelist), nested too deeply. */
export type CompileFailureKind = 'empty' | 'too-long' | 'unavailable' | 'syntax' | 'invalid' | 'too-deep';

/**
 * Parse, check and compile a user expression in the given variables (e.g. ['theta', 'phi'] or
 * ['x']). Never throws and never evaluates anything unchecked: every failure is reported as
 * { ok: false, kind, message } with a message for the person who typed it — syntax errors with the
 * character position, "unknown symbol 'y' — use theta, phi", "function 'foo' is not allowed", …
 * Accepts θ/φ for theta/phi, π/τ for pi/tau. Evaluation is real-valued (Math.*): outside a
 * function's domain the result is NaN, which callers must treat as invalid.
 */
export function compileExpression(src: string, variables: readonly string[]): Promise<CompileResult> {
  if (typeof src !== 'string')
    return Promise.resolve({ ok: false, kind: 'invalid', message: 'the expression must be text' });
  // Results are immutable, so identical requests share one (re-renders, workers, URL round trips).
  const key = variables.join(',') + '\u0000' + src;
  const hit = cache.get(key);
  if (hit) {
    cache.delete(key); // refresh its recency
    cache.set(key, hit);
    return hit;
  }
  const p = compileUncached(src, variables);
  cache.set(key, p);
  // a failed engine load may succeed later: do not keep that answer
  void p.then((r) => {
    if (!r.ok && r.kind === 'unavailable' && cache.get(key) === p) cache.delete(key);
  });
  if (cache.size > CACHE_SIZE) cache.delete(cache.keys().next().value!);
  return p;
}

const CACHE_SIZE = 64;
const LOAD_ERROR = 'the expression parser could not be loaded (check the connection and try again)';
const cache = new Map<string, Promise<CompileResult>>();

async function compileUncached(src: string, variables: readonly string[]): Promise<CompileResult> {
  const trimmed = src.trim();
  if (trimmed.length === 0) return { ok: false, kind: 'empty', message: 'the expression is empty' };
  if (src.length > MAX_EXPRESSION_LENGTH) {
    return {
      ok: false,
      kind: 'too-long',
      message: `the expression is too long (${src.length} characters; at most ${MAX_EXPRESSION_LENGTH})`,
    };
  }
  let engine: Engine;
  try {
    engine = await loadExpressionEngine();
  } catch {
    return { ok: false, kind: 'unavailable', message: LOAD_ERROR };
  }
  let tree;
  try {
    tree = engine.parseToTree(src);
  } catch (e) {
    return { ok: false, kind: e instanceof RangeError ? 'too-deep' : 'syntax', message: syntaxMessage(e) };
  }
  try {
    const fn = checkAndCompile(tree, variables);
    const canon = canonicalizeTree(tree);
    let tex: string;
    try {
      tex = treeToTex(canon);
    } catch {
      tex = '\\text{' + canon.toString().replace(/[\\{}$&#^_%~]/g, ' ') + '}';
    }
    return { ok: true, fn, text: canon.toString(), tex };
  } catch (e) {
    if (e instanceof ExpressionError) return { ok: false, kind: 'invalid', message: e.message };
    if (e instanceof RangeError)
      return { ok: false, kind: 'too-deep', message: 'the expression is nested too deeply' };
    return {
      ok: false,
      kind: 'invalid',
      message: `the expression could not be compiled: ${e instanceof Error ? e.message : String(e)}`,
    };
  }
}

function syntaxMessage(e: unknown): string {
  if (e instanceof RangeError) return 'the expression is nested too deeply';
  if (e instanceof Error) {
    const pos = (e as { char?: unknown }).char;
    const msg = e.message.replace(/\s*\(char \d+\)\s*$/, '');
    return typeof pos === 'number' ? `syntax error at character ${pos}: ${msg}` : `syntax error: ${msg}`;
  }
  return 'syntax error';
}

/**
 * LaTeX for an expression (aliases normalized), for display. If it does not parse or fails the
 * whitelist, returns the source as \text{…} so the page can still show something.
 */
export async function toTex(
  src: string,
  variables: readonly string[] = ['theta', 'phi', 'x'],
): Promise<string> {
  const r = await compileExpression(src, variables);
  if (r.ok) return r.tex;
  return '\\text{' + src.replace(/[\\{}$&#^_%~]/g, ' ') + '}';
}
