/**
 * The 2D cross-section through the ray and the sphere's centre (an SVG): the great circle of the
 * sphere, the ray (solid for t ≥ 0, dashed behind the origin), its roots, and draggable handles
 * for the origin, the direction, the centre and the radius. The frame (plane and zoom) is kept
 * while dragging so nothing jumps; it is recomputed only when typed values leave the plane.
 * React renders the elements; their positions and labels are written by drawCross (after each
 * render, and per animation frame through `drawRef` without React, while a sweep plays).
 */
import { useLayoutEffect, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { useWidth } from '../../../ui/useWidth';
import { useSectionWidth } from '../../../ui/Deferred';
import type { RaySphereHit } from '../../../core/geometry';
import {
  canonicalFrame,
  dirFromFrame,
  fromFrame,
  frameFits,
  tidy,
  toFrame,
  type Frame2D,
  type V3,
} from '../model';

/** The ray and sphere a figure draws: the checked inputs, the chosen method's hit, |o − C| / r. */
export interface RayState {
  o: V3;
  d: V3;
  c: V3;
  r: number;
  res: RaySphereHit | null;
  distanceRatio: number;
}

export interface CrossSectionProps extends RayState {
  onChange: (patch: { o?: V3; d?: V3; c?: V3; r?: number }) => void;
  /** More points to keep in view (e.g. the ends of a sweep), so the view does not jump while animating. */
  fitExtra?: readonly V3[];
  /** Set to a function that redraws the figure for another ray directly (per animation frame). */
  drawRef?: { current: ((ray: CrossRay) => void) | null };
}

/** What moves while a sweep plays. */
export type CrossRay = RayState;

/** Each coordinate rounded to `step` (see tidy). */
const tidyVec = (q: V3, step: number): V3 => [tidy(q[0], step), tidy(q[1], step), tidy(q[2], step)];

/** Above this |o − c| / r the view centres on the sphere and leaves the origin off screen. */
const FAR = 60;

interface View {
  cx: number;
  cy: number;
  /** world units per pixel */
  s: number;
  far?: boolean;
  /** The figure width the view was fitted for. */
  W?: number;
}

type Target = 'o' | 'tip' | 'c' | 'r';

interface Layout {
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

/**
 * The figure's layout for a ray: the plane (kept while it still fits, or while dragging) and the
 * view (kept while the content still fits well). Updates the kept frame and view in `keep`.
 */
function layoutCross(
  ray: CrossRay,
  fitExtra: readonly V3[],
  W: number,
  H: number,
  dragging: boolean,
  keep: { frame: Frame2D | null; view: View | null },
): Layout {
  const { o, d, c, r, res, distanceRatio } = ray;
  const far = distanceRatio > FAR;
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
    const f: V3 = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
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
    const extra = fitExtra.map((q) => toFrame(fr!, q));
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
  if (!dragging && (!view || !inside(view) || view.s > 2.5 * fitS || far !== prevView?.far || view.W !== W))
    view = fit;
  keep.view = { ...view!, far, W };
  const v = view!;
  const step = 10 ** Math.floor(Math.log10(v.s * 2));

  const L = Math.min(130, 0.22 * W) * v.s; // direction arrow length: 130 px (less on a phone)
  const tip: [number, number] = [O2[0] + L * dir2[0], O2[1] + L * dir2[1]];
  const rAngle = Math.PI / 4;
  const rHandle: [number, number] = [C2[0] + r * Math.cos(rAngle), C2[1] + r * Math.sin(rAngle)];

  // ray segment across the whole view: t from the origin to well past the view
  const reach = (Math.hypot(W, H) * v.s + Math.hypot(O2[0] - v.cx, O2[1] - v.cy)) * 1.2;
  const fwdEnd: [number, number] = [O2[0] + reach * dir2[0], O2[1] + reach * dir2[1]];
  const backEnd: [number, number] = [O2[0] - reach * dir2[0], O2[1] - reach * dir2[1]];
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

const X_ = (g: Layout, x: number) => g.W / 2 + (x - g.v.cx) / g.v.s;
const Y_ = (g: Layout, y: number) => g.H / 2 - (y - g.v.cy) / g.v.s;
/** Clamp huge coordinates (far mode) so the SVG stays well-behaved. */
const cl = (x: number) => Math.max(-1e5, Math.min(1e5, x));

/** Writes a layout into the elements CrossSection rendered (marked with data-k). */
function drawCross(fig: HTMLElement, g: Layout): void {
  const X = (x: number) => X_(g, x);
  const Y = (y: number) => Y_(g, y);
  const q = (k: string) => fig.querySelector<SVGElement>(`[data-k="${k}"]`);
  const set = (el: Element | null, attrs: Record<string, string | number>) => {
    if (!el) return;
    for (const a in attrs) {
      const v = String(attrs[a]);
      if (el.getAttribute(a) !== v) el.setAttribute(a, v);
    }
  };
  const show = (el: Element | null, on: boolean) => {
    if (!el) return;
    if (on) el.removeAttribute('display');
    else el.setAttribute('display', 'none');
  };
  const text = (el: Element | null, t: string) => {
    if (el && el.textContent !== t) el.textContent = t;
  };
  const { O2, C2, far, res } = g;
  const caseCls = res ? `case-${res.case}` : '';
  const figCls = `rs-section ${caseCls}`;
  if (fig.getAttribute('class') !== figCls) fig.setAttribute('class', figCls);
  set(q('circle'), { cx: cl(X(C2[0])), cy: cl(Y(C2[1])), r: Math.min(1e5, g.r / g.v.s) });
  set(q('back'), { x1: cl(X(g.backEnd[0])), y1: cl(Y(g.backEnd[1])), x2: cl(X(O2[0])), y2: cl(Y(O2[1])) });
  set(q('fwd'), { x1: cl(X(O2[0])), y1: cl(Y(O2[1])), x2: cl(X(g.fwdEnd[0])), y2: cl(Y(g.fwdEnd[1])) });
  const dir = q('dir');
  show(dir, !far);
  if (!far) set(dir, { x1: X(O2[0]), y1: Y(O2[1]), x2: X(g.tip[0]), y2: Y(g.tip[1]) });
  for (let i = 0; i < 2; i++) {
    const el = q(`root${i}`);
    const t = g.roots[i];
    show(el, t !== undefined);
    if (!el || t === undefined) continue;
    const p = g.rootPts[i];
    const isHit = res !== null && res.tHit !== null && res.tHit === t;
    set(el, {
      transform: `translate(${cl(X(p[0]))} ${cl(Y(p[1]))})`,
      class: `rs-root${isHit ? ' hit' : ''}${t < 0 ? ' behind' : ''}`,
    });
    set(el.firstElementChild, { r: isHit ? 6.5 : 5 });
    const label = el.lastElementChild;
    set(label, { y: i === 0 ? -9 : 18 });
    text(
      label,
      `${g.roots.length === 1 ? 't₀ = t₁' : `t${i === 0 ? '₀' : '₁'}`}${isHit ? ' (hit)' : t < 0 ? ' < 0' : ''}`,
    );
  }
  const oLabel = q('o-label');
  show(oLabel, !far);
  if (!far) set(oLabel, { x: cl(X(O2[0])) - 10, y: cl(Y(O2[1])) - 12 });
  set(q('c-label'), { x: cl(X(C2[0])) + 9, y: cl(Y(C2[1])) + 16 });
  const handle = (k: string, at: [number, number], on = true) => {
    const el = q(`h-${k}`);
    show(el, on);
    if (on) set(el, { transform: `translate(${cl(X(at[0]))} ${cl(Y(at[1]))})` });
  };
  handle('o', O2, !far);
  handle('tip', g.tip, !far);
  handle('c', C2);
  handle('r', g.rHandle);
  set(q('h-r'), { 'aria-label': `radius r = ${g.r} (drag, or focus and use the arrow keys)` });
  set(q('r-label'), { x: X(g.rHandle[0]) + 12, y: Y(g.rHandle[1]) - 6 });
  const originOff = X(O2[0]) < 0 || X(O2[0]) > g.W || Y(O2[1]) < 0 || Y(O2[1]) > g.H;
  const note = q('note');
  show(note, far || originOff);
  if (note && (far || originOff)) {
    set(note, { y: g.H - 12 });
    text(
      note,
      far
        ? `Not to scale: the origin is ${g.distanceRatio.toPrecision(3)} radii away (off to the ${g.dir2[0] >= 0 ? 'left' : 'right'}). Type values to move it.`
        : 'The origin is outside the view.',
    );
  }
}

export function CrossSection({
  o,
  d,
  c,
  r,
  res,
  distanceRatio,
  onChange,
  fitExtra = [],
  drawRef,
}: CrossSectionProps) {
  const svgRef = useRef<SVGSVGElement>(null);
  // one SVG unit = one CSS pixel: labels and handles keep their size on small screens
  const figRef = useRef<HTMLElement>(null);
  // first drawn at the width of the placeholder it replaced (the figure fills its section), else a guess
  const W = Math.max(280, useWidth(figRef, useSectionWidth() ?? 640));
  const H = Math.round(Math.min(460, Math.max(280, W * 0.62)));
  const keep = useRef<{ frame: Frame2D | null; view: View | null }>({ frame: null, view: null });
  const dragRef = useRef<{ target: Target; pointerId: number } | null>(null);
  const [dragging, setDragging] = useState<Target | null>(null);
  // the ray drawn last (from a render or a frame): pointer and key handlers work on what is shown
  const ray = useRef<CrossRay>({ o, d, c, r, res, distanceRatio });
  if (!drawRef) ray.current = { o, d, c, r, res, distanceRatio };
  const shown = useRef<Layout | null>(null);
  const layout = (x: CrossRay) => layoutCross(x, fitExtra, W, H, dragging !== null, keep.current);
  const draw = (x: CrossRay) => {
    ray.current = x;
    const g = layout(x);
    shown.current = g;
    if (figRef.current) drawCross(figRef.current, g);
  };
  if (drawRef) drawRef.current = draw;
  useLayoutEffect(() => draw(ray.current));
  const cur = () => shown.current ?? layout(ray.current);

  const toWorld2 = (e: PointerEvent<SVGSVGElement>): [number, number] | null => {
    const svg = svgRef.current;
    const m = svg?.getScreenCTM();
    if (!svg || !m) return null;
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
    const g = cur();
    return [g.v.cx + (p.x - g.W / 2) * g.v.s, g.v.cy - (p.y - g.H / 2) * g.v.s];
  };

  const apply = (target: Target, x: number, y: number) => {
    const g = cur();
    const { fr, O2, C2, dl, v, step } = g;
    const t = (q: V3) => tidyVec(q, step);
    if (target === 'o') onChange({ o: t(fromFrame(fr, x, y)) });
    else if (target === 'c') onChange({ c: t(fromFrame(fr, x, y)) });
    else if (target === 'r') {
      const nr = Math.hypot(x - C2[0], y - C2[1]);
      if (nr > step) onChange({ r: tidy(nr, step) });
    } else {
      const vx = x - O2[0];
      const vy = y - O2[1];
      const n = Math.hypot(vx, vy);
      if (n < 4 * v.s) return;
      const w = dirFromFrame(fr, (vx / n) * dl, (vy / n) * dl);
      const ds = 10 ** Math.floor(Math.log10(dl / 500));
      const nd = tidyVec(w, ds);
      if (nd.some((z) => z !== 0)) onChange({ d: nd });
    }
  };

  const down = (target: Target) => (e: PointerEvent<SVGElement>) => {
    e.preventDefault();
    svgRef.current?.setPointerCapture(e.pointerId);
    dragRef.current = { target, pointerId: e.pointerId };
    setDragging(target);
  };
  const move = (e: PointerEvent<SVGSVGElement>) => {
    const dr = dragRef.current;
    if (!dr || dr.pointerId !== e.pointerId) return;
    const p = toWorld2(e);
    if (p) apply(dr.target, p[0], p[1]);
  };
  const up = (e: PointerEvent<SVGSVGElement>) => {
    if (dragRef.current?.pointerId !== e.pointerId) return;
    dragRef.current = null;
    setDragging(null);
  };
  const key = (target: Target) => (e: KeyboardEvent<SVGElement>) => {
    const g = cur();
    const k = 8 * g.v.s;
    const dx = e.key === 'ArrowRight' ? k : e.key === 'ArrowLeft' ? -k : 0;
    const dy = e.key === 'ArrowUp' ? k : e.key === 'ArrowDown' ? -k : 0;
    if (!dx && !dy) return;
    e.preventDefault();
    const at = target === 'o' ? g.O2 : target === 'tip' ? g.tip : target === 'c' ? g.C2 : g.rHandle;
    apply(target, at[0] + dx, at[1] + dy);
  };

  const handle = (target: Target, label: string, cls: string) => (
    <g
      className={`rs-handle ${cls}${dragging === target ? ' active' : ''}`}
      data-k={`h-${target}`}
      onPointerDown={down(target)}
      onKeyDown={key(target)}
      tabIndex={0}
      role="button"
      aria-roledescription="draggable handle"
      aria-label={`${label} (drag, or focus and use the arrow keys)`}
      data-testid={`handle-${target}`}
    >
      <circle r={16} className="rs-handle-hit" />
      <circle r={13} className="rs-handle-ring" />
      <circle r={7} />
    </g>
  );

  return (
    <figure className="rs-section" ref={figRef}>
      <svg
        ref={svgRef}
        viewBox={`0 0 ${W} ${H}`}
        className={`rs-svg${dragging ? ' dragging' : ''}`}
        width="100%"
        height={H}
        role="group"
        aria-label="Cross-section through the ray and the sphere's centre"
        onPointerMove={move}
        onPointerUp={up}
        onPointerCancel={up}
        data-testid="cross-section"
      >
        <defs>
          <marker
            id="rs-arrow"
            viewBox="0 0 10 10"
            refX="8"
            refY="5"
            markerWidth="7"
            markerHeight="7"
            orient="auto-start-reverse"
          >
            <path d="M0,0 L10,5 L0,10 z" className="rs-arrowhead" />
          </marker>
        </defs>
        <circle data-k="circle" className="rs-circle" />
        <line data-k="back" className="rs-ray-back" />
        <line data-k="fwd" className="rs-ray" />
        <line data-k="dir" className="rs-dir" markerEnd="url(#rs-arrow)" />
        {[0, 1].map((i) => (
          <g key={i} data-k={`root${i}`} className="rs-root" display="none">
            <circle r={5} />
            <text x={8} className="rs-label" />
          </g>
        ))}
        <text data-k="o-label" className="rs-label" textAnchor="end">
          o
        </text>
        <text data-k="c-label" className="rs-label">
          C
        </text>
        {handle('o', 'ray origin o', 'h-o')}
        {handle('tip', 'ray direction d', 'h-d')}
        {handle('c', 'sphere centre C', 'h-c')}
        {handle('r', 'radius r', 'h-r')}
        <text data-k="r-label" className="rs-label">
          r
        </text>
        <text data-k="note" x={12} className="rs-note" display="none" />
      </svg>
      <figcaption className="rs-caption">
        Plane through the ray and the centre. Solid: the ray (t ≥ 0); dashed: the line behind the origin (t
        &lt; 0). Drag <span className="key-o">o</span>, the <span className="key-d">arrow tip</span>{' '}
        (direction), <span className="key-c">C</span> and the <span className="key-r">rim handle</span>{' '}
        (radius).
      </figcaption>
    </figure>
  );
}
