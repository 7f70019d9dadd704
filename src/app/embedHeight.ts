import { useEffect } from 'react';

/** Message a host page receives from an embedded scene: `{ type: 'render-math-lab:height', height }`. */
export const HEIGHT_MESSAGE = 'render-math-lab:height';

/**
 * In an iframe, post the document's height to the parent whenever it changes, so the host can
 * size the iframe (see README, "Embedding a scene").
 */
export function usePostHeight(active: boolean): void {
  useEffect(() => {
    if (!active || window.parent === window) return;
    let last = -1;
    let raf = 0;
    const post = () => {
      raf = 0;
      const h = Math.ceil(document.documentElement.scrollHeight);
      if (h === last) return;
      last = h;
      window.parent.postMessage({ type: HEIGHT_MESSAGE, height: h, href: window.location.href }, '*');
    };
    const schedule = () => {
      if (!raf) raf = requestAnimationFrame(post);
    };
    const ro = new ResizeObserver(schedule);
    ro.observe(document.body);
    schedule();
    return () => {
      ro.disconnect();
      if (raf) cancelAnimationFrame(raf);
    };
  }, [active]);
}
