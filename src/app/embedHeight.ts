import { useEffect } from 'react';

/**
 * Message a host page receives from an embedded scene:
 * `{ type: 'render-math-lab:height', height, scene }` (the scene id, or null off a scene). Nothing
 * else: the page's URL and parameters go only to a host that asks through the host API.
 */
export const HEIGHT_MESSAGE = 'render-math-lab:height';

/** The height of the page's content: the app root's bottom edge (not the viewport-filling document). */
export function contentHeight(): number {
  const root = document.getElementById('root') ?? document.body;
  const rect = root.getBoundingClientRect();
  const body = getComputedStyle(document.body);
  return Math.ceil(
    rect.bottom +
      window.scrollY +
      (parseFloat(body.paddingBottom) || 0) +
      (parseFloat(body.marginBottom) || 0),
  );
}

/**
 * In an iframe, post the content's height to the parent whenever it changes (growing or
 * shrinking), so the host can size the iframe (README, "Embed a scene"). With `origin=` the
 * message goes only to those origins (to none when it names no usable one).
 */
export function usePostHeight(
  active: boolean,
  sceneId: string | null,
  origins: readonly string[] | null = null,
): void {
  useEffect(() => {
    // `origin=` with no usable origin: nobody is told anything
    if (!active || window.parent === window || (origins && origins.length === 0)) return;
    let last = -1;
    let raf = 0;
    const post = () => {
      raf = 0;
      const h = contentHeight();
      if (h === last) return;
      last = h;
      const msg = { type: HEIGHT_MESSAGE, height: h, scene: sceneId };
      if (origins) for (const o of origins) window.parent.postMessage(msg, o);
      else window.parent.postMessage(msg, '*');
    };
    const schedule = () => {
      if (!raf) raf = requestAnimationFrame(post);
    };
    const ro = new ResizeObserver(schedule);
    const root = document.getElementById('root');
    if (root) ro.observe(root);
    ro.observe(document.body);
    schedule();
    return () => {
      ro.disconnect();
      if (raf) cancelAnimationFrame(raf);
    };
  }, [active, sceneId, origins]);
}
