/**
 * The shared animation timeline: one implementation of play / pause / step / reset / speed / loop /
 * scrub for every scene.
 *
 * The position `t` is state like any other scene parameter: it lives in the scene's URL parameters
 * (`t`, and `play=1` while playing), so a link reopens the animation at the same moment. What a scene
 * draws at position t must be a pure function of its parameters, its seed and t (the scene's model
 * computes it; the view only draws it). While playing, the position advances once per animation
 * frame; subscribers (`timeline.subscribe`, `useTimelineFrame`) get every frame's position, and
 * React state (`timeline.t`) follows every frame too unless the scene passes `renderHz`: then React
 * re-renders at most that often while playing (and exactly on pause, step, reset and seek), and
 * the scene draws the moving parts itself from a frame subscription (direct DOM / canvas writes),
 * which keeps React's reconciliation out of the per-frame path. The transport's scrubber and
 * position text follow every frame through such a subscription. The URL is written when the
 * animation pauses, is stepped, reset or scrubbed, not per frame.
 *
 * Nothing is requested from requestAnimationFrame while the timeline is paused, while its element
 * is off screen, or while the tab is hidden. `prefers-reduced-motion: reduce` starts it paused and
 * ignores `play=1` from a link (the Play button still works: that is the user's own choice).
 *
 * The URL parameters and the pure arithmetic of playing are in src/kit/timeline.ts.
 */
import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState, type RefObject } from 'react';
import { advance, clampPosition, openingPosition, positionShown } from '../kit/timeline';
import { useShortcuts } from './shortcuts';

/**
 * With `renderHz`, React re-renders at most every this many frames while playing: at 60 frames a
 * second that is 3 Hz; on a slow or throttled machine (10–20 frames a second) the text then updates
 * every 1–2 s and at most one frame in 20 carries React's work (the goal is on the 95th percentile).
 */
const RENDER_MIN_FRAMES = 20;

/**
 * How often text that follows a playing timeline by direct writes (the transport's position text,
 * a scene's readouts) changes, at most: numbers that change every frame cannot be read, and
 * readouts are live regions. Exact whenever the timeline is paused.
 */
export const TEXT_HZ = 4;

export function prefersReducedMotion(): boolean {
  return (
    typeof window !== 'undefined' &&
    typeof window.matchMedia === 'function' &&
    window.matchMedia('(prefers-reduced-motion: reduce)').matches
  );
}

export interface TimelineOptions {
  /** The position from the URL (the scene's `t` parameter). */
  t: number;
  /** `play` from the URL. */
  play: boolean;
  /** The scene's setParams: the timeline writes `t` and `play` through it. */
  setParams: (patch: { t?: number; play?: boolean }) => void;
  /** End of the timeline: 1 for a 0…1 timeline, N for a sample index. */
  max: number;
  /** Positions are whole steps (e.g. a sample index); the visible position is floor(t). */
  integer?: boolean;
  /** Seconds from 0 to max at 1× speed. */
  duration: number;
  /** What "step" adds (default: 1 for integer timelines, max/100 otherwise). */
  stepSize?: number;
  /** Start over at 0 after the end (default false). The transport has a toggle. */
  loop?: boolean;
  /** The element whose visibility gates frames: no frames while it is off screen. */
  visibleRef?: RefObject<Element | null>;
  /** Register Space (play/pause) and s (step) as classroom shortcuts (default true). */
  shortcuts?: boolean;
  /**
   * While playing, update React state (`t`) at most this many times a second (subscribers still get
   * every frame); exact on pause / step / reset / seek. 0: not at all while playing (everything
   * that moves is drawn by frame subscribers). Default: every frame.
   */
  renderHz?: number;
}

/** A frame subscriber: the visible position (integer timelines: floored) and whether it is playing. */
export type TimelineListener = (t: number, playing: boolean) => void;

