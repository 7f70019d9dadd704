/**
 * The texture scene's animation, kept out of the scene component: the timeline lives in
 * <TimelineDriver> (which renders the transport) and publishes its position to a small store;
 * only the components that draw the moving query subscribe to it (the grid's query and stencil,
 * the value-along-path marker, the readouts, the reconstruction's cross, and — at the timeline's
 * step resolution while playing — the worked steps). A frame therefore re-renders those parts
 * only, never the scene with its controls, derivations of the sphere and the memoized images.
 */
import { useLayoutEffect, useSyncExternalStore, type ReactNode, type RefObject } from 'react';
import { TimelineTransport, useTimeline, type Timeline } from '../../ui';
import { drawnLookup, frameAt, type Frame, type Lookup, type QueryPath } from './model';
import type { GridSource } from './model';
import type { LookupOptions, TextureGrid } from '../../core/texture';

/** Seconds for one pass along the path at 1×. */
export const DURATION = 8;
/** Step size of the timeline; while playing, the worked steps (KaTeX) follow at this resolution. */
export const STEP = 0.05;

/** The worked steps' position: the timeline's step while playing (so KaTeX is redrawn per step, not per frame), exact when paused. */
export function workedPosition(t: number, playing: boolean): number {
  return playing ? Math.floor(t / STEP + 1e-9) * STEP : t;
}

export interface TimelineStore {
  /** The latest timeline (for its actions: reset from a drag, etc.); null before the driver mounted. */
  readonly timeline: () => Timeline | null;
  readonly t: () => number;
  readonly playing: () => boolean;
  readonly tWorked: () => number;
  readonly publish: (tl: Timeline) => void;
  readonly subscribe: (fn: () => void) => () => void;
}

export function createTimelineStore(t0: number): TimelineStore {
  let tl: Timeline | null = null;
  let t = Number.isFinite(t0) ? Math.min(1, Math.max(0, t0)) : 0;
  let playing = false;
  const listeners = new Set<() => void>();
  return {
    timeline: () => tl,
    t: () => t,
    playing: () => playing,
    tWorked: () => workedPosition(t, playing),
    publish: (next) => {
      tl = next;
      if (next.t === t && next.playing === playing) return;
      t = next.t;
      playing = next.playing;
      for (const fn of listeners) fn();
    },
    subscribe: (fn) => {
      listeners.add(fn);
      return () => listeners.delete(fn);
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

/** The current position (re-renders the caller each frame while playing). */
export function useAnimT(store: TimelineStore): number {
  return useSyncExternalStore(store.subscribe, store.t);
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
  const tl = useTimeline({ t, play, setParams, max: 1, duration: DURATION, stepSize: STEP, visibleRef });
  useLayoutEffect(() => store.publish(tl), [store, tl]);
  return (
    <TimelineTransport timeline={tl} label="Query path" format={formatT}>
      {children}
    </TimelineTransport>
  );
}
