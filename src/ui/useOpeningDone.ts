/**
 * The page's load milestones (./whenQuiet) as React state:
 *  - `usePageSettled`: the first screen has been painted and the page has then been quiet
 *    (pageSettled). A worker's opening run whose result is not on the first screen waits for it.
 *  - `useOpeningDone`: the page has settled, or its reader has pressed a key, a pointer, the wheel
 *    or a touch screen (openingDone). Work that competes for the cores but is not needed to show
 *    the first screen (a worker that renders, a reference computed in the background) starts then.
 */
import { useEffect, useState } from 'react';
import { isOpeningDone, isPageSettled, openingDone, pageSettled } from './whenQuiet';

/** True once `when()` has resolved (at once where `now()` says it already has). */
function useResolved(now: () => boolean, when: () => Promise<void>): boolean {
  const [done, setDone] = useState(now);
  useEffect(() => {
    if (done) return;
    let live = true;
    void when().then(() => {
      if (live) setDone(true);
    });
    return () => {
      live = false;
    };
  }, [done, when]);
  return done;
}

/** True once the page has settled; at once, without asking for it, where `wanted` is false. */
export function usePageSettled(wanted = true): boolean {
  return useResolved(() => !wanted || isPageSettled(), pageSettled);
}

export function useOpeningDone(): boolean {
  return useResolved(isOpeningDone, openingDone);
}