export interface Timeline {
  /** Current position (integer timelines: a whole number). */
  t: number;
  max: number;
  integer: boolean;
  playing: boolean;
  speed: number;
  loop: boolean;
  stepSize: number;
  play: () => void;
  pause: () => void;
  toggle: () => void;
  /** Pause and move one step forward. */
  step: () => void;
  /** Pause at position 0. */
  reset: () => void;
  /** Move to a position (keeps playing if playing). */
  seek: (t: number) => void;
  setSpeed: (s: number) => void;
  setLoop: (loop: boolean) => void;
  /**
   * Called with the position on every animation frame while playing and on every change of the
   * position or of playing (after React committed it); returns the unsubscribe function. Listeners
   * are called once on subscribe too.
   */
  subscribe: (fn: TimelineListener) => () => void;
  /** The live position (ahead of `t` between React renders when `renderHz` is set). */
  now: () => number;
}

/**
 * The position at a coarse rate: re-renders only the calling component, at most `hz` times a
 * second (and at most every RENDER_MIN_FRAMES frames) while playing, and on every change while
 * paused (exact on pause, step, seek, reset). For text that follows an animation whose owner does
 * not re-render while playing (`renderHz: 0`).
 */
export function useCoarsePosition(tl: Pick<Timeline, 'subscribe' | 'now'>, hz: number): number {
  const [t, setT] = useState(tl.now);
  const last = useRef({ at: -Infinity, frames: Infinity });
  useTimelineFrame(tl, (x, playing) => {
    const l = last.current;
    l.frames++;
    const now = typeof performance === 'undefined' ? Date.now() : performance.now();
    if (!playing || (now - l.at >= 1000 / hz - 1 && l.frames >= RENDER_MIN_FRAMES)) {
      l.at = now;
      l.frames = 0;
      setT(x);
    }
  });
  return t;
}

/**
 * Run `draw(t, playing)` on every frame of the timeline and whenever its position or state changes
 * (subscribed in a layout effect, so the first draw happens before paint). `draw` may change
 * identity between renders; the latest one is used. Keep it cheap: direct DOM / canvas writes.
 */
export function useTimelineFrame(tl: Pick<Timeline, 'subscribe'> | null, draw: TimelineListener): void {
  const ref = useRef(draw);
  ref.current = draw;
  const sub = tl?.subscribe;
  useLayoutEffect(() => (sub ? sub((t, p) => ref.current(t, p)) : undefined), [sub]);
}

/** Scroll `el` into view when none of it is in the window. */
function scrollIntoViewIfAway(el: Element | null | undefined): void {
  if (!el) return;
  const r = el.getBoundingClientRect();
  if (r.bottom <= 0 || r.top >= window.innerHeight) el.scrollIntoView({ block: 'nearest' });
}

