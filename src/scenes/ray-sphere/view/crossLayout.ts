/**
 * The cross-section's layout, pure (no DOM): the plane through the ray and the centre (kept while
 * it still fits, or while dragging), the view (kept while the content still fits well), where the
 * handles go (the direction tip and the radius handle step aside from the roots and the ray), and
 * where each label goes so that no handle covers it (view/labelLayout.ts).
 */
import type { RaySphereHit } from '../../../core/geometry';
import { canonicalFrame, frameFits, toFrame, type Frame2D } from '../frame';
import { FAR_RATIO } from '../model';
import type { Vec3 } from '../../../core/vec3';
import {
  discBox,
  overlapArea,
  pickClear,
  placeLabels,
  type Box,
  type LabelRequest,
  type Pt,
} from './labelLayout';

/** The ray and sphere a figure draws: the checked inputs, the chosen method's hit, |o − C| / r. */
export interface RayState {
  o: Vec3;
  d: Vec3;
  c: Vec3;
  r: number;
  res: RaySphereHit | null;
  distanceRatio: number;
}

export interface View {
  cx: number;
  cy: number;
  /** world units per pixel */
  s: number;
  far?: boolean;
  /** The figure size the view was fitted for. */
  W?: number;
  H?: number;
}

export type Target = 'o' | 'tip' | 'c' | 'r';

/** What the layout keeps from one drawing to the next (so nothing jumps while dragging or playing). */
export interface Kept {
  frame: Frame2D | null;
  view: View | null;
  /** The index of the direction arrow's length and of the radius handle's angle used last. */
  tipLen?: number | null;
  rAngle?: number | null;
}

/** A handle's hit area (px): the handles' outer circle. */
export const HANDLE_R = 16;
/** How far a label keeps from a handle's centre, and from a root marker's (px). */
const HANDLE_CLEAR = HANDLE_R + 3;
const MARKER_CLEAR = 8;

/** Arrow lengths (× the base length) tried for the direction tip, the first being the usual one. */
const TIP_LENGTHS = [1, 0.75, 1.3, 0.55];
/** Angles (degrees from the figure's x axis) tried for the radius handle. */
const R_ANGLES = [45, 135, -45, -135, 90, -90, 0, 180];

export interface Layout {
  far: boolean;
  fr: Frame2D;
  v: View;
  W: number;
  H: number;
  dl: number;
  r: number;
  O2: [number, number];
  C2: [number, number];
  dir2: [number, number];
  tip: [number, number];
  rHandle: [number, number];
  fwdEnd: [number, number];
  backEnd: [number, number];
  roots: number[];
  rootPts: [number, number][];
  res: RaySphereHit | null;
  distanceRatio: number;
  step: number;
}

/** World (frame) → figure pixels. */
export const X_ = (g: Pick<Layout, 'W' | 'v'>, x: number) => g.W / 2 + (x - g.v.cx) / g.v.s;
export const Y_ = (g: Pick<Layout, 'H' | 'v'>, y: number) => g.H / 2 - (y - g.v.cy) / g.v.s;
/** Clamp huge coordinates (far mode) so the SVG stays well-behaved. */
export const cl = (x: number) => Math.max(-1e5, Math.min(1e5, x));

/**
 * The figure's layout for a ray: the plane (kept while it still fits, or while dragging) and the
 * view (kept while the content still fits well). Updates what is kept in `keep`.
 */
