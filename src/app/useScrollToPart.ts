import { useEffect } from 'react';

/**
 * Land on an exam part (`part=1c`): once the scene has drawn the element `#part-1c`, scroll it to
 * the top and move focus there (screen readers start reading at the part). Gives up quietly after
 * a few seconds if the scene never draws it.
 */
export function useScrollToPart(part: string | null) {
  useEffect(() => {
    if (!part) return;
    let done = false;
    const tryLand = () => {
      if (done) return true;
      const el = document.getElementById(`part-${part}`);
      if (!el) return false;
      done = true;
      el.scrollIntoView({ block: 'start' });
      if (el.tabIndex < 0 && !el.hasAttribute('tabindex')) el.setAttribute('tabindex', '-1');
      el.focus({ preventScroll: true });
      return true;
    };
    if (tryLand()) return;
    const mo = new MutationObserver(() => {
      if (tryLand()) mo.disconnect();
    });
    mo.observe(document.body, { childList: true, subtree: true });
    const timer = window.setTimeout(() => mo.disconnect(), 8000);
    return () => {
      done = true;
      mo.disconnect();
      window.clearTimeout(timer);
    };
  }, [part]);
}
