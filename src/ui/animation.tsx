/**
 * Animation wiring for scenes, on top of the shared timeline (./timeline). What moves every frame
 * never goes through React state; React renders only what must be exact (on pause, step, seek) or
 * what can follow at a readable rate.
 *
 * - The frame path: `createAnimationStore` + `<AnimationDriver>` (or `useAnimationDriver` where the
 *   scene owns the timeline itself). The driver owns the timeline and publishes it to the store, so
 *   the scene component does not re-render when the timeline plays, pauses or moves. Parts that
 *   move draw themselves with `useAnimFrame(store, draw)`: `draw(t, text)` runs on every frame
 *   and after each render, and writes the DOM directly; `text` says whether text may change too
 *   (always when paused, at most TEXT_HZ a second while playing: numbers that change every frame
 *   cannot be read, and readouts are live regions).
 * - The still position: `useStillT(store)` is the position while paused and the position where
 *   playing started while it plays. Expensive views (figures re-rendered by React, KaTeX worked
 *   steps) render at it, so no frame carries their cost; they catch up on pause. `usePlaying(store)`
 *   re-renders on play and pause only.
 * - Values: `useThrottled(value, ms, immediate)` changes at most every `ms` (leading and trailing
 *   edges; at once when `immediate`), for React readouts fed by fast partial results;
 *   `useHeldWhile(value, hold)` keeps the value it had when `hold` began (while playing, while
 *   dragging); `lastValue(f)` remembers f's last argument and result (the figures and the scene
 *   often ask for the same t in one frame).
 * - Auto-run of worker jobs when a panel is first seen: `useAutoRun` in ../workers.
 */
import { useEffect, useLayoutEffect, useRef, useState, useSyncExternalStore, type ReactNode } from 'react';
import { TEXT_HZ, useTimeline, useTimelineFrame, type Timeline, type TimelineOptions } from './timeline';
import { TimelineTransport } from './TimelineTransport';

/**
 * What the animated parts read: the published timeline (React-paced) and the live frames.
 * `t` and `playing` change on every publish; `tStill` only while paused.
 */
export interface AnimationStore {
  /** The latest timeline (for its actions: reset from a drag, etc.); null before the driver mounted. */
  readonly timeline: () => Timeline | null;
  /** The position the timeline last rendered with. */
  readonly t: () => number;
  readonly playing: () => boolean;
  /** The still position: follows t while paused, held at the position where playing started. */
  readonly tStill: () => number;
  /** The live position (every frame). */
  readonly tLive: () => number;
  /** Whether the timeline is playing, as of its latest frame. */
  readonly livePlaying: () => boolean;
  /** A timeline render (the driver calls it); listeners hear of a change of t or playing. */
  readonly publish: (tl: Timeline) => void;
  readonly subscribe: (fn: () => void) => () => void;
  /** A frame's position (the driver calls it). */
  readonly frame: (t: number, playing?: boolean) => void;
  readonly subscribeFrame: (fn: (t: number) => void) => () => void;
}

/** The still position from the published state (pure; `still` is where playing started). */
export function heldPosition(t: number, playing: boolean, still: number): number {
  return playing ? still : t;
}

