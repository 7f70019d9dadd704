/**
 * The texture scene's animation, kept out of the scene component: the timeline lives in
 * <TimelineDriver> (which renders the transport) and publishes its position to a small store.
 * Per animation frame nothing re-renders in React: the moving SVG nodes (the grid's query and
 * stencil, the value-along-path marker, the reconstruction's crosses) are written directly by
 * frame listeners (`useAnimFrame`), while the figures themselves re-render only when the position
 * changes while paused (`useStillT`: pause, step, seek). The text readouts follow the timeline's
 * coarse position (`useAnimT`, RENDER_HZ times a second while playing, exact on pause) and the
 * worked steps (KaTeX) a coarser one still (`useWorkedT`).
 */
import { useLayoutEffect, useRef, useSyncExternalStore, type ReactNode, type RefObject } from 'react';
import { TimelineTransport, useTimeline, useTimelineFrame, type Timeline } from '../../ui';
import { drawnLookup, frameAt, type Frame, type Lookup, type QueryPath } from './model';
import type { GridSource } from './model';
import type { LookupOptions, TextureGrid } from '../../core/texture';

/** Seconds for one pass along the path at 1×. */
export const DURATION = 8;
/** Step size of the timeline; while playing, the worked steps (KaTeX) follow at this resolution. */
export const STEP = 0.05;

/** How often React re-renders the text readouts while playing (the figures move every frame without React). */
export const RENDER_HZ = 4;
/** While playing, the worked steps (KaTeX) follow the position in steps of this size (2 s at 1×); exact when paused. */
export const WORKED_STEP = 0.25;

/** The worked steps' position: coarse while playing (so KaTeX is redrawn every 2 s at 1×, not per frame), exact when paused. */
export function workedPosition(t: number, playing: boolean): number {
  return playing ? Math.floor(t / WORKED_STEP + 1e-9) * WORKED_STEP : t;
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
  readonly publish: (tl: Timeline) => void;
  readonly subscribe: (fn: () => void) => () => void;
  /** Per-frame position from the timeline (the driver calls it). */
  readonly frame: (t: number) => void;
  readonly subscribeFrame: (fn: (t: number) => void) => () => void;
}

export function createTimelineStore(t0: number): TimelineStore {
  let tl: Timeline | null = null;
  let t = Number.isFinite(t0) ? Math.min(1, Math.max(0, t0)) : 0;
  let playing = false;
  let still = t;
  let live = t;
  const listeners = new Set<() => void>();
  const frameListeners = new Set<(t: number) => void>();
  return {
    timeline: () => tl,
    t: () => t,
    playing: () => playing,
    tWorked: () => workedPosition(t, playing),
    tStill: () => still,
    tLive: () => live,
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
    frame: (x) => {
      live = x;
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

export function animContext(store: TimelineStore, grid: TextureGrid, opts: LookupOptions, src: GridSource, path: QueryPath, committedPath: QueryPath): AnimContext {
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

/** The coarse position (re-renders the caller RENDER_HZ times a second while playing; exact when paused). */
export function useAnimT(store: TimelineStore): number {
  return useSyncExternalStore(store.subscribe, store.t);
}

/** The figures' position: changes only while paused (pause, step, seek, a link); frames draw through useAnimFrame. */
export function useStillT(store: TimelineStore): number {
  return useSyncExternalStore(store.subscribe, store.tStill);
}

/**
 * Draw the moving parts at the live position: on every frame, and after each render of the caller
 * (so a parameter change while playing does not show the held position for a frame). `draw` should
 * write the DOM directly.
 */
export function useAnimFrame(store: TimelineStore, draw: (t: number) => void): void {
  const ref = useRef(draw);
  ref.current = draw;
  useLayoutEffect(() => store.subscribeFrame((t) => ref.current(t)), [store]);
  useLayoutEffect(() => {
    ref.current(store.tLive());
  });
}

/** The worked steps' position (re-renders the caller once per timeline step while playing). */
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
  const tl = useTimeline({ t, play, setParams, max: 1, duration: DURATION, stepSize: STEP, visibleRef, renderHz: RENDER_HZ });
  useLayoutEffect(() => store.publish(tl), [store, tl]);
  useTimelineFrame(tl, store.frame);
  return (
    <TimelineTransport timeline={tl} label="Query path" format={formatT}>
      {children}
    </TimelineTransport>
  );
}
