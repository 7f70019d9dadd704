/**
 * The slide's highlight: an outline (class `deck-highlight`) around the element of the slide whose
 * `data-testid` the slide names, found again whenever the scene redraws it.
 */
import { useEffect, type RefObject } from 'react';

export function useHighlight(root: RefObject<HTMLElement | null>, testId: string | undefined): void {
  useEffect(() => {
    const el = root.current;
    if (!el || !testId) return;
    const selector = `[data-testid="${CSS.escape(testId)}"]`;
    let marked: Element | null = null;
    const mark = () => {
      const found = el.querySelector(selector);
      if (found === marked) return;
      marked?.classList.remove('deck-highlight');
      found?.classList.add('deck-highlight');
      marked = found;
    };
    mark();
    const mo = new MutationObserver(mark);
    mo.observe(el, { childList: true, subtree: true });
    return () => {
      mo.disconnect();
      marked?.classList.remove('deck-highlight');
    };
  }, [root, testId]);
}