/** A store starting at `t0` (clamped into [0, max]; not finite: 0). */
export function createAnimationStore(t0: number, max = 1): AnimationStore {
  let tl: Timeline | null = null;
  let t = Number.isFinite(t0) ? Math.min(max, Math.max(0, t0)) : 0;
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
    tStill: () => heldPosition(t, playing, still),
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

/** Publish a timeline to a store: its renders (after commit) and every frame. */
export function useAnimationDriver(store: AnimationStore, tl: Timeline): void {
  useLayoutEffect(() => store.publish(tl), [store, tl]);
  useTimelineFrame(tl, store.frame);
}

export interface AnimationDriverProps extends TimelineOptions {
  store: AnimationStore;
  /** The transport's accessible name. */
  label: string;
  /** The transport's position text. */
  format?: (t: number) => string;
  /** Extra controls inside the transport. */
  children?: ReactNode;
}

/**
 * Owns the timeline (the only component the timeline itself re-renders) and its transport, and
 * publishes it to `store`.
 */
export function AnimationDriver({ store, label, format, children, ...timeline }: AnimationDriverProps) {
  const tl = useTimeline(timeline);
  useAnimationDriver(store, tl);
  return (
    <TimelineTransport timeline={tl} label={label} format={format}>
      {children}
    </TimelineTransport>
  );
}

/** The still position (re-renders the caller on pause, step, seek; not while playing). */
export function useStillT(store: AnimationStore): number {
  return useSyncExternalStore(store.subscribe, store.tStill);
}

/** Whether the timeline plays (re-renders the caller on play and pause only). */
export function usePlaying(store: AnimationStore): boolean {
  return useSyncExternalStore(store.subscribe, store.playing);
}

/**
 * Whether a frame at time `now` (ms) may change text: always while paused, while playing at most
 * `hz` times a second.
 */
export function textGate(hz: number): (playing: boolean, now: number) => boolean {
  let last = -Infinity;
  return (playing, now) => {
    const ok = !playing || now - last >= 1000 / hz - 1;
    if (ok) last = now;
    return ok;
  };
}

/**
 * Draw the moving parts at the live position: on every frame, and after each render of the caller
 * (so a parameter change while playing does not show the held position for a frame). `draw` should
 * write the DOM directly; `text` is true always while paused and at most TEXT_HZ times a second
 * while playing. `draw` may change identity between renders; the latest one is used.
 */
export function useAnimFrame(store: AnimationStore, draw: (t: number, text: boolean) => void): void {
  const ref = useRef(draw);
  ref.current = draw;
  useLayoutEffect(() => {
    const text = textGate(TEXT_HZ);
    return store.subscribeFrame((t) => ref.current(t, text(store.livePlaying(), performance.now())));
  }, [store]);
  useLayoutEffect(() => {
    ref.current(store.tLive(), true);
  });
}

/** A clock for `createThrottle` (tests pass a fake one). */
export interface ThrottleClock {
  now: () => number;
  setTimeout: (fn: () => void, ms: number) => unknown;
  clearTimeout: (id: unknown) => void;
}

const realClock: ThrottleClock = {
  now: () => performance.now(),
  setTimeout: (fn, ms) => setTimeout(fn, ms),
  clearTimeout: (id) => clearTimeout(id as ReturnType<typeof setTimeout>),
};

export interface Throttle<T> {
  /** A new value: shown now if `ms` have passed since the last one shown (or `immediate`), else at that time. */
  push: (value: T, immediate?: boolean) => void;
  /** Drop a pending value. */
  dispose: () => void;
}

/**
 * Calls `show` with the values pushed, at most once per `ms`: leading edge (a value after a quiet
 * `ms` is shown at once) and trailing edge (the latest value is shown `ms` after the previous one).
 */
export function createThrottle<T>(
  ms: number,
  show: (v: T) => void,
  clock: ThrottleClock = realClock,
): Throttle<T> {
  let last = 0;
  let timer: unknown;
  let pending = false;
  let latest: T;
  const cancel = () => {
    if (pending) clock.clearTimeout(timer);
    pending = false;
  };
  return {
    push: (value, immediate = false) => {
      latest = value;
      const now = clock.now();
      if (immediate || now - last >= ms) {
        cancel();
        last = now;
        show(value);
      } else if (!pending) {
        pending = true;
        timer = clock.setTimeout(
          () => {
            pending = false;
            last = clock.now();
            show(latest);
          },
          ms - (now - last),
        );
      }
    },
    dispose: cancel,
  };
}

/**
 * `value`, changing at most once per `ms` (leading and trailing edges: the latest value is shown
 * `ms` after the previous change), and at once when `immediate` (e.g. the final result of a run).
 */
export function useThrottled<T>(value: T, ms: number, immediate = false): T {
  const [shown, setShown] = useState(value);
  const throttle = useRef<{ ms: number; th: Throttle<T> } | null>(null);
  useEffect(() => {
    let t = throttle.current;
    if (!t || t.ms !== ms) {
      t?.th.dispose();
      t = throttle.current = { ms, th: createThrottle<T>(ms, setShown) };
    }
    t.th.push(value, immediate);
  }, [value, ms, immediate]);
  useEffect(() => () => throttle.current?.th.dispose(), []);
  return shown;
}

/** `value`, except while `hold` is true: then the value it had when holding began. */
export function useHeldWhile<T>(value: T, hold: boolean): T {
  const ref = useRef(value);
  if (!hold) ref.current = value;
  return ref.current;
}

/** `f`, remembering its last argument and result. */
export function lastValue<T>(f: (t: number) => T): (t: number) => T {
  let at = NaN;
  let v: T | undefined;
  let has = false;
  return (t) => {
    if (!has || t !== at) {
      v = f(t);
      at = t;
      has = true;
    }
    return v as T;
  };
}
