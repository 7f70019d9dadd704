import { useCallback, useEffect, useRef, useState } from 'react';
import { isCancelled, runWorkerTask } from './run';

export interface WorkerTaskState<R, P> {
  running: boolean;
  progress: number;
  partial: P | undefined;
  result: R | undefined;
  error: string | null;
}

/**
 * React wrapper over {@link runWorkerTask}: `start(args)` cancels any run in flight and starts a
 * new one; `cancel()` stops it; state carries progress, partial results, the result and errors.
 * Progress updates are coalesced to one React update per animation frame.
 */
export function useWorkerTask<R, P = unknown>(makeWorker: () => Worker, method: string) {
  const [state, setState] = useState<WorkerTaskState<R, P>>({ running: false, progress: 0, partial: undefined, result: undefined, error: null });
  const ctl = useRef<AbortController | null>(null);
  const pending = useRef<{ fraction: number; partial?: P } | null>(null);
  const raf = useRef(0);
  const makeRef = useRef(makeWorker);
  makeRef.current = makeWorker;

  const cancel = useCallback(() => {
    ctl.current?.abort();
    ctl.current = null;
    setState((s) => (s.running ? { ...s, running: false } : s));
  }, []);

  const start = useCallback(
    (args: unknown) => {
      ctl.current?.abort();
      const c = new AbortController();
      ctl.current = c;
      setState({ running: true, progress: 0, partial: undefined, result: undefined, error: null });
      runWorkerTask<R, P>(() => makeRef.current(), method, args, {
        signal: c.signal,
        onProgress: (fraction, partial) => {
          pending.current = { fraction, partial };
          if (!raf.current) {
            raf.current = requestAnimationFrame(() => {
              raf.current = 0;
              const p = pending.current;
              pending.current = null;
              if (p && ctl.current === c) setState((s) => ({ ...s, progress: p.fraction, partial: p.partial ?? s.partial }));
            });
          }
        },
      }).then(
        (result) => {
          if (ctl.current === c) {
            ctl.current = null;
            setState((s) => ({ ...s, running: false, progress: 1, result }));
          }
        },
        (err) => {
          if (isCancelled(err)) return;
          if (ctl.current === c) {
            ctl.current = null;
            setState((s) => ({ ...s, running: false, error: err instanceof Error ? err.message : String(err) }));
          }
        },
      );
    },
    [method],
  );

  useEffect(
    () => () => {
      ctl.current?.abort();
      if (raf.current) cancelAnimationFrame(raf.current);
    },
    [],
  );

  return { ...state, start, cancel };
}
