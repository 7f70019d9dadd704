/**
 * The one hook that turns a typed expression into a function for the page. `compile` is the
 * scene's compiler (core/expr's, adapted to its variables; module-level so it is stable); `fast`
 * an optional synchronous path (e.g. the exam's default integrand, so the default page never loads
 * the parser). A result for an older `src` reads as pending: the page never uses a stale function.
 */
import { useEffect, useMemo, useState } from 'react';
import type { Failure } from '../core/failure';

export type CompileOutcome<F> = { ok: true; fn: F; tex?: string } | Failure;

export type Compiled<F> =
  | { status: 'pending'; src: string }
  | { status: 'ok'; src: string; fn: F; tex?: string }
  | { status: 'error'; src: string; kind: string; message: string };

function toCompiled<F>(src: string, r: CompileOutcome<F>): Compiled<F> {
  return r.ok
    ? { status: 'ok', src, fn: r.fn, tex: r.tex }
    : { status: 'error', src, kind: r.kind, message: r.message };
}

export function useCompiled<F>(
  src: string,
  compile: (src: string) => Promise<CompileOutcome<F>>,
  options: { enabled?: boolean; fast?: (src: string) => CompileOutcome<F> | null } = {},
): Compiled<F> {
  const { enabled = true, fast } = options;
  const quick = useMemo(() => {
    if (!enabled || !fast) return null;
    const r = fast(src);
    return r ? toCompiled(src, r) : null;
  }, [src, enabled, fast]);
  const [state, setState] = useState<Compiled<F>>({ status: 'pending', src });
  useEffect(() => {
    if (!enabled || quick) return;
    let alive = true;
    compile(src).then(
      (r) => alive && setState(toCompiled(src, r)),
      (e: unknown) =>
        alive &&
        setState({
          status: 'error',
          src,
          kind: 'unavailable',
          message: e instanceof Error ? e.message : String(e),
        }),
    );
    return () => {
      alive = false;
    };
  }, [src, enabled, quick, compile]);
  if (quick) return quick;
  return state.src === src ? state : { status: 'pending', src };
}
