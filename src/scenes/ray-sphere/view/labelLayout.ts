/**
 * Where the cross-section's labels and handles go so that no handle covers a label and no label
 * covers a marker: a few candidate places around each anchor, scored by what they would overlap.
 * Pure geometry in figure pixels (y down), no DOM, unit-tested.
 */

export type Pt = readonly [number, number];

/** An axis-aligned box: left, top, width, height (figure pixels). */
export interface Box {
  x: number;
  y: number;
  w: number;
  h: number;
}

/** The box of a disc (a handle's hit area, a marker) of radius `r` about `p`. */
export const discBox = (p: Pt, r: number): Box => ({ x: p[0] - r, y: p[1] - r, w: 2 * r, h: 2 * r });

/** The area two boxes share (0 when apart). */
export function overlapArea(a: Box, b: Box): number {
  const w = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
  const h = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

/**
 * The part of the segment p–q inside the box (Liang–Barsky), or null when none is: lines are
 * drawn only where they can be seen, so their boxes stay within the figure.
 */
export function clipSegment(p: Pt, q: Pt, b: Box): [Pt, Pt] | null {
  let t0 = 0;
  let t1 = 1;
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  const edges: [number, number][] = [
    [-dx, p[0] - b.x],
    [dx, b.x + b.w - p[0]],
    [-dy, p[1] - b.y],
    [dy, b.y + b.h - p[1]],
  ];
  for (const [pp, qq] of edges) {
    if (pp === 0) {
      if (qq < 0) return null;
      continue;
    }
    const r = qq / pp;
    if (pp < 0) t0 = Math.max(t0, r);
    else t1 = Math.min(t1, r);
    if (t0 > t1) return null;
  }
  return [
    [p[0] + t0 * dx, p[1] + t0 * dy],
    [p[0] + t1 * dx, p[1] + t1 * dy],
  ];
}

/** Does the segment from p to q pass through the box? */
export const segmentHitsBox = (p: Pt, q: Pt, b: Box): boolean => clipSegment(p, q, b) !== null;

/** Distance from p to the segment a–b. */
export function distToSegment(p: Pt, a: Pt, b: Pt): number {
  const vx = b[0] - a[0];
  const vy = b[1] - a[1];
  const L2 = vx * vx + vy * vy;
  const k = L2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * vx + (p[1] - a[1]) * vy) / L2)) : 0;
  return Math.hypot(p[0] - a[0] - k * vx, p[1] - a[1] - k * vy);
}

/** Eight directions as signs (x right, y down), east first then anticlockwise on screen. */
const DIRS: Pt[] = [
  [1, 0],
  [1, -1],
  [0, -1],
  [-1, -1],
  [-1, 0],
  [-1, 1],
  [0, 1],
  [1, 1],
];

/**
 * The box of a w × h label put in direction `dir` (signs) from `anchor`, `gap` away along each
 * axis it moves on and centred on the others: to the east its left edge is `gap` right of the
 * anchor, to the north-east its bottom-left corner is `gap` right of and above it, and so on; so a
 * square of half-side `gap` about the anchor stays clear.
 */
export function boxAt(anchor: Pt, dir: Pt, gap: number, w: number, h: number): Box {
  const cx = anchor[0] + dir[0] * (gap + w / 2);
  const cy = anchor[1] + dir[1] * (gap + h / 2);
  return { x: cx - w / 2, y: cy - h / 2, w, h };
}

export interface LabelRequest {
  anchor: Pt;
  /** Distance from the anchor to the label's nearest edge. */
  gap: number;
  w: number;
  h: number;
  /** Direction indices (0 = east, 1 = north-east, … anticlockwise) tried first, in order. */
  prefer?: readonly number[];
}

export interface Scene {
  W: number;
  H: number;
  /** Boxes nothing may cover: handles, markers. */
  hard: Box[];
  /** Lines a label should rather not cross (the ray, the direction arrow). */
  lines: [Pt, Pt][];
}

/** Cost of a candidate box: overlaps first, then leaving the figure, then crossing lines. */
function cost(b: Box, s: Scene, placed: Box[]): number {
  let c = 0;
  for (const o of s.hard) c += 1000 * overlapArea(b, o);
  for (const o of placed) c += 1000 * overlapArea(b, o);
  const out =
    Math.max(0, -b.x) * b.h +
    Math.max(0, b.x + b.w - s.W) * b.h +
    Math.max(0, -b.y) * b.w +
    Math.max(0, b.y + b.h - s.H) * b.w;
  c += 1000 * out;
  for (const [p, q] of s.lines) if (segmentHitsBox(p, q, b)) c += 50;
  return c;
}

/**
 * Places each label in turn (earlier requests win): the cheapest of eight directions at the
 * request's gap, then at twice the gap; ties go to the preferred order. Every label placed becomes
 * an obstacle for the next.
 */
export function placeLabels(reqs: readonly LabelRequest[], s: Scene): Box[] {
  const placed: Box[] = [];
  for (const r of reqs) {
    const order = [...(r.prefer ?? []), ...DIRS.keys()].filter((v, i, a) => a.indexOf(v) === i);
    let best: Box | null = null;
    let bestCost = Infinity;
    for (const gap of [r.gap, 2 * r.gap]) {
      for (let k = 0; k < order.length; k++) {
        const b = boxAt(r.anchor, DIRS[order[k]], gap, r.w, r.h);
        // a small tie-break keeps the preferred direction and the near gap when all else is equal
        const c = cost(b, s, placed) + k * 0.01 + (gap > r.gap ? 1 : 0);
        if (c < bestCost) {
          bestCost = c;
          best = b;
        }
      }
      if (bestCost < 1) break;
    }
    placed.push(best!);
  }
  return placed;
}

/**
 * The first of `candidates` (handle positions) at least `clear` pixels from every obstacle point
 * and line, keeping `keep` (the index used last time) while it still is; else the one farthest
 * from them. Lets a handle step aside from a marker without jumping around needlessly.
 */
export function pickClear(
  candidates: readonly Pt[],
  points: readonly Pt[],
  lines: readonly [Pt, Pt][],
  clear: number,
  keep: number | null,
): number {
  const room = (p: Pt) =>
    Math.min(
      Infinity,
      ...points.map((q) => Math.hypot(p[0] - q[0], p[1] - q[1])),
      ...lines.map(([a, b]) => distToSegment(p, a, b)),
    );
  if (keep !== null && keep < candidates.length && room(candidates[keep]) >= clear) return keep;
  let best = 0;
  let bestRoom = -Infinity;
  for (let i = 0; i < candidates.length; i++) {
    const r = room(candidates[i]);
    if (r >= clear) return i;
    if (r > bestRoom) {
      bestRoom = r;
      best = i;
    }
  }
  return best;
}
