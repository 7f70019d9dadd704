import { useEffect } from 'react';

/**
 * Land on an exam part (`part=1c`): once the scene has drawn the element `#part-1c`, scroll it to
 * the top and move focus there (screen readers start reading at the part). Gives up quietly after
 * a few seconds if the scene never draws it.
 *
 * `askFirst`: a link that opens in classroom mode and asks first (`present=1&ask=1`, a lesson
 * preset shown to a room) lands on the top of the page instead, each time such a link is opened
 * (`query`, the link's query string, tells them apart): the question to predict and the stage
 * under it fill the first screen, so the class reads the question, Reveal (`v`) shows the result on
 * the stage in view, and Space plays the animation in view. The part follows below.
 */
export function useScrollToPart(part: string | null, askFirst = false, query = '') {
  useEffect(() => {
    if (askFirst) window.scrollTo(0, 0);
  }, [askFirst, query]);
  useEffect(() => {
    if (!part || askFirst) return;
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
  }, [part, askFirst]);
}
