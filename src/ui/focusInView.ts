/**
 * Keeps the element that has just received focus in view while the page settles around it.
 *
 * The browser scrolls a focused element into view once, as focus moves. A part of the page above
 * it may change height a moment later: a derivation drawn only once it nears the screen
 * (content-visibility: auto holds an estimated height for it until then), a formula typeset, a
 * view loaded. The focused element can then leave the screen under a keyboard user's eyes (WCAG
 * 2.4.11, focus not obscured). So for a short while after each focus change, whenever the page's
 * height changes, a focused element that is no longer in view is brought back by the least scroll
 * (block 'nearest', which honours the page's scroll-padding: the sticky header and the controls
 * drawer). Only a focus change made with Tab counts (a click, or a key that acts, such as Enter
 * on a preset that scrolls to its part, may mean to move the page), and any other key, a
 * pointer, a wheel or a touch hands the page back to the reader at once.
 */

/** How the focused element sits against the visible band of the page (all in CSS px). */
export interface FocusBox {
  top: number;
  bottom: number;
  /** The viewport's height. */
  viewport: number;
  /** The page's scroll-padding: the bands that sticky bars cover. */
  padTop: number;
  padBottom: number;
}

/**
 * Whether the focused element needs scrolling back: none of it is in the band between the sticky
 * bars. (An element taller than the band, or partly in it, is left where it is: the reader sees it.)
 */
export function outOfView({ top, bottom, viewport, padTop, padBottom }: FocusBox): boolean {
  if (!(bottom > top)) return false; // not rendered (display: none) or no box
  return bottom <= padTop || top >= viewport - padBottom;
}

const px = (v: string) => {
  const n = parseFloat(v);
  return Number.isFinite(n) ? n : 0;
};

/** Start keeping focus in view on `doc` for `settleMs` after each focus change; returns the stop. */
export function keepFocusInView(doc: Document = document, settleMs = 1500): () => void {
  const win = doc.defaultView;
  if (!win || typeof ResizeObserver !== 'function') return () => {};
  let target: Element | null = null;
  let until = 0;
  let tabbing = false;
  const onKey = (e: KeyboardEvent) => {
    tabbing = e.key === 'Tab';
    if (!tabbing) target = null;
  };
  const onFocus = (e: FocusEvent) => {
    target = tabbing && e.target instanceof Element ? e.target : null;
    tabbing = false;
    until = performance.now() + settleMs;
  };
  const release = () => {
    tabbing = false;
    target = null;
  };
  const check = () => {
    const el = target;
    if (!el || doc.activeElement !== el || performance.now() > until || !el.isConnected) return;
    const r = el.getBoundingClientRect();
    const cs = win.getComputedStyle(doc.documentElement);
    const box = {
      top: r.top,
      bottom: r.bottom,
      viewport: doc.documentElement.clientHeight,
      padTop: px(cs.scrollPaddingTop),
      padBottom: px(cs.scrollPaddingBottom),
    };
    if (outOfView(box)) el.scrollIntoView({ block: 'nearest' });
  };
  const ro = new ResizeObserver(check);
  ro.observe(doc.body);
  doc.addEventListener('keydown', onKey, true);
  doc.addEventListener('focusin', onFocus);
  doc.addEventListener('pointerdown', release, true);
  win.addEventListener('wheel', release, { passive: true });
  win.addEventListener('touchstart', release, { passive: true });
  return () => {
    ro.disconnect();
    doc.removeEventListener('keydown', onKey, true);
    doc.removeEventListener('focusin', onFocus);
    doc.removeEventListener('pointerdown', release, true);
    win.removeEventListener('wheel', release);
    win.removeEventListener('touchstart', release);
  };
}
