/**
 * Tab stops for formula boxes that scroll. A formula wider than its box (`.deriv-formula`, which
 * scrolls sideways) must be reachable from the keyboard; a formula that fits is no tab stop (a
 * derivation is read, not operated: dozens of focusable formulas would bury the page's controls).
 * The boxes are measured again whenever the container or a box resizes (a narrower window, a
 * typeset formula replacing its placeholder).
 */
import { useEffect, type RefObject } from 'react';

/** Gives every `.deriv-formula` box under `root` a tab stop exactly while its content overflows it. */
export function focusOverflowing(root: ParentNode): void {
  for (const box of root.querySelectorAll<HTMLElement>('.deriv-formula')) {
    const scrolls = box.scrollWidth > box.clientWidth + 1;
    if (scrolls !== box.hasAttribute('tabindex')) {
      if (scrolls) box.setAttribute('tabindex', '0');
      else box.removeAttribute('tabindex');
    }
  }
}

/** Keeps the formula boxes under `ref` focusable while (and only while) they scroll; `key` names their content. */
export function useScrollBoxFocus(ref: RefObject<HTMLElement | null>, key: unknown): void {
  useEffect(() => {
    const root = ref.current;
    if (!root) return;
    focusOverflowing(root);
    if (typeof ResizeObserver === 'undefined') return;
    const ro = new ResizeObserver(() => focusOverflowing(root));
    ro.observe(root);
    for (const box of root.querySelectorAll('.deriv-formula')) ro.observe(box);
    return () => ro.disconnect();
  }, [ref, key]);
}
