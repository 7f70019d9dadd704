import { useLayoutEffect, useState, type RefObject } from 'react';

/**
 * The element's content width in CSS pixels (ResizeObserver), `fallback` before the first
 * measurement. SVG figures use it as their viewBox width so that one user unit is one CSS pixel:
 * labels and handles keep their size on a phone instead of shrinking with the figure.
 */
export function useWidth(ref: RefObject<Element | null>, fallback: number): number {
  const [w, setW] = useState(fallback);
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) return;
    const measure = () => {
      const x = Math.round(el.getBoundingClientRect().width);
      if (x > 0) setW((old) => (Math.abs(old - x) >= 1 ? x : old));
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [ref]);
  return w;
}