export function layoutCross(
  ray: RayState,
  fitExtra: readonly Vec3[],
  W: number,
  H: number,
  dragging: Target | null,
  keep: Kept,
): Layout {
  const { o, d, c, r, res, distanceRatio } = ray;
  const far = distanceRatio > FAR_RATIO;
  // --- frame: keep it while it still contains the ray and the centre
  const prevView = keep.view;
  const tolLen = prevView ? prevView.s * 0.75 : 1e-9 * (Math.abs(r) + 1);
  let fr = keep.frame;
  if (far || (!dragging && (!fr || !frameFits(fr, o, d, c, tolLen)))) fr = canonicalFrame(o, d, c);
  if (!fr) fr = canonicalFrame(o, d, c);
  keep.frame = fr;

  const dl = Math.hypot(d[0], d[1], d[2]);
  let O2: [number, number];
  let C2: [number, number];
  let dir2: [number, number];
  if (far) {
    // Projecting a point 10⁸ r away onto e2 would amplify e2's rounding (≈ε|f|/|l|) into a
    // visible offset; in the canonical frame the exact answer is known: the ray runs along x at
    // height |l| (the distance of the line from the centre), and the centre is the origin.
    const f: Vec3 = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
    const k = (f[0] * d[0] + f[1] * d[1] + f[2] * d[2]) / (dl * dl);
    const lx = f[0] - k * d[0];
    const ly = f[1] - k * d[1];
    const lz = f[2] - k * d[2];
    O2 = [k * dl, Math.hypot(lx, ly, lz)];
    C2 = [0, 0];
    dir2 = [1, 0];
  } else {
    O2 = toFrame(fr, o);
    C2 = toFrame(fr, c);
    dir2 = [
      (d[0] * fr.e1[0] + d[1] * fr.e1[1] + d[2] * fr.e1[2]) / dl,
      (d[0] * fr.e2[0] + d[1] * fr.e2[1] + d[2] * fr.e2[2]) / dl,
    ];
  }
  // a tangent's double root is drawn once
  const roots = res && res.t0 !== null ? (res.t0 === res.t1 ? [res.t0] : [res.t0, res.t1!]) : [];
  // root points along the drawn line (t in units of |d|)
  const rootPts = roots.map((t): [number, number] => [O2[0] + t * dl * dir2[0], O2[1] + t * dl * dir2[1]]);

  // --- view: fit the content, but keep the view while dragging or while it still fits well
  let box: [number, number, number, number]; // xmin, xmax, ymin, ymax
  if (far) {
    // the closest point of the line to the centre, and the sphere
    const tClose = -((O2[0] - C2[0]) * dir2[0] + (O2[1] - C2[1]) * dir2[1]);
    const P: [number, number] = [O2[0] + tClose * dir2[0], O2[1] + tClose * dir2[1]];
    box = [
      Math.min(C2[0] - r, P[0]),
      Math.max(C2[0] + r, P[0]),
      Math.min(C2[1] - r, P[1]),
      Math.max(C2[1] + r, P[1]),
    ];
  } else {
    const extra = fitExtra.map((q) => toFrame(fr, q));
    const xs = [C2[0] - r, C2[0] + r, O2[0], ...rootPts.map((p) => p[0]), ...extra.map((p) => p[0])];
    const ys = [C2[1] - r, C2[1] + r, O2[1], ...rootPts.map((p) => p[1]), ...extra.map((p) => p[1])];
    box = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  }
  const bw = box[1] - box[0];
  const bh = box[3] - box[2];
  // margins for labels and handles, smaller on a phone-sized figure
  const fitS = Math.max(bw / (W - Math.min(130, 0.16 * W)), bh / (H - Math.min(110, 0.22 * H))) || 1;
  const fit: View = { cx: (box[0] + box[1]) / 2, cy: (box[2] + box[3]) / 2, s: fitS };
  let view = prevView;
  const inside = (v: View) =>
    box[0] >= v.cx - (v.s * W) / 2 + 10 * v.s &&
    box[1] <= v.cx + (v.s * W) / 2 - 10 * v.s &&
    box[2] >= v.cy - (v.s * H) / 2 + 10 * v.s &&
    box[3] <= v.cy + (v.s * H) / 2 - 10 * v.s;
  const resized = view?.W !== W || view?.H !== H;
  if (!dragging && (!view || !inside(view) || view.s > 2.5 * fitS || far !== prevView?.far || resized))
    view = fit;
  keep.view = { ...view!, far, W, H };
  const v = view!;
  const step = 10 ** Math.floor(Math.log10(v.s * 2));
  const px = (p: readonly [number, number]): Pt => [X_({ W, v }, p[0]), Y_({ H, v }, p[1])];

  // ray segment across the whole view: t from the origin to well past the view
  const reach = (Math.hypot(W, H) * v.s + Math.hypot(O2[0] - v.cx, O2[1] - v.cy)) * 1.2;
  const fwdEnd: [number, number] = [O2[0] + reach * dir2[0], O2[1] + reach * dir2[1]];
  const backEnd: [number, number] = [O2[0] - reach * dir2[0], O2[1] - reach * dir2[1]];
  const rootsPx = rootPts.map(px);
  const rayPx: [Pt, Pt] = [px(backEnd), px(fwdEnd)];

  // --- the direction tip: 130 px along the ray (less on a phone), nearer or farther when that
  // would put its handle on a root marker or on the centre's handle; kept while dragging it
  const L0 = Math.min(130, 0.22 * W) * v.s;
  const tips = TIP_LENGTHS.map((k): [number, number] => [O2[0] + k * L0 * dir2[0], O2[1] + k * L0 * dir2[1]]);
  const tipI =
    dragging === 'tip' && keep.tipLen != null
      ? keep.tipLen
      : pickClear(tips.map(px), [...rootsPx, px(C2)], [], 2 * HANDLE_R + 4, keep.tipLen ?? null);
  keep.tipLen = tipI;
  const tip = tips[tipI];

  // --- the radius handle: on the rim, at an angle away from the ray, the roots and the other
  // handles; kept while dragging it
  const rims = R_ANGLES.map((deg): [number, number] => {
    const a = (deg * Math.PI) / 180;
    return [C2[0] + r * Math.cos(a), C2[1] + r * Math.sin(a)];
  });
  const others = far ? [px(C2)] : [px(O2), px(tip), px(C2)];
  const rI =
    dragging === 'r' && keep.rAngle != null
      ? keep.rAngle
      : pickClear(rims.map(px), [...rootsPx, ...others], [rayPx], 2 * HANDLE_R + 4, keep.rAngle ?? null);
  keep.rAngle = rI;
  const rHandle = rims[rI];
  return {
    far,
    fr,
    v,
    W,
    H,
    dl,
    r,
    O2,
    C2,
    dir2,
    tip,
    rHandle,
    fwdEnd,
    backEnd,
    roots,
    rootPts,
    res,
    distanceRatio,
    step,
  };
}

