/**
 * Tab stops for formula boxes that scroll. A formula wider than its box (`.deriv-formula`, which
 * scrolls sideways) must be reachable from the keyboard; a formula that fits is no tab stop (a
 * derivation is read, not operated: dozens of focusable formulas would bury the page's controls).
 * The boxes are measured again whenever the container or a box resizes (a narrower window, a
 * typeset formula replacing its placeholder).
 */
import { useEffect, type RefObject } from 'react';

/**
 * Gives every `.deriv-formula` box under `root` a tab stop exactly while its content overflows it.
 * Every box is measured first and changed after: a change between two measurements would make the
 * browser lay the page out again for the next one (once per box).
 */
export function focusOverflowing(root: ParentNode): void {
  const boxes = [...root.querySelectorAll<HTMLElement>('.deriv-formula')];
  const scrolls = boxes.map((box) => box.scrollWidth > box.clientWidth + 1);
  boxes.forEach((box, i) => {
    if (scrolls[i] === box.hasAttribute('tabindex')) return;
    if (scrolls[i]) box.setAttribute('tabindex', '0');
    else box.removeAttribute('tabindex');
  });
}

/** Keeps the formula boxes under `ref` focusable while (and only while) they scroll; `key` names their content. */
export function useScrollBoxFocus(ref: RefObject<HTMLElement | null>, key: unknown): void {
  useEffect(() => {
    const root = ref.current;
    if (!root) return;
    if (typeof ResizeObserver === 'undefined') {
      focusOverflowing(root);
      return;
    }
    // a ResizeObserver reports every box it is given once, after the next layout: the first
    // measurement waits for it rather than forcing a layout of the page from this effect
    const ro = new ResizeObserver(() => focusOverflowing(root));
    ro.observe(root);
    for (const box of root.querySelectorAll('.deriv-formula')) ro.observe(box);
    return () => ro.disconnect();
  }, [ref, key]);
}
