/**
 * The scene's view hooks: plot height on phones, the redraw rate of the plots, and the page's own
 * estimate spread over short tasks.
 */
import { useEffect, useState } from 'react';
import { runChunked } from '../../../ui';
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

/** Redraw interval of the plots while a run is in progress (ms). */
export const REDRAW_MS = 400;

export /**
 * estimate1D(problem, n) on the main thread, one batch of points per short task (ui/chunked), so
 * neither the scene's first render nor a parameter change runs it in one long task.
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

/**
 * ask=1 holds the animation at its start: while `held`, a position other than 0 (or playing) is
 * written back to t = 0, paused, so the race is still at its start when the results are revealed.
 */
export function useHeldAtStart(
  held: boolean,
  t: number,
  play: boolean,
  setParams: (patch: { t: number; play: boolean }) => void,
): void {
  useEffect(() => {
    if (held && (t !== 0 || play)) setParams({ t: 0, play: false });
  }, [held, t, play, setParams]);
}