/** Is the origin drawn (it is not when the sphere is so far away that the figure is not to scale)? */
export const originShown = (g: Layout) => !g.far;

/** The label of root i (t₀ or t₁, "t₀ = t₁" for a tangent's double root, and whether it is the hit). */
export function rootLabel(g: Layout, i: number): string {
  const t = g.roots[i];
  const isHit = g.res !== null && g.res.tHit !== null && g.res.tHit === t;
  const name = g.roots.length === 1 ? 't₀ = t₁' : `t${i === 0 ? '₀' : '₁'}`;
  return `${name}${isHit ? ' (hit)' : t < 0 ? ' < 0' : ''}`;
}

/** The note under a figure that is not to scale, or whose origin is out of view; null when none. */
export function noteText(g: Layout): string | null {
  const X = X_(g, g.O2[0]);
  const Y = Y_(g, g.O2[1]);
  const originOff = X < 0 || X > g.W || Y < 0 || Y > g.H;
  if (g.far)
    return `Not to scale: the origin is ${g.distanceRatio.toPrecision(3)} radii away (off to the ${g.dir2[0] >= 0 ? 'left' : 'right'}). Type values to move it.`;
  return originOff ? 'The origin is outside the view.' : null;
}

/** The labels the figure writes, by their data-k key. */
export type LabelKey =
  'root0-label' | 'root1-label' | 'o-label' | 'c-label' | 'r-label' | 'note' | 'note2' | 'note3';

/** The keys of the note's lines, in order (a long note is broken to fit the figure's width). */
export const NOTE_KEYS = ['note', 'note2', 'note3'] as const;

export interface PlacedLabel {
  key: LabelKey;
  text: string;
  box: Box;
}

