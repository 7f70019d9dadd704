/**
 * The one guard every hand-drawn SVG chart uses between data and attributes: scales that map any
 * double (NaN, ±∞, subnormal, past the largest double) to a finite coordinate, and a coordinate writer that
 * never writes "NaN" or "Infinity". A degenerate domain (equal ends, non-finite ends, a span that
 * overflows) maps to the middle of the range instead of dividing by zero.
 */
import { formatFixed } from '../core/format';

/** No coordinate leaves ±this (far outside any chart; SVG clips it, the browser parses it). */
export const COORD_LIMIT = 1e6;

export type Scale = (v: number) => number;

/** A finite coordinate: NaN becomes `fallback`, ±∞ and huge values are clamped to ±COORD_LIMIT. */
export function coord(v: number, fallback = 0): number {
  if (Number.isNaN(v)) return Number.isFinite(fallback) ? clampCoord(fallback) : 0;
  return clampCoord(v);
}

function clampCoord(v: number): number {
  return v > COORD_LIMIT ? COORD_LIMIT : v < -COORD_LIMIT ? -COORD_LIMIT : v;
}

/** `coord(v)` written with `digits` decimals, for an SVG attribute or path. */
export function coordText(v: number, digits = 1, fallback = 0): string {
  return formatFixed(coord(v, fallback), digits);
}

/**
 * d0 → r0, d1 → r1, linearly; any input gives a finite output (NaN: the range's middle). The span
 * is computed on halves when d1 − d0 overflows, so domains up to ±MAX_VALUE work.
 */
export function linearScale(d0: number, d1: number, r0: number, r1: number): Scale {
  const mid = (r0 + r1) / 2;
  if (!Number.isFinite(d0) || !Number.isFinite(d1) || !Number.isFinite(r0) || !Number.isFinite(r1))
    return () => coord(mid, 0);
  const h0 = d0 / 2;
  const span = d1 / 2 - h0; // halves: never overflows
  if (!(span !== 0)) return () => coord(mid);
  const dr = r1 - r0;
  return (v) => {
    if (Number.isNaN(v)) return coord(mid);
    const f = (v / 2 - h0) / span; // v = ±∞ gives ±∞, clamped below
    return coord(r0 + f * dr, mid);
  };
}

const LOG_MIN = Math.log10(Number.MIN_VALUE); // ≈ −323.3: the smallest subnormal
const LOG_MAX = Math.log10(Number.MAX_VALUE); // ≈ 308.25

/** log10 that is finite for every positive double and reads 0 or less as the smallest one. */
export function safeLog10(v: number): number {
  if (Number.isNaN(v)) return NaN;
  if (!(v > 0)) return LOG_MIN;
  if (v === Infinity) return LOG_MAX;
  return Math.log10(v);
}

/**
 * d0 → r0, d1 → r1 on log10 axes; any input gives a finite output: values ≤ 0 (and subnormals that
 * round to 0) sit at the smallest double's position, NaN at the range's middle.
 */
export function logScale(d0: number, d1: number, r0: number, r1: number): Scale {
  const lin = linearScale(safeLog10(d0), safeLog10(d1), r0, r1);
  return (v) => lin(safeLog10(v));
}

/** The exponent e with 10^e representable and > 0 (e ≥ −323), for log axes' decade ticks. */
export function clampExponent(e: number): number {
  if (!Number.isFinite(e)) return e > 0 ? 308 : -323;
  return Math.max(-323, Math.min(308, e));
}
