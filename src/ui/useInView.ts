import { useEffect, useState, type RefObject } from 'react';

/**
 * True once the element has come within `margin` of the viewport (sticky: stays true), so heavy
 * work (drawing a plot, loading three.js) waits until a view that needs it is about to be seen.
 */
export function useSeenOnce(ref: RefObject<Element | null>, margin = '200px'): boolean {
  const [seen, setSeen] = useState(false);
  useEffect(() => {
    if (seen) return;
    const el = ref.current;
    if (!el) return;
    if (typeof IntersectionObserver !== 'function') {
      setSeen(true);
      return;
    }
    const io = new IntersectionObserver(
      (entries) => {
        if (entries.some((e) => e.isIntersecting)) {
          setSeen(true);
          io.disconnect();
        }
      },
      { rootMargin: margin },
    );
    io.observe(el);
    return () => io.disconnect();
  }, [ref, margin, seen]);
  return seen;
}

/**
 * Live visibility (not sticky): used to pause rendering while a view is off screen (`margin`: how
 * far outside the viewport still counts, as IntersectionObserver's rootMargin).
 */
export function observeVisibility(
  el: Element,
  onChange: (visible: boolean) => void,
  margin = '0px',
): () => void {
  if (typeof IntersectionObserver !== 'function') {
    onChange(true);
    return () => {};
  }
  const io = new IntersectionObserver(
    (entries) => {
      for (const e of entries) onChange(e.isIntersecting);
    },
    { rootMargin: margin },
  );
  io.observe(el);
  return () => io.disconnect();
}

/**
 * True on a touch-only device (a phone or tablet: no hover, a coarse pointer). Such devices get
 * lighter defaults: no plot tool buttons, and 3D views that start when asked (src/three/Viewport).
 */
export function touchOnly(): boolean {
  return (
    typeof window !== 'undefined' &&
    typeof window.matchMedia === 'function' &&
    window.matchMedia('(hover: none) and (pointer: coarse)').matches
  );
}