/** Each handle shown and its centre in figure pixels. */
export function handlePositions(g: Layout): { target: Target; at: Pt }[] {
  const px = (p: readonly [number, number]): Pt => [X_(g, p[0]), Y_(g, p[1])];
  const out: { target: Target; at: Pt }[] = [];
  if (originShown(g)) out.push({ target: 'o', at: px(g.O2) }, { target: 'tip', at: px(g.tip) });
  out.push({ target: 'c', at: px(g.C2) }, { target: 'r', at: px(g.rHandle) });
  return out;
}

/**
 * Where every label goes for this layout: `size(key, text)` gives a label's width and height
 * (measured in the page, estimated in tests). Labels avoid the handles, the root markers and each
 * other, stay inside the figure where they can, and rather not cross the ray.
 */
export function planLabels(
  g: Layout,
  size: (key: LabelKey, text: string) => [number, number],
): PlacedLabel[] {
  const px = (p: readonly [number, number]): Pt => [X_(g, p[0]), Y_(g, p[1])];
  const hard: Box[] = [
    ...handlePositions(g).map((h) => discBox(h.at, HANDLE_CLEAR)),
    ...g.rootPts.map((p) => discBox(px(p), MARKER_CLEAR)),
  ];
  const lines: [Pt, Pt][] = [[px(g.backEnd), px(g.fwdEnd)]];
  if (originShown(g)) lines.push([px(g.O2), px(g.tip)]);
  const out: PlacedLabel[] = [];
  // the note first (it is long), along the bottom or the top edge, wherever no handle is
  const note = noteText(g);
  if (note) {
    // broken into lines that fit the figure's width (at most NOTE_KEYS.length, the last one takes the rest)
    const lines: string[] = [];
    let line = '';
    for (const word of note.split(' ')) {
      const next = line ? `${line} ${word}` : word;
      const key = NOTE_KEYS[Math.min(lines.length, NOTE_KEYS.length - 1)];
      if (line && lines.length < NOTE_KEYS.length - 1 && size(key, next)[0] > g.W - 24) {
        lines.push(line);
        line = word;
      } else line = next;
    }
    lines.push(line);
    const sized = lines.map((text, i) => ({ key: NOTE_KEYS[i], text, wh: size(NOTE_KEYS[i], text) }));
    const w = Math.max(...sized.map((l) => l.wh[0]));
    const h = sized.reduce((a, l) => a + l.wh[1], 0);
    const spots: Box[] = [
      { x: 12, y: g.H - 8 - h, w, h },
      { x: 12, y: 8, w, h },
    ];
    const box = spots.find((b) => hard.every((o) => overlapArea(o, b) === 0)) ?? spots[0];
    hard.push(box);
    let y = box.y;
    for (const l of sized) {
      out.push({ key: l.key, text: l.text, box: { x: box.x, y, w: l.wh[0], h: l.wh[1] } });
      y += l.wh[1];
    }
  }
  const wanted: { key: LabelKey; text: string }[] = [];
  const reqs: LabelRequest[] = [];
  const add = (key: LabelKey, text: string, anchor: Pt, gap: number, prefer: number[]) => {
    const [w, h] = size(key, text);
    wanted.push({ key, text });
    reqs.push({ anchor, gap, w, h, prefer });
  };
  // root labels above-right (t₀) and below-right (t₁) of their markers by default
  g.rootPts.forEach((p, i) =>
    add(i ? 'root1-label' : 'root0-label', rootLabel(g, i), px(p), 9, i ? [7, 6, 0] : [1, 2, 0]),
  );
  if (originShown(g)) add('o-label', 'o', px(g.O2), HANDLE_CLEAR, [3, 5, 2, 4]);
  add('c-label', 'C', px(g.C2), HANDLE_CLEAR, [7, 5, 1, 3]);
  add('r-label', 'r', px(g.rHandle), HANDLE_CLEAR, [1, 7, 3, 5]);
  const boxes = placeLabels(reqs, { W: g.W, H: g.H, hard, lines });
  wanted.forEach((l, i) => out.push({ ...l, box: boxes[i] }));
  return out;
}
