/**
 * The 2D cross-section through the ray and the sphere's centre (an SVG): the great circle of the
 * sphere, the ray (solid for t ≥ 0, dashed behind the origin), its roots, and handles for the
 * origin, the direction, the centre and the radius (drag them, or focus one and use the arrow
 * keys; each is a slider that says what it is, where it is and what the ray does now). The
 * layout (view/crossLayout.ts) keeps the frame while dragging so nothing jumps, and places the
 * labels where no handle covers them. React renders the elements; their positions and labels are
 * written by drawCross (after each render, and per animation frame through `drawRef` without
 * React, while a sweep plays).
 */
import { afterDraw, afterPress, stepFrom, type KeyChain } from './keyChain';
import { useEffect, useLayoutEffect, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { afterPaint } from '../../../ui/afterPaint';
import { announce } from '../../../ui/announce';
import { useWidth } from '../../../ui/useWidth';
import { mountingForPrint, useSectionWidth } from '../../../ui/Deferred';
import { dirFromFrame, fromFrame } from '../frame';
import { tidy } from '../tidy';
import type { Vec3 } from '../../../core/vec3';
import type { RaySphereParams } from '../params';
import { ArrowMarker } from '../../../ui/ArrowMarker';
import {
  cl,
  handlePositions,
  HANDLE_R,
  layoutCross,
  NOTE_KEYS,
  noteText,
  planLabels,
  X_,
  Y_,
  type Kept,
  type LabelKey,
  type Layout,
  type RayState,
  type Target,
} from './crossLayout';
import { handleText, HANDLE_NAMES } from './describe';
import { clipSegment } from './labelLayout';

export type { RayState } from './crossLayout';

export interface CrossSectionProps extends RayState {
  onChange: (patch: Partial<Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r'>>) => void;
  /** More points to keep in view (e.g. the ends of a sweep), so the view does not jump while animating. */
  fitExtra?: readonly Vec3[];
  /** Set to a function that redraws the figure for another ray directly (per animation frame). */
  drawRef?: { current: ((ray: CrossRay) => void) | null };
  /** The tallest the drawing may be (px); default 460. */
  maxHeight?: number;
  /**
   * Fill the height of the enclosing `.stage-figure` (the classroom stage gives it what the first
   * screen leaves); otherwise the height follows the width.
   */
  fill?: boolean;
}

/** The height of the enclosing `.stage-figure` while `on` (null: not filling, or not measured yet). */
function useFillHeight(ref: { current: HTMLElement | null }, on: boolean): number | null {
  const [h, setH] = useState<number | null>(null);
  useLayoutEffect(() => {
    const box = on ? ref.current?.closest<HTMLElement>('.stage-figure') : null;
    if (!box) {
      setH(null);
      return;
    }
    const measure = () => setH(box.clientHeight);
    measure();
    const ro = typeof ResizeObserver === 'function' ? new ResizeObserver(measure) : null;
    ro?.observe(box);
    return () => ro?.disconnect();
  }, [ref, on]);
  return h;
}

/** What moves while a sweep plays. */
export type CrossRay = RayState;

/** Each coordinate rounded to `step` (see tidy). */
const tidyVec = (q: Vec3, step: number): RaySphereParams['o'] => [
  tidy(q[0], step),
  tidy(q[1], step),
  tidy(q[2], step),
];

/**
 * A label's size: its text's width in the label's font (cached per text and font) and 1.25 em.
 * The width comes from a canvas's measureText in the element's computed font, which lays nothing
 * out: measuring the SVG text itself (getComputedTextLength) forced a layout of the page, in the
 * middle of the draw, for each text not measured before (the note's line breaking tries one per
 * word, and a drag changes the roots' labels every frame).
 */
function useLabelSizer() {
  const cache = useRef(new Map<string, number>());
  const pen = useRef<CanvasRenderingContext2D | null | undefined>(undefined);
  return (el: SVGTextElement | null, text: string): [number, number] => {
    const cs = el ? getComputedStyle(el) : null;
    const fs = cs ? parseFloat(cs.fontSize) || 15 : 15;
    const font = cs ? `${cs.fontStyle} ${cs.fontWeight} ${fs}px ${cs.fontFamily}` : `${fs}px`;
    const key = `${font}|${text}`;
    let w = cache.current.get(key);
    if (w === undefined) {
      if (pen.current === undefined) pen.current = document.createElement('canvas').getContext('2d');
      let m = 0;
      if (pen.current && cs) {
        pen.current.font = font;
        m = pen.current.measureText(text).width;
      }
      // no canvas (jsdom) or no element: estimate it from its length
      w = m > 0 ? m : 0.62 * fs * text.length;
      if (m > 0) cache.current.set(key, w);
    }
    return [w + 2, 1.25 * fs];
  };
}

/** Writes a layout into the elements CrossSection rendered (marked with data-k). */
function drawCross(
  fig: HTMLElement,
  g: Layout,
  size: (el: SVGTextElement | null, text: string) => [number, number],
  withLabels: boolean,
): void {
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
  const { O2, C2, far, res } = g;
  const caseCls = res ? `case-${res.case}` : '';
  const figCls = `rs-section ${caseCls}`;
  if (fig.getAttribute('class') !== figCls) fig.setAttribute('class', figCls);
  set(q('circle'), { cx: cl(X(C2[0])), cy: cl(Y(C2[1])), r: Math.min(1e5, g.r / g.v.s) });
  // the ray and the line behind the origin, drawn only within the figure
  const line = (k: string, a: readonly [number, number], b: readonly [number, number]) => {
    const seg = clipSegment([cl(X(a[0])), cl(Y(a[1]))], [cl(X(b[0])), cl(Y(b[1]))], {
      x: 0,
      y: 0,
      w: g.W,
      h: g.H,
    });
    show(q(k), seg !== null);
    if (seg)
      set(q(k), {
        x1: seg[0][0].toFixed(1),
        y1: seg[0][1].toFixed(1),
        x2: seg[1][0].toFixed(1),
        y2: seg[1][1].toFixed(1),
      });
  };
  line('back', g.backEnd, O2);
  line('fwd', O2, g.fwdEnd);
  const dir = q('dir');
  show(dir, !far);
  if (!far) set(dir, { x1: X(O2[0]), y1: Y(O2[1]), x2: X(g.tip[0]), y2: Y(g.tip[1]) });
  for (let i = 0; i < 2; i++) {
    const el = q(`root${i}`);
    const t = g.roots[i];
    show(el, t !== undefined);
    show(q(`root${i}-label`), t !== undefined);
    if (!el || t === undefined) continue;
    const p = g.rootPts[i];
    const isHit = res !== null && res.tHit !== null && res.tHit === t;
    set(el, {
      transform: `translate(${cl(X(p[0]))} ${cl(Y(p[1]))})`,
      class: `rs-root${isHit ? ' hit' : ''}${t < 0 ? ' behind' : ''}`,
    });
    set(el.firstElementChild, { r: isHit ? 6.5 : 5 });
  }
  const shown = new Set(handlePositions(g).map((h) => h.target));
  for (const h of handlePositions(g))
    set(q(`h-${h.target}`), { transform: `translate(${cl(h.at[0])} ${cl(h.at[1])})` });
  for (const k of ['o', 'tip', 'c', 'r'] as const) show(q(`h-${k}`), shown.has(k));
  show(q('o-label'), !far);
  for (const k of NOTE_KEYS) show(q(k), noteText(g) !== null);
  // labels last: measured with their current text, then put where no handle covers them; until
  // the figure's first frame has been painted they wait, hidden (see CrossSection)
  const svg = fig.querySelector('svg');
  set(svg, { 'data-labels': withLabels ? 'placed' : 'pending' });
  if (!withLabels) return;
  const labels = planLabels(g, (key: LabelKey, text: string) => {
    const el = q(key) as SVGTextElement | null;
    if (el && el.textContent !== text) el.textContent = text;
    return size(el, text);
  });
  for (const k of NOTE_KEYS)
    show(
      q(k),
      labels.some((l) => l.key === k),
    );
  for (const l of labels) {
    const el = q(l.key);
    if (!el) continue;
    const fs = l.box.h / 1.25;
    set(el, { x: l.box.x.toFixed(1), y: (l.box.y + 0.95 * fs).toFixed(1) });
  }
}

/** The slider attributes of a handle for this layout (name, value text, a value for aria-valuenow). */
function handleAria(g: Layout, ray: RayState, target: Target) {
  const t = handleText(target, ray, g.dir2);
  return {
    'aria-valuetext': t.valueText,
    'aria-valuenow': t.valueNow,
    'aria-valuemin': t.min,
    'aria-valuemax': t.max,
  };
}

/** The parameter a handle moves, as a comparable text: o, c, r, or d for the direction tip. */
function keyValue(target: Target, x: Partial<Pick<RayState, 'o' | 'd' | 'c' | 'r'>>): string {
  return JSON.stringify(target === 'tip' ? x.d : x[target]);
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
  maxHeight = 460,
  fill = false,
}: CrossSectionProps) {
  const svgRef = useRef<SVGSVGElement>(null);
  // one SVG unit = one CSS pixel: labels and handles keep their size on small screens
  const figRef = useRef<HTMLDivElement>(null);
  // first drawn at the width of the placeholder it replaced (the figure fills its section), else a guess
  const W = Math.max(280, useWidth(figRef, useSectionWidth() ?? 640));
  const fillH = useFillHeight(figRef, fill);
  const H =
    fillH !== null
      ? Math.max(200, Math.round(fillH))
      : Math.round(Math.min(Math.max(240, maxHeight), Math.max(280, W * 0.62)));
  const keep = useRef<Kept>({ frame: null, view: null });
  const dragRef = useRef<{ target: Target; pointerId: number } | null>(null);
  const [dragging, setDragging] = useState<Target | null>(null);
  // the ray drawn last (from a render or a frame): pointer and key handlers work on what is shown
  const ray = useRef<CrossRay>({ o, d, c, r, res, distanceRatio });
  if (!drawRef) ray.current = { o, d, c, r, res, distanceRatio };
  const shown = useRef<Layout | null>(null);
  const size = useLabelSizer();
  // The labels are measured in their computed font, which forces the browser to compute the style
  // of everything changed since its last frame: right after the page has mounted, that is the whole
  // page, and it made the mounting task several times longer on a phone. So the draws before the
  // figure's first painted frame leave the labels hidden; the first draw after it places them (in
  // a task of its own, with styles already computed), and every later draw places them at once.
  // A figure mounted for a print places them at once (no frame comes before the print).
  const labelsOn = useRef(false);
  if (mountingForPrint()) labelsOn.current = true;
  const layout = (x: CrossRay) => layoutCross(x, fitExtra, W, H, dragging, keep.current);
  // Where the last key presses sent a handle, until a draw shows it (see `key` below). A draw that
  // shows the value last sent, or one no press of the chain sent (a link, a drag, the timeline),
  // ends the chain: the next press steps from what is drawn.
  const keyed = useRef<KeyChain | null>(null);
  const draw = (x: CrossRay) => {
    const chain = keyed.current;
    if (chain) keyed.current = afterDraw(chain, keyValue(chain.target, x));
    ray.current = x;
    const g = layout(x);
    shown.current = g;
    const fig = figRef.current;
    if (!fig) return;
    drawCross(fig, g, size, labelsOn.current);
    for (const target of ['o', 'tip', 'c', 'r'] as const) {
      const el = fig.querySelector(`[data-k="h-${target}"]`);
      const attrs = handleAria(g, x, target);
      for (const a in attrs) {
        const v = attrs[a as keyof typeof attrs];
        if (!el) continue;
        if (v === undefined) el.removeAttribute(a);
        else if (el.getAttribute(a) !== String(v)) el.setAttribute(a, String(v));
      }
    }
  };
  if (drawRef) drawRef.current = draw;
  const latest = useRef(draw);
  latest.current = draw;
  useLayoutEffect(() => draw(ray.current));
  useEffect(() => {
    let alive = true;
    void afterPaint().then(() => {
      if (!alive || labelsOn.current) return;
      labelsOn.current = true;
      latest.current(ray.current);
    });
    return () => {
      alive = false;
    };
  }, []);
  const cur = () => shown.current ?? layout(ray.current);

  const toWorld2 = (e: PointerEvent<SVGSVGElement>): [number, number] | null => {
    const svg = svgRef.current;
    const m = svg?.getScreenCTM();
    if (!svg || !m) return null;
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
    const g = cur();
    return [g.v.cx + (p.x - g.W / 2) * g.v.s, g.v.cy - (p.y - g.H / 2) * g.v.s];
  };

  /** Moves a handle to (x, y) in the figure; returns the patch it sent (null: none). */
  const apply = (target: Target, x: number, y: number): Partial<RaySphereParams> | null => {
    const g = cur();
    const { fr, O2, C2, dl, v, step } = g;
    const t = (q: Vec3) => tidyVec(q, step);
    let patch: Partial<RaySphereParams> | null = null;
    if (target === 'o') patch = { o: t(fromFrame(fr, x, y)) };
    else if (target === 'c') patch = { c: t(fromFrame(fr, x, y)) };
    else if (target === 'r') {
      const nr = Math.hypot(x - C2[0], y - C2[1]);
      if (nr > step) patch = { r: tidy(nr, step) };
    } else {
      const vx = x - O2[0];
      const vy = y - O2[1];
      const n = Math.hypot(vx, vy);
      if (n < 4 * v.s) return null;
      const w = dirFromFrame(fr, (vx / n) * dl, (vy / n) * dl);
      const ds = 10 ** Math.floor(Math.log10(dl / 500));
      const nd = tidyVec(w, ds);
      if (nd.some((z) => z !== 0)) patch = { d: nd };
    }
    if (patch) onChange(patch);
    return patch;
  };

  const down = (target: Target) => (e: PointerEvent<SVGElement>) => {
    e.preventDefault();
    keyed.current = null;
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
    const dr = dragRef.current;
    if (dr?.pointerId !== e.pointerId) return;
    dragRef.current = null;
    setDragging(null);
    // what was dragged, where it is now and what the ray does (a slider's keys say it themselves)
    const g = cur();
    const name = HANDLE_NAMES[dr.target];
    announce(
      `${name[0].toUpperCase()}${name.slice(1)}: ${handleText(dr.target, ray.current, g.dir2).valueText}`,
    );
  };
  // Arrow keys move a point 8 px in the figure (Shift: 1 px; Page Up / Down: 40 px). The radius is
  // a plain slider: Up / Right grow it, Down / Left shrink it.
  //
  // Presses can come faster than frames (a held key on a busy phone, a burst of input), while the
  // scene applies at most one edit per frame and the figure redraws after it: each press steps on
  // from where the previous press sent the handle, not from where it is drawn, or every press of a
  // frame but one would be lost (see `keyed`).
  const key = (target: Target) => (e: KeyboardEvent<SVGElement>) => {
    const g = cur();
    const px = e.key === 'PageUp' || e.key === 'PageDown' ? 40 : e.shiftKey ? 1 : 8;
    const k = px * g.v.s;
    const from = stepFrom(keyed.current, target);
    const remember = (at: KeyChain['at'], patch: Partial<RaySphereParams>) => {
      keyed.current = afterPress(
        keyed.current,
        target,
        at,
        keyValue(target, patch),
        keyValue(target, ray.current),
      );
    };
    if (target === 'r') {
      const sgn = { ArrowUp: 1, ArrowRight: 1, PageUp: 1, ArrowDown: -1, ArrowLeft: -1, PageDown: -1 }[e.key];
      if (!sgn) return;
      e.preventDefault();
      const step = e.shiftKey ? g.step / 10 : g.step;
      const nr = tidy((typeof from === 'number' ? from : g.r) + sgn * Math.max(k, step), step);
      if (nr > 0) {
        onChange({ r: nr });
        remember(nr, { r: nr });
      }
      return;
    }
    const dx = e.key === 'ArrowRight' ? k : e.key === 'ArrowLeft' ? -k : 0;
    const dy =
      e.key === 'ArrowUp' || e.key === 'PageUp' ? k : e.key === 'ArrowDown' || e.key === 'PageDown' ? -k : 0;
    if (!dx && !dy) return;
    e.preventDefault();
    const at = Array.isArray(from) ? from : target === 'o' ? g.O2 : target === 'tip' ? g.tip : g.C2;
    const to: [number, number] = [at[0] + dx, at[1] + dy];
    const patch = apply(target, to[0], to[1]);
    if (patch) remember(to, patch);
  };

  const handle = (target: Target, cls: string) => (
    <g
      className={`rs-handle ${cls}${dragging === target ? ' active' : ''}`}
      data-k={`h-${target}`}
      onPointerDown={down(target)}
      onKeyDown={key(target)}
      tabIndex={0}
      role="slider"
      aria-label={HANDLE_NAMES[target]}
      data-testid={`handle-${target}`}
    >
      <circle r={HANDLE_R} className="rs-handle-hit" />
      <circle r={13} className="rs-handle-ring" />
      <circle r={7.5} className="rs-handle-dot" />
      <path d="M-3.5,0H3.5M0,-3.5V3.5" className="rs-handle-grip" />
    </g>
  );

  return (
    <div className="rs-section" ref={figRef}>
      <svg
        ref={svgRef}
        viewBox={`0 0 ${W} ${H}`}
        className={`rs-svg${dragging ? ' dragging' : ''}`}
        width="100%"
        height={H}
        role="group"
        onPointerMove={move}
        onPointerUp={up}
        onPointerCancel={up}
        data-testid="cross-section"
      >
        <defs>
          <ArrowMarker id="rs-arrow" size={7} refX={8} headClassName="rs-arrowhead" />
        </defs>
        <circle data-k="circle" className="rs-circle" />
        <line data-k="back" className="rs-ray-back" />
        <line data-k="fwd" className="rs-ray" />
        <line data-k="dir" className="rs-dir" markerEnd="url(#rs-arrow)" />
        {[0, 1].map((i) => (
          <g key={i} data-k={`root${i}`} className="rs-root" display="none">
            <circle r={5} />
          </g>
        ))}
        {handle('o', 'h-o')}
        {handle('tip', 'h-d')}
        {handle('c', 'h-c')}
        {handle('r', 'h-r')}
        {/* labels after the handles: drawn on top, and placed where no handle is */}
        {[0, 1].map((i) => (
          <text key={i} data-k={`root${i}-label`} className="rs-label" display="none" />
        ))}
        <text data-k="o-label" className="rs-label">
          o
        </text>
        <text data-k="c-label" className="rs-label">
          C
        </text>
        <text data-k="r-label" className="rs-label">
          r
        </text>
        <text data-k="note" className="rs-note" display="none" />
        <text data-k="note2" className="rs-note" display="none" />
        <text data-k="note3" className="rs-note" display="none" />
      </svg>
      <p className="rs-caption">
        Plane through the ray and the centre. Solid: the ray (t&nbsp;≥&nbsp;0); dashed: the line behind the
        origin (t&nbsp;&lt;&nbsp;0); filled dots: the roots. Drag a ringed handle (<b>o</b>, the arrow tip for
        the direction, <b>C</b>, and the one on the rim for the radius), or focus it and use the arrow keys;
        or type the values.
      </p>
    </div>
  );
}
