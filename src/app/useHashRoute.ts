import { startTransition, useEffect, useState } from 'react';
import { parseHash, type Route } from '../kit/shell';

/**
 * The current hash route; re-renders on hashchange (not on replaceState, which the shell itself does).
 * A change of the query on the same page (a typed or pasted link, back and forward) re-renders the
 * scene as a transition, which React renders in slices that yield, so a storm of such changes
 * never makes one long task; a change of page renders at once.
 */
export function useHashRoute(): Route {
  const [route, setRoute] = useState(() => parseHash(window.location.hash));
  useEffect(() => {
    let path = parseHash(window.location.hash).path;
    const on = () => {
      const next = parseHash(window.location.hash);
      const samePage = next.path === path;
      path = next.path;
      if (samePage) startTransition(() => setRoute(next));
      else setRoute(next);
    };
    window.addEventListener('hashchange', on);
    return () => window.removeEventListener('hashchange', on);
  }, []);
  return route;
}
