import { useEffect, useState } from 'react';
import { parseHash, type Route } from '../kit/shell';

/** The current hash route; re-renders on hashchange (not on replaceState, which the shell itself does). */
export function useHashRoute(): Route {
  const [route, setRoute] = useState(() => parseHash(window.location.hash));
  useEffect(() => {
    const on = () => setRoute(parseHash(window.location.hash));
    window.addEventListener('hashchange', on);
    return () => window.removeEventListener('hashchange', on);
  }, []);
  return route;
}
