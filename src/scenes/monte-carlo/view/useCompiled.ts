/**
 * Compile a typed expression in x for the page. The exam's (x + c)² takes a fast path that needs
 * no parser, so the default page never loads mathjs; anything else goes through core/expr.
 */
import { useEffect, useState } from 'react';
import { squareShift, type Fn1 } from '../model';
import { compileX } from '../expr';

export type Compiled = { status: 'pending' } | { status: 'ok'; fn: Fn1; src: string } | { status: 'error'; message: string; src: string };

function fast(src: string): Compiled | null {
  const c = squareShift(src);
  if (c === null) return null;
  return { status: 'ok', fn: (x: number) => (x + c) * (x + c), src };
}

export function useCompiled(src: string, enabled = true): Compiled {
  const [state, setState] = useState<Compiled>(() => (enabled ? (fast(src) ?? { status: 'pending' }) : { status: 'pending' }));
  useEffect(() => {
    if (!enabled) return;
    const f = fast(src);
    if (f) {
      setState(f);
      return;
    }
    let alive = true;
    setState((s) => (s.status !== 'pending' && s.src === src ? s : { status: 'pending' }));
    compileX(src).then(
      (r) => {
        if (!alive) return;
        setState(r.ok ? { status: 'ok', fn: r.fn, src } : { status: 'error', message: r.message, src });
      },
      (e: unknown) => alive && setState({ status: 'error', message: e instanceof Error ? e.message : String(e), src }),
    );
    return () => {
      alive = false;
    };
  }, [src, enabled]);
  return state;
}
