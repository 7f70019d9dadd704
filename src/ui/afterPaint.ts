/**
 * Resolves once the browser has painted the frame in progress (the next animation frame, then a
 * task). Work that the first paint does not need (the KaTeX worker and stylesheet, the service
 * worker) waits for it, so a phone does not download and run it before the page's first content is
 * on screen (Lighthouse's LCP counts everything started before that paint). A hidden page
 * paints no frames: there it resolves after a task, and a timer makes sure it always resolves.
 */
export function afterPaint(): Promise<void> {
  return new Promise<void>((resolve) => {
    let done = false;
    const go = () => {
      if (done) return;
      done = true;
      resolve();
    };
    const visible = typeof document === 'undefined' || document.visibilityState !== 'hidden';
    if (visible && typeof requestAnimationFrame === 'function')
      requestAnimationFrame(() => setTimeout(go, 0));
    setTimeout(go, visible ? 1000 : 0);
  });
}
