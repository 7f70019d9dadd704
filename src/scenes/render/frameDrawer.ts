/**
 * The progressive render's drawing: at most once per animation frame however many passes arrive,
 * and, when the run stops, the whole image once more if its last frame had not come yet. A run that
 * has finished is not started again (./useProgressiveRender.ts), so a frame cancelled after the last
 * pass (the canvas left the screen, the page moved on) would otherwise leave the canvas and the
 * readouts one pass short for good. A run stopped before it is whole draws nothing more: it starts
 * again from its first pass when it may run.
 */

/** Frame scheduling (the page's requestAnimationFrame; a fake clock in tests). */
export interface FrameClock {
  request: (cb: () => void) => number;
  cancel: (id: number) => void;
}

export const ANIMATION_FRAMES: FrameClock = {
  request: (cb) => requestAnimationFrame(cb),
  cancel: (id) => cancelAnimationFrame(id),
};

export interface FrameDrawer {
  /** New samples arrived: draw at the next frame (once, however many arrive before it). */
  schedule: () => void;
  /** The last pass has arrived: the image is whole; draw it at the next frame. */
  complete: () => void;
  /** The run stops: no more frames; a whole image not drawn yet is drawn now. */
  stop: () => void;
}

export function frameDrawer(draw: () => void, clock: FrameClock = ANIMATION_FRAMES): FrameDrawer {
  let frame = 0;
  let whole = false;
  const schedule = () => {
    if (frame) return;
    frame = clock.request(() => {
      frame = 0;
      draw();
    });
  };
  return {
    schedule,
    complete: () => {
      whole = true;
      schedule();
    },
    stop: () => {
      if (!frame) return;
      clock.cancel(frame);
      frame = 0;
      if (whole) draw();
    },
  };
}

/**
 * The readouts under the image (samples per pixel, mean, relMSE, speed) are React state: each
 * update re-renders them and costs main-thread time that the canvas, drawn every frame, does not.
 * `show` runs at most once per `intervalMs` while a run goes on; `last()` marks the run whole (the
 * next `frame()` shows, whatever the time); `flush()` shows what a skipped frame left unshown (a run
 * stopped between two readouts).
 */
export interface ReadoutGate {
  /** A frame was drawn: show the readouts if the interval has passed or the run is whole. */
  frame: () => void;
  /** The run is whole: the next frame shows its readouts. */
  last: () => void;
  /** Show now if a frame has been drawn since the readouts were last shown. */
  flush: () => void;
}

export function readoutGate(
  show: () => void,
  intervalMs: number,
  now: () => number = () => performance.now(),
): ReadoutGate {
  let shownAt = -Infinity;
  let stale = false;
  let whole = false;
  const fire = () => {
    stale = false;
    shownAt = now();
    show();
  };
  return {
    frame: () => {
      if (whole || now() - shownAt >= intervalMs) fire();
      else stale = true;
    },
    last: () => {
      whole = true;
    },
    flush: () => {
      if (stale) fire();
    },
  };
}