/** The timeline hook: see the module comment. */
export function useTimeline(opts: TimelineOptions): Timeline {
  const { max, duration, setParams } = opts;
  const integer = !!opts.integer;
  const stepSize = opts.stepSize ?? (integer ? 1 : max / 100);
  const [opening] = useState(() => {
    const play = opts.play && !prefersReducedMotion();
    return { play, t: openingPosition(opts.t, max, integer, play) };
  });
  const [exact, setExactState] = useState(opening.t);
  const [playing, setPlaying] = useState(opening.play);
  const [speed, setSpeed] = useState(1);
  const [loop, setLoop] = useState(!!opts.loop);

  // live values for the frame loop and callbacks (`exact` runs ahead of React state while playing
  // with renderHz; setExact keeps both in step)
  const current = { playing, speed, loop, max, integer, duration, setParams, renderHz: opts.renderHz };
  const live = useRef({ exact, ...current });
  live.current = { ...live.current, ...current };
  const setExact = useCallback((next: number | ((e: number) => number)) => {
    const v = typeof next === 'function' ? next(live.current.exact) : next;
    live.current.exact = v;
    setExactState(v);
  }, []);

  // frame subscribers
  const listeners = useRef(new Set<TimelineListener>());
  const notify = useCallback(() => {
    const l = live.current;
    const t = positionShown(l.exact, l.integer);
    for (const fn of listeners.current) fn(t, l.playing);
  }, []);
  const subscribe = useCallback((fn: TimelineListener) => {
    listeners.current.add(fn);
    const l = live.current;
    fn(positionShown(l.exact, l.integer), l.playing);
    return () => {
      listeners.current.delete(fn);
    };
  }, []);
  const now = useCallback(() => {
    const l = live.current;
    return positionShown(l.exact, l.integer);
  }, []);
  // every committed change (pause, step, seek, a coarse render while playing) reaches the subscribers
  useLayoutEffect(() => {
    live.current.playing = playing;
    notify();
  }, [exact, playing, max, integer, notify]);

  // what we last wrote to the URL, so external changes (hashchange, host API) can be told apart
  const written = useRef({ t: clampPosition(opts.t, max, integer), play: opts.play });

  // external change of `t` (hashchange, host API seek, the scene's "opening state" reset)
  useEffect(() => {
    const t = clampPosition(opts.t, max, integer);
    if (t !== written.current.t) {
      written.current.t = t;
      setExact(t);
    }
  }, [opts.t, max, integer, setExact]);
  // external change of `play`
  // (a host page's pause must also leave the paused position in the URL, as the Pause button does)
  useEffect(() => {
    if (opts.play === written.current.play) return;
    written.current.play = opts.play;
    const l = live.current;
    if (opts.play) {
      if (prefersReducedMotion()) return;
      if (l.exact >= l.max) setExact(0); // play from the start after the end
      setPlaying(true);
    } else if (l.playing) {
      l.playing = false; // at once: no frame may move past the position written below
      setPlaying(false);
      setExact(l.exact);
      const t = positionShown(l.exact, l.integer);
      written.current.t = t;
      l.setParams({ t });
    }
  }, [opts.play, setExact]);
  // a shorter timeline (e.g. fewer samples) clamps the position
  useEffect(() => {
    setExact((e) => clampPosition(e, max, false));
  }, [max, setExact]);

  const write = useCallback((patch: { t?: number; play?: boolean }) => {
    if (patch.t !== undefined) written.current.t = patch.t;
    if (patch.play !== undefined) written.current.play = patch.play;
    live.current.setParams(patch);
  }, []);

  const stepSizeRef = useRef(stepSize);
  stepSizeRef.current = stepSize;

  const shown = (e: number) => positionShown(e, live.current.integer);

  const pause = useCallback(() => {
    // at once, not at React's next render: a frame that runs before that render must not move
    // the position past the one paused at (and written to the link)
    live.current.playing = false;
    setPlaying(false);
    setExact(live.current.exact); // React state catches up with a position that ran ahead (renderHz)
    write({ t: shown(live.current.exact), play: false });
  }, [write, setExact]);
  const play = useCallback(() => {
    let start = live.current.exact;
    if (start >= live.current.max) start = 0; // play from the start after the end
    setExact(start);
    setPlaying(true);
    write({ t: shown(start), play: true });
  }, [write, setExact]);
  const toggle = useCallback(() => (live.current.playing ? pause() : play()), [pause, play]);
  const seek = useCallback(
    (t: number) => {
      const c = clampPosition(t, live.current.max, live.current.integer);
      setExact(c);
      write({ t: c });
    },
    [write, setExact],
  );
  const step = useCallback(() => {
    const l = live.current;
    let next = positionShown(l.exact, l.integer) + stepSizeRef.current;
    if (next > l.max) next = l.loop ? 0 : l.max;
    next = clampPosition(next, l.max, l.integer);
    live.current.playing = false;
    setPlaying(false);
    setExact(next);
    write({ t: next, play: false });
  }, [write, setExact]);
  const reset = useCallback(() => {
    live.current.playing = false;
    setPlaying(false);
    setExact(0);
    write({ t: 0, play: false });
  }, [write, setExact]);

  // the frame loop: only while playing, on screen and in a visible tab
  const visibleRef = opts.visibleRef;
  const [onScreen, setOnScreen] = useState(true);
  const [tabVisible, setTabVisible] = useState(
    () => typeof document === 'undefined' || document.visibilityState !== 'hidden',
  );
  useEffect(() => {
    const on = () => setTabVisible(document.visibilityState !== 'hidden');
    document.addEventListener('visibilitychange', on);
    return () => document.removeEventListener('visibilitychange', on);
  }, []);
  // The element may mount after the timeline (inside a section that mounts late, ui/Deferred), so
  // it is looked for again after each render and on each frame, and observed once it is there.
  const observed = useRef<{ el: Element | null; io: IntersectionObserver | null }>({ el: null, io: null });
  const ensureObserved = useCallback(() => {
    const o = observed.current;
    const el = visibleRef?.current ?? null;
    if (el === o.el || typeof IntersectionObserver === 'undefined') return;
    o.io?.disconnect();
    o.el = el;
    o.io = null;
    if (!el) {
      setOnScreen(true); // nothing to watch: the timeline runs
      return;
    }
    o.io = new IntersectionObserver((entries) => {
      for (const e of entries) setOnScreen(e.isIntersecting);
    });
    o.io.observe(el);
  }, [visibleRef]);
  useEffect(() => {
    ensureObserved();
  });
  useEffect(
    () => () => {
      observed.current.io?.disconnect();
      observed.current = { el: null, io: null };
    },
    [ensureObserved],
  );

  useEffect(() => {
    if (!playing || !onScreen || !tabVisible) return;
    let raf = 0;
    let last = -1;
    let rendered = -Infinity;
    let sinceRender = Infinity;
    const frame = (now: number) => {
      raf = 0;
      const l = live.current;
      if (!l.playing) return;
      ensureObserved();
      const dt = last < 0 ? 0 : Math.min(100, now - last); // a long gap (e.g. a stall) does not jump
      last = now;
      const { t, ended } = advance(l.exact, dt, {
        max: l.max,
        duration: l.duration,
        speed: l.speed,
        loop: l.loop,
      });
      if (ended) {
        setExact(t);
        setPlaying(false);
        write({ t: shown(t), play: false });
        return;
      }
      const hz = l.renderHz;
      sinceRender++;
      // coarse React renders: at most renderHz a second, and (on a slow machine, where frames are
      // far apart) at most every RENDER_MIN_FRAMES frames, so most frames stay free of React
      if (
        hz === undefined ||
        (hz > 0 && now - rendered >= 1000 / hz - 1 && sinceRender >= RENDER_MIN_FRAMES)
      ) {
        rendered = now;
        sinceRender = 0;
        setExact(t); // the layout effect tells the subscribers after React committed
      } else {
        l.exact = t;
        notify();
      }
      raf = requestAnimationFrame(frame);
    };
    raf = requestAnimationFrame(frame);
    return () => {
      if (raf) cancelAnimationFrame(raf);
    };
  }, [playing, onScreen, tabVisible, write, setExact, notify, ensureObserved]);

  // the classroom's Space plays what the room sees: an animation off screen comes into view first
  // (it runs only while on screen)
  const playPause = useCallback(() => {
    if (!live.current.playing) scrollIntoViewIfAway(visibleRef?.current);
    toggle();
  }, [toggle, visibleRef]);
  useShortcuts(opts.shortcuts === false ? {} : { playPause, step });

  const t = positionShown(exact, integer);
  return useMemo(
    () => ({
      t,
      max,
      integer,
      playing,
      speed,
      loop,
      stepSize,
      play,
      pause,
      toggle,
      step,
      reset,
      seek,
      setSpeed,
      setLoop,
      subscribe,
      now,
    }),
    [t, max, integer, playing, speed, loop, stepSize, play, pause, toggle, step, reset, seek, subscribe, now],
  );
}
