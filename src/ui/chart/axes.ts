/**
 * The axes of a chart: their extent in axis units (log10 of the value on a log axis), the mapping
 * to pixels, and round ticks with labels that never overlap. Pure, no DOM.
 */
import { niceTicks, pow10Text, tickLabel } from '../axis';

export type AxisKind = 'linear' | 'log';

export interface Tick {
  /** Position in px along the figure (x from the left, y from the top). */
  px: number;
  label: string;
  /** A 2 or 5 between decades on a log axis (drawn smaller, no grid line). */
  minor?: boolean;
}

export interface Axis {
  kind: AxisKind;
  /** The ends in axis units (log10 on a log axis), lo < hi. */
  lo: number;
  hi: number;
  /** The pixels the ends map to (px0 ↔ lo); px0 > px1 for a y axis or a reversed x axis. */
  px0: number;
  px1: number;
  ticks: Tick[];
}

/** Axis units of a data value: the value, or its log10 on a log axis (NaN where a log axis cannot show it). */
export function toUnits(kind: AxisKind, v: number | null | undefined): number {
  if (v === null || v === undefined || !Number.isFinite(v)) return NaN;
  if (kind === 'log') return v > 0 ? Math.log10(v) : NaN;
  return v;
}

/** The data value of axis units u. */
export function fromUnits(kind: AxisKind, u: number): number {
  return kind === 'log' ? 10 ** u : u;
}

/** Pixel of axis units u on the axis (finite for finite u). */
export function unitsToPx(a: Pick<Axis, 'lo' | 'hi' | 'px0' | 'px1'>, u: number): number {
  return a.px0 + ((u - a.lo) / (a.hi - a.lo)) * (a.px1 - a.px0);
}

/** Axis units at pixel p. */
export function pxToUnits(a: Pick<Axis, 'lo' | 'hi' | 'px0' | 'px1'>, p: number): number {
  return a.lo + ((p - a.px0) / (a.px1 - a.px0)) * (a.hi - a.lo);
}

/**
 * The range [lo, hi] (axis units) that shows the extents `ext` (already in axis units) with
 * `pad` of the span added at each free end; `zeroFloor` keeps an end at exactly 0 when the data
 * start there (bars stand on 0). An empty extent gives [0, 1]; a single value a unit (or a
 * decade) around it.
 */
export function autoRange(
  ext: readonly [number, number] | null,
  kind: AxisKind,
  pad: number,
  zeroFloor = false,
): [number, number] {
  if (!ext) return [0, 1];
  let [lo, hi] = ext;
  if (!(hi > lo)) {
    if (zeroFloor && kind === 'linear' && lo === 0) return [0, 1];
    const half = kind === 'log' ? 0.5 : lo === 0 ? 1 : Math.abs(lo) * 0.1;
    return [lo - half, hi + half];
  }
  const span = hi - lo;
  const floorAtZero = zeroFloor && kind === 'linear' && lo === 0;
  if (!floorAtZero) lo -= span * pad;
  hi += span * pad;
  return [lo, hi];
}

/** Whether labels at these pixel positions, of these widths (along the axis), leave `gap` px between neighbours. */
function fits(px: readonly number[], widths: readonly number[], gap: number): boolean {
  for (let k = 1; k < px.length; k++)
    if (Math.abs(px[k] - px[k - 1]) < (widths[k] + widths[k - 1]) / 2 + gap) return false;
  return true;
}

/** The decades labelled on a log axis with `per` decades between labels. */
const DECADE_STEPS = [1, 2, 3, 5, 10, 20, 50, 100];

/**
 * How a log axis with decades e0 … e1 writes 10^e: plainly ("0.01", "10000") when every decade
 * lies in 0.01 … 1000, or in 1 … 10000 (counts), and as a power of ten ("10⁻³", "10⁶") otherwise:
 * one axis never mixes the two ways.
 */
export function decadeLabel(e: number, e0: number, e1: number): string {
  const plain = (e0 >= -2 && e1 <= 3) || (e0 >= 0 && e1 <= 4);
  if (!plain) return pow10Text(e);
  return e >= 0 ? String(10 ** e) : `0.${'0'.repeat(-e - 1)}1`;
}

/**
 * Ticks for the axis's range: on a linear axis round steps (1, 2, 5 × 10ⁿ); on a log axis the
 * decades (with 2 and 5 between them where there is room, or every second, third… decade where
 * there is not), falling back to round linear steps inside a range of less than a decade. The
 * count follows the axis's length in px (`spacing` px per tick at most), thinned until the
 * labels (`measure` gives a label's extent along the axis) no longer overlap.
 */
export function makeTicks(
  a: Omit<Axis, 'ticks'>,
  spacing: number,
  measure: (label: string) => number,
): Tick[] {
  const len = Math.abs(a.px1 - a.px0);
  const ok = (t: Tick[]) =>
    fits(
      t.map((x) => x.px),
      t.map((x) => measure(x.label)),
      6,
    );
  const inside = (u: number) => u >= a.lo - 1e-9 * (a.hi - a.lo) && u <= a.hi + 1e-9 * (a.hi - a.lo);
  const at = (u: number, label: string, minor = false): Tick =>
    minor ? { px: unitsToPx(a, u), label, minor } : { px: unitsToPx(a, u), label };

  if (a.kind === 'log' && a.hi - a.lo >= 1) {
    const e0 = Math.ceil(a.lo - 1e-9);
    const e1 = Math.floor(a.hi + 1e-9);
    const label = (e: number) => decadeLabel(e, e0, e1);
    const decades = (per: number) => {
      const out: Tick[] = [];
      for (let e = Math.ceil(e0 / per) * per; e <= e1; e += per) out.push(at(e, label(e)));
      return out;
    };
    // 1, 2, 5 in each decade when a decade is long enough for three labels
    if ((len / (a.hi - a.lo)) * 0.3 >= spacing * 0.6) {
      const out: Tick[] = [];
      for (let e = e0 - 1; e <= e1; e++)
        for (const m of [1, 2, 5]) {
          const u = e + Math.log10(m);
          if (inside(u)) out.push(at(u, m === 1 ? label(e) : String(m), m !== 1));
        }
      if (ok(out)) return out;
    }
    for (const per of DECADE_STEPS) {
      const out = decades(per);
      if (out.length <= Math.max(2, len / spacing + 1) && ok(out)) return out;
    }
    return decades(DECADE_STEPS[DECADE_STEPS.length - 1]);
  }

  // linear steps, in values (a log axis shorter than a decade places them at their log10)
  const vlo = a.kind === 'log' ? 10 ** a.lo : a.lo;
  const vhi = a.kind === 'log' ? 10 ** a.hi : a.hi;
  for (let count = Math.max(2, Math.floor(len / spacing)); count >= 2; count--) {
    const { ticks, step } = niceTicks(vlo, vhi, count);
    const out = ticks
      .map((v) => ({ u: a.kind === 'log' ? Math.log10(v) : v, v }))
      .filter(({ u }) => Number.isFinite(u) && inside(u))
      .map(({ u, v }) => at(u, tickLabel(v, step)));
    if (ok(out)) return out;
  }
  // too short for two labels: the one nearest the middle
  const { ticks, step } = niceTicks(vlo, vhi, 1);
  const mid = (a.lo + a.hi) / 2;
  const best = ticks
    .map((v) => ({ u: a.kind === 'log' ? Math.log10(v) : v, v }))
    .filter(({ u }) => Number.isFinite(u) && inside(u))
    .sort((p, q) => Math.abs(p.u - mid) - Math.abs(q.u - mid))[0];
  return best ? [at(best.u, tickLabel(best.v, step))] : [];
}
