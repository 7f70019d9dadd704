/**
 * Compile a typed expression in (theta, phi) with core/expr (mathjs parser loaded lazily).
 * Returns 'pending' until the parser chunk has loaded, then the compiled function or the message.
 */
import { useEffect, useState } from 'react';
import { compileExpression } from '../../core/expr';

export type Compiled =
  | { status: 'pending'; src: string }
  | { status: 'ok'; src: string; fn: (theta: number, phi: number) => number; tex: string }
  | { status: 'error'; src: string; error: string };

export function useCompiled(src: string, enabled = true): Compiled {
  const [state, setState] = useState<Compiled>({ status: 'pending', src });
  useEffect(() => {
    if (!enabled) return;
    let alive = true;
    compileExpression(src, ['theta', 'phi']).then(
      (r) => {
        if (!alive) return;
        if (r.ok) {
          const fn = r.fn;
          setState({ status: 'ok', src, fn: (t, p) => fn(t, p), tex: r.tex });
        } else setState({ status: 'error', src, error: r.error });
      },
      (e: unknown) => alive && setState({ status: 'error', src, error: e instanceof Error ? e.message : String(e) }),
    );
    return () => {
      alive = false;
    };
  }, [src, enabled]);
  // a stale result (for an older src) reads as pending
  return state.src === src ? state : { status: 'pending', src };
}
