/**
 * The texture scene's animation settings and the frame cache its animated parts share. The wiring
 * is the shared one (ui/animation): the timeline lives in an <AnimationDriver> (which renders the
 * transport) and publishes to a store. Per animation frame nothing re-renders in React: the moving
 * SVG nodes (the grid's query and stencil, the value-along-path marker, the reconstruction's
 * crosses) are written directly by frame listeners (`useAnimFrame`), while the figures themselves
 * re-render only when the position changes while paused (`useStillT`: pause, step, seek). The text
 * readouts beside the grid are written the same way (their text at most TEXT_HZ times a second
 * while playing, so a screen reader is not flooded; exact on pause), and their notes render only
 * while paused; the worked steps (KaTeX) and the answer under them follow the moving query at the
 * text rate, each position typeset ahead (in the KaTeX worker) so the formula and its answer
 * change in one render (../exam/shared: useShownFrame).
 */
import { lastValue, type AnimationStore } from '../../../ui';
import { drawnLookup, type GridSource, type Lookup } from '../model';
import { frameAt, type Frame, type QueryPath } from '../path';
import type { LookupOptions, TextureGrid } from '../../../core/texture';

/** Seconds for one pass along the path at 1×. */
export const DURATION = 8;
/** Step size of the timeline. */
export const STEP = 0.05;

/**
 * React renders while playing: none (renderHz 0). Everything that moves (the figures, the readouts
 * beside the grid, the transport's position) is written by frame subscribers; React renders again
 * on pause, step, seek and reset, at the exact position.
 */
export const RENDER_HZ = 0;

/** The transport's position text. */
export const formatT = (t: number) => `t = ${t.toFixed(2)}`;

/** Everything the animated parts need besides t; memoized by the scene on its params (not on t). */
export interface AnimContext {
  store: AnimationStore;
  grid: TextureGrid;
  opts: LookupOptions;
  src: GridSource;
  /** The drawn path (follows a drag). */
  path: QueryPath;
  /** A handle is being dragged (the path follows the pointer, not yet the URL). */
  dragging: boolean;
  /** The query at position t of `path`, and its drawn (addressed) lookup; cached for the last t. */
  frame: (t: number) => { frame: Frame; dq: Lookup };
}

export function animContext(
  store: AnimationStore,
  grid: TextureGrid,
  opts: LookupOptions,
  src: GridSource,
  path: QueryPath,
  dragging = false,
): AnimContext {
  return {
    store,
    grid,
    opts,
    src,
    path,
    dragging,
    frame: lastValue((t) => {
      const frame = frameAt(grid, opts, path, t);
      return { frame, dq: drawnLookup(grid, frame.u, frame.v, opts) };
    }),
  };
}
