/**
 * The timeline's URL contract and arithmetic, shared by every animated scene: the `t` / `play`
 * parameters a scene spreads into its schema, and the pure maths of playing (advance by elapsed
 * time at a speed, loop or stop at the end), clamping and the opening position of a link. No React
 * and no DOM: a scene's params.ts imports this, and the React hook in src/ui/timeline.ts drives it.
 */
import type { ParamSpec } from './params';

/** The position a timeline shows: integer timelines show whole steps (floored, allowing for rounding). */
export function positionShown(exact: number, integer: boolean): number {
  return integer ? Math.floor(exact + 1e-9) : exact;
}

/** Speeds offered by the transport (× the scene's natural speed). */
export const TIMELINE_SPEEDS = [0.25, 0.5, 1, 2, 4] as const;

/**
 * URL parameters of a timeline, to spread into a scene's schema:
 * `t` (position, 0…max) and `play` (0/1).
 */
export function timelineParams(opts: { max: number; default?: number; integer?: boolean }): {
  t: Extract<ParamSpec, { kind: 'number' }>;
  play: Extract<ParamSpec, { kind: 'bool' }>;
} {
  return {
    t: {
      kind: 'number',
      default: opts.default ?? 0,
      min: 0,
      max: opts.max,
      integer: opts.integer,
      label: 'animation position',
    },
    play: { kind: 'bool', default: false, label: 'animation playing' },
  };
}

/** Position after `dtMs` milliseconds of playing at `speed` (pure; exported for tests). */
export function advance(
  t: number,
  dtMs: number,
  opts: { max: number; duration: number; speed: number; loop: boolean },
): { t: number; ended: boolean } {
  const rate = opts.max / Math.max(opts.duration, 1e-3); // position units per second at 1×
  let next = t + (dtMs / 1000) * rate * opts.speed;
  if (!(next < opts.max)) {
    if (opts.loop && opts.max > 0) {
      next = next % opts.max;
      return { t: next, ended: false };
    }
    return { t: opts.max, ended: true };
  }
  return { t: Math.max(0, next), ended: false };
}

/** Clamp (and round, for integer timelines) a position into [0, max]; NaN → 0. */
export function clampPosition(t: number, max: number, integer: boolean): number {
  if (!Number.isFinite(t)) return 0;
  const c = Math.min(max, Math.max(0, t));
  return integer ? Math.round(c) : c;
}

/**
 * Where a link opens the animation: `t` clamped; but a link that asks to play (`play=1`) from the
 * end (e.g. a scene whose default `t` is the finished figure) plays from the start, as the Play
 * button does after the end. One rule for every scene.
 */
export function openingPosition(t: number, max: number, integer: boolean, playing: boolean): number {
  const c = clampPosition(t, max, integer);
  return playing && c >= max ? 0 : c;
}
