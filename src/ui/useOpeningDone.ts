/**
 * Whether the page's opening is over (./whenQuiet openingDone: the page has settled, or its reader
 * has pressed a key, a pointer, the wheel or a touch screen), as React state. Work that competes
 * for the cores but is not needed to show the first screen (a worker that renders, a reference
 * computed in the background) starts when it turns true.
 */
import { useEffect, useState } from 'react';
import { isOpeningDone, openingDone } from './whenQuiet';

export function useOpeningDone(): boolean {
  const [done, setDone] = useState(isOpeningDone);
  useEffect(() => {
    if (done) return;
    let live = true;
    void openingDone().then(() => {
      if (live) setDone(true);
    });
    return () => {
      live = false;
    };
  }, [done]);
  return done;
}
