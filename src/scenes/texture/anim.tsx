/**
 * The texture scene's animation, kept out of the scene component: the timeline lives in
 * <TimelineDriver> (which renders the transport) and publishes its position to a small store.
 * Per animation frame nothing re-renders in React: the moving SVG nodes (the grid's query and
 * stencil, the value-along-path marker, the reconstruction's crosses) are written directly by
 * frame listeners (`useAnimFrame`), while the figures themselves re-render only when the position
 * changes while paused (`useStillT`: pause, step, seek). The text readouts beside the grid are
 * written the same way (their text at most TEXT_HZ times a second while playing, so a screen reader
 * is not flooded; exact on pause), and their notes render only while paused; the
 * worked steps (KaTeX) hold the position where playing started and catch up on pause (`useWorkedT`):
 * typesetting them costs several frames' worth of time at once, so none of it happens mid-play.
 */
import { useLayoutEffect, useRef, useSyncExternalStore, type ReactNode, type RefObject } from 'react';
import { TEXT_HZ, TimelineTransport, useTimeline, useTimelineFrame, type Timeline } from '../../ui';
import { drawnLookup, frameAt, type Frame, type Lookup, type QueryPath } from './model';
import type { GridSource } from './model';
import type { LookupOptions, TextureGrid } from '../../core/texture';

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
/**
 * The worked steps' position: while playing, the position where it started (`still`: KaTeX is not
 * re-typeset mid-play, a typeset costs more than a frame); exact when paused.
 */
export function workedPosition(t: number, playing: boolean, still: number): number {
  return playing ? still : t;
}

export interface TimelineStore {
  /** The latest timeline (for its actions: reset from a drag, etc.); null before the driver mounted. */
  readonly timeline: () => Timeline | null;
  readonly t: () => number;
  readonly playing: () => boolean;
  readonly tWorked: () => number;
  /** The position the figures are rendered at: follows t while paused, held while playing. */
  readonly tStill: () => number;
  /** The live position (every frame). */
  readonly tLive: () => number;
  /** Whether the timeline is playing, as of its latest frame. */
  readonly livePlaying: () => boolean;
  readonly publish: (tl: Timeline) => void;
  readonly subscribe: (fn: () => void) => () => void;
  /** Per-frame position from the timeline (the driver calls it). */
  readonly frame: (t: number, playing?: boolean) => void;
  readonly subscribeFrame: (fn: (t: number) => void) => () => void;
}

export function createTimelineStore(t0: number): TimelineStore {
  let tl: Timeline | null = null;
  let t = Number.isFinite(t0) ? Math.min(1, Math.max(0, t0)) : 0;
  let playing = false;
  let still = t;
  let live = t;
  let livePlaying = false;
  const listeners = new Set<() => void>();
  const frameListeners = new Set<(t: number) => void>();
  return {
    timeline: () => tl,
    t: () => t,
    playing: () => playing,
    tWorked: () => workedPosition(t, playing, still),
    tStill: () => still,
    tLive: () => live,
    livePlaying: () => livePlaying,
    publish: (next) => {
      tl = next;
      if (next.t === t && next.playing === playing) return;
      t = next.t;
      playing = next.playing;
      if (!playing) still = t;
      for (const fn of listeners) fn();
    },
    subscribe: (fn) => {
      listeners.add(fn);
      return () => listeners.delete(fn);
    },
    frame: (x, p) => {
      live = x;
      if (p !== undefined) livePlaying = p;
      for (const fn of frameListeners) fn(x);
    },
    subscribeFrame: (fn) => {
      frameListeners.add(fn);
      return () => frameListeners.delete(fn);
    },
  };
}

/** Everything the animated parts need besides t; memoized by the scene on its params (not on t). */
export interface AnimContext {
  store: TimelineStore;
  grid: TextureGrid;
  opts: LookupOptions;
  src: GridSource;
  /** The drawn path (follows a drag). */
  path: QueryPath;
  /** The committed path (the worked steps follow it). */
  committedPath: QueryPath;
  /** The query at position t of `path`, and its drawn (addressed) lookup; cached for the last t. */
  frame: (t: number) => { frame: Frame; dq: Lookup };
  /** The query at position t of `committedPath`; cached for the last t. */
  worked: (t: number) => Frame;
}

export function animContext(
  store: TimelineStore,
  grid: TextureGrid,
  opts: LookupOptions,
  src: GridSource,
  path: QueryPath,
  committedPath: QueryPath,
): AnimContext {
  let ft = NaN;
  let fv: { frame: Frame; dq: Lookup } | null = null;
  let wt = NaN;
  let wv: Frame | null = null;
  return {
    store,
    grid,
    opts,
    src,
    path,
    committedPath,
    frame: (t) => {
      if (fv === null || t !== ft) {
        const frame = frameAt(grid, opts, path, t);
        fv = { frame, dq: drawnLookup(grid, frame.u, frame.v, opts) };
        ft = t;
      }
      return fv;
    },
    worked: (t) => {
      if (wv === null || t !== wt) {
        wv = frameAt(grid, opts, committedPath, t);
        wt = t;
      }
      return wv;
    },
  };
}

/** The figures' position: changes only while paused (pause, step, seek, a link); frames draw through useAnimFrame. */
export function useStillT(store: TimelineStore): number {
  return useSyncExternalStore(store.subscribe, store.tStill);
}

/**
 * Draw the moving parts at the live position: on every frame, and after each render of the caller
 * (so a parameter change while playing does not show the held position for a frame). `draw` should
 * write the DOM directly. Its second argument says whether text should be written too: always
 * while paused, at most TEXT_HZ times a second while playing (numbers that change every frame are
 * unreadable, and readouts are live regions).
 */
export function useAnimFrame(store: TimelineStore, draw: (t: number, text: boolean) => void): void {
  const ref = useRef(draw);
  ref.current = draw;
  const lastText = useRef(-Infinity);
  useLayoutEffect(
    () =>
      store.subscribeFrame((t) => {
        const now = performance.now();
        const text = !store.livePlaying() || now - lastText.current >= 1000 / TEXT_HZ - 1;
        if (text) lastText.current = now;
        ref.current(t, text);
      }),
    [store],
  );
  useLayoutEffect(() => {
    ref.current(store.tLive(), true);
  });
}

/** Whether the timeline plays (re-renders the caller on play and pause only). */
export function usePlaying(store: TimelineStore): boolean {
  return useSyncExternalStore(store.subscribe, store.playing);
}

/** The worked steps' position (held while playing: re-renders the caller on pause, step, seek). */
export function useWorkedT(store: TimelineStore): number {
  return useSyncExternalStore(store.subscribe, store.tWorked);
}

const formatT = (t: number) => `t = ${t.toFixed(2)}`;

/** Owns the timeline (the only component re-rendered by the hook itself) and its transport. */
export function TimelineDriver({
  store,
  t,
  play,
  setParams,
  visibleRef,
  children,
}: {
  store: TimelineStore;
  t: number;
  play: boolean;
  setParams: (patch: { t?: number; play?: boolean }) => void;
  visibleRef: RefObject<Element | null>;
  children?: ReactNode;
}) {
  const tl = useTimeline({
    t,
    play,
    setParams,
    max: 1,
    duration: DURATION,
    stepSize: STEP,
    visibleRef,
    renderHz: RENDER_HZ,
  });
  useLayoutEffect(() => store.publish(tl), [store, tl]);
  useTimelineFrame(tl, store.frame);
  return (
    <TimelineTransport timeline={tl} label="Query path" format={formatT}>
      {children}
    </TimelineTransport>
  );
}
