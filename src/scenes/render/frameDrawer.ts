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
