/**
 * The scene's view hooks: plot height on phones, throttled redraws, worker runs started when first
 * seen, and the page's own estimate spread over short tasks.
 */
import { useEffect, useRef, useState } from 'react';
import { runChunked, useSeenOnce } from '../../../ui';
import { useWorkerJob } from '../../../workers';
import type { ArgsOf, TaskMap, TaskName, WorkerFactory } from '../../../workers/protocol';
import { EstimateRun1D, type McEstimate, type Problem1D } from '../../../core/estimators';

export /** Extra plot height on phones, where the legend above the plot takes several rows. */
function useLegendRoom(): number {
  const q = '(max-width: 600px)';
  const [narrow, setNarrow] = useState(
    () =>
      typeof window !== 'undefined' &&
      typeof window.matchMedia === 'function' &&
      window.matchMedia(q).matches,
  );
  useEffect(() => {
    if (typeof window.matchMedia !== 'function') return;
    const m = window.matchMedia(q);
    const on = () => setNarrow(m.matches);
    m.addEventListener('change', on);
    return () => m.removeEventListener('change', on);
  }, []);
  return narrow ? 110 : 0;
}

export /**
 * The value, updated at most every `ms` (a steady redraw rate however fast partial results come),
 * and at once when `immediate` (the final result).
 */
function useThrottled<T>(value: T, ms: number, immediate: boolean): T {
  const [shown, setShown] = useState(value);
  const last = useRef(0);
  const timer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  const latest = useRef(value);
  latest.current = value;
  useEffect(() => {
    const now = performance.now();
    if (immediate || now - last.current >= ms) {
      if (timer.current !== undefined) clearTimeout(timer.current);
      timer.current = undefined;
      last.current = now;
      setShown(value);
    } else if (timer.current === undefined) {
      timer.current = setTimeout(
        () => {
          timer.current = undefined;
          last.current = performance.now();
          setShown(latest.current);
        },
        ms - (now - last.current),
      );
    }
  }, [value, ms, immediate]);
  useEffect(() => () => clearTimeout(timer.current), []);
  return shown;
}

/** Redraw interval of the plots while a run is in progress (ms). */
export const REDRAW_MS = 400;

export /**
 * Start a worker job when the panel is first seen and whenever its key changes (debounced). The
 * panels share one queue: their runs go one at a time (first come, first served), so the workers
 * never take every core from the page that draws their results (2 cores are common).
 */
function useAutoRun<T extends TaskMap, K extends TaskName<T>>(
  method: K,
  makeWorker: WorkerFactory<T>,
  args: ArgsOf<T, K>,
  key: string,
  box: React.RefObject<HTMLElement | null>,
) {
  const seen = useSeenOnce(box, '100px');
  return useWorkerJob(makeWorker, method, args, {
    key,
    enabled: seen,
    delayMs: 250,
    queue: 'monte-carlo',
  });
}

export /**
 * estimate1D(problem, n) on the main thread, one batch of points per short task (ui/chunked), so
 * neither the scene's first render nor a parameter change runs it in one long task (issue 15).
 * Null while it runs (and when `problem` is null); the result is exactly estimate1D's. A new
 * problem or n cancels the run in progress. `problem` is compared by identity (memoise it).
 */
function useSlicedEstimate(problem: Problem1D | null, n: number): McEstimate | null {
  const [done, setDone] = useState<{ problem: Problem1D; n: number; est: McEstimate } | null>(null);
  useEffect(() => {
    if (!problem) return;
    const run = new EstimateRun1D(problem, n);
    let cancel = () => {};
    const step = () => {
      if (run.step()) setDone({ problem, n, est: run.result() });
      else cancel = runChunked(step);
    };
    cancel = runChunked(step);
    return () => cancel();
  }, [problem, n]);
  return problem && done && done.problem === problem && done.n === n ? done.est : null;
}
