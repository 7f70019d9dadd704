import { useEffect, useState, type RefObject } from 'react';

/**
 * The element's width in CSS pixels (border box, rounded), `fallback` until the first
 * measurement. SVG figures use it as their viewBox width so that one user unit is one CSS pixel:
 * labels and handles keep their size on a phone instead of shrinking with the figure.
 *
 * Measured only by a ResizeObserver, never by reading the layout in an effect: on a page's first
 * commit such a read forced the layout of the whole page inside React's commit, one long task on a
 * phone. The observer reports after the browser's own layout; the new width is drawn in
 * the next frame (applying it inside the observer's callback would resize observed boxes in the
 * same frame: "ResizeObserver loop completed with undelivered notifications"). The figures that
 * use it have a fixed height, so that first frame shifts nothing.
 */
export function useWidth(ref: RefObject<Element | null>, fallback: number): number {
  const [w, setW] = useState(fallback);
  useEffect(() => {
    const el = ref.current;
    if (!el || typeof ResizeObserver !== 'function') return;
    const ro = new ResizeObserver((entries) => {
      const e = entries[entries.length - 1];
      const x = Math.round(e.borderBoxSize?.[0]?.inlineSize ?? e.contentRect.width);
      if (x > 0) setW((old) => (Math.abs(old - x) >= 1 ? x : old));
    });
    ro.observe(el);
    return () => ro.disconnect();
  }, [ref]);
  return w;
}
