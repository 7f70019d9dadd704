/**
 * A part of the page that is mounted late (issue 15): when it comes near the screen, else in idle
 * time, one section per idle period in page order (./viewQueue), and at once before printing. A
 * scene's exam page mounts its first screen first; the derivations, tables and plots below follow
 * in short tasks instead of one long commit (and one long layout) when the page opens on a phone.
 *
 * Until it mounts, a placeholder keeps an estimated height (so the scroll bar is about right and
 * the page below does not jump when it arrives near the screen) and is marked
 * `data-deferred="pending"` (tests wait until none is left). Mounting is a transition: React
 * renders the subtree in slices that yield to input. Where IntersectionObserver is missing
 * everything mounts at once.
 */
import { startTransition, useEffect, useRef, useState, type ReactNode } from 'react';
import { flushSync } from 'react-dom';
import { createViewQueue } from './viewQueue';

/** How far below (or above) the screen a section starts mounting. */
export const DEFERRED_MARGIN = '800px 0px';

const queue = createViewQueue({
  margin: DEFERRED_MARGIN,
  perIdle: 1,
  // a page that is never idle (a slow phone, a loaded machine) still gets a section every 0.5 s
  idleTimeoutMs: 500,
  runNear: (job) => {
    job();
    return () => {};
  },
});

let flushing = false;
/** Mount every section still waiting, synchronously (before printing). */
export function flushDeferred(): void {
  flushing = true;
  try {
    flushSync(() => queue.flush());
  } finally {
    flushing = false;
  }
}

let printHooked = false;
function hookPrint(): void {
  if (printHooked || typeof window === 'undefined') return;
  printHooked = true;
  // capture: before MathTex's own beforeprint listener (on window, capture listeners run first),
  // so the formulas of the sections mounted here are sent to the typesetter by that flush too
  window.addEventListener('beforeprint', flushDeferred, { capture: true });
}

export function Deferred({ children, estimate = 480 }: { children: ReactNode; /** the placeholder's height (px) */ estimate?: number }) {
  const [on, setOn] = useState(() => typeof IntersectionObserver !== 'function');
  const ref = useRef<HTMLDivElement>(null);
  useEffect(() => {
    if (on) return;
    hookPrint();
    // the print flush mounts synchronously (flushSync needs a plain update, not a transition)
    return queue.schedule(ref.current, () => {
      if (flushing) setOn(true);
      else startTransition(() => setOn(true));
    });
  }, [on]);
  if (on) return <>{children}</>;
  return <div ref={ref} className="deferred-pending" data-deferred="pending" style={{ minHeight: estimate }} />;
}
