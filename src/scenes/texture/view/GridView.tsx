/**
 * The texel grid with the query point and its path. Layers, so dragging and playing stay cheap:
 * 1. a canvas with the nearest-neighbour regions coloured by value (redrawn only when the grid or
 *    the conventions change),
 * 2. memoized SVG layers with the nodes, node lines and axes (below the stencil) and the value
 *    labels (above it, so the nearest-node highlight never covers a value),
 * 3. a small SVG layer with the nearest node and the bilinear stencil, and the query marker — the
 *    only parts that re-render per pointer event or animation frame,
 * 4. the path (line or circle) with its two draggable ends.
 * Everything is drawn in the texture's own frame (u right, v′ up; v′ = 1 − v when flipped) with the
 * query brought into [0, 1]² by the wrap mode (an equivalent point: the lookup there is the same).
 */
import { useWidth } from '../../../ui/useWidth';
import {
  memo,
  useEffect,
  useLayoutEffect,
  useMemo,
  useRef,
  type KeyboardEvent,
  type PointerEvent,
  type RefObject,
} from 'react';
import { nodeCoord, type LookupOptions, type TextureGrid } from '../../../core/texture';
import { darkTextOn, normalizeValue } from '../../../core/colormap';
import { pathPoint, textureImage, type Lookup, type QueryPath, type ShownTexture } from '../model';

const VB = 1000; // viewBox size of the plotted window
/** Smallest on-screen size of any text in the figure, in CSS pixels (at least 12 px on phones). */
const MIN_TEXT_PX = 12.5;
/** Radius of a handle's hit area in CSS pixels (a ≥ 24 px target on touch screens). */
const HANDLE_HIT_PX = 20;

export interface ViewWindow {
  min: number;
  max: number;
}

/** The plotted window of (u, v′): [0, 1] with room for texel-centre stencils that cross the edge. */
export function viewWindow(grid: TextureGrid, opts: LookupOptions): ViewWindow {
  const n = Math.min(grid.width, grid.height);
  const m = (opts.align === 'center' ? 0.5 / n : 0) + 0.08;
  return { min: -m, max: 1 + m };
}

/** Which thing a pointer or key moves: the path's start (u, v), its end (u2, v2), or the query itself. */
export type Grab = 'a' | 'b' | 'query';

interface Props extends ShownTexture {
  /** The lookup drawn (from {@link drawnLookup}). */
  q: Lookup;
  /** The query's path in the user's (u, v) (drawn in the texture frame). */
  path: QueryPath;
  /**
   * Called with texture-frame (u, v′) in [0, 1]²; final = pointer released / key pressed. `grab`:
   * 'b' moves the path's end, 'a' its start (the animation keeps its position), 'query' puts the
   * query there (the scene rewinds the animation to t = 0, where the query is the start).
   */
  onMove: (grab: Grab, u: number, vt: number, final: boolean) => void;
  editing: boolean;
  selected: { i: number; j: number } | null;
  onSelect: (i: number, j: number) => void;
  /** Enter on the grid while editing: go to the value field. */
  onEditEnter: () => void;
  present: boolean;
  /** Ask first: no nearest-node highlight and no bilinear stencil (they show the answers). */
  ask?: boolean;
  /** Set to a function that moves the query marker and the stencil to a lookup directly (per animation frame). */
  drawRef?: { current: ((q: Lookup) => void) | null };
}

export function GridView({
  grid,
  opts,
  range,
  q,
  path,
  onMove,
  editing,
  selected,
  onSelect,
  onEditEnter,
  present,
  ask = false,
  drawRef,
}: Props) {
  const win = useMemo(() => viewWindow(grid, opts), [grid, opts]);
  const svgRef = useRef<SVGSVGElement>(null);
  const markerRef = useRef<SVGGElement>(null);
  const stencilRef = useRef<SVGGElement>(null);
  if (drawRef) {
    // per-frame drawing of the moving query without React (see ./anim.ts)
    drawRef.current = (dq: Lookup) => {
      const m = markerRef.current;
      if (m) m.setAttribute('transform', `translate(${sx(dq.bil.u, win)} ${sy(dq.bil.v, win)})`);
      const st = stencilRef.current;
      if (st) drawStencil(st, queryGeometry(grid, win, dq));
    };
  }
  const dragging = useRef<Grab | null>(null);
  const pending = useRef<{ u: number; v: number } | null>(null);
  const raf = useRef(0);
  const moveRef = useRef(onMove);
  moveRef.current = onMove;
  useEffect(() => () => cancelAnimationFrame(raf.current), []);
  // viewBox units per CSS pixel, so text and handles keep a minimum on-screen size
  const unitsPerPx = VB / useWidth(svgRef, 520);

  const flip = (v: number) => (opts.vflip ? 1 - v : v);
  const aT = { u: path.a[0], v: flip(path.a[1]) };
  const bT = { u: path.b[0], v: flip(path.b[1]) };

  const toUV = (e: PointerEvent<SVGSVGElement>) => {
    const r = svgRef.current!.getBoundingClientRect();
    const fx = (e.clientX - r.left) / r.width;
    const fy = (e.clientY - r.top) / r.height;
    const span = win.max - win.min;
    const clamp01 = (t: number) => Math.min(1, Math.max(0, t));
    return {
      u: round4(clamp01(win.min + fx * span)),
      v: round4(clamp01(win.max - fy * span)),
      x: fx * VB,
      y: fy * VB,
    };
  };

  const nodeAt = (u: number, v: number) => {
    const pick = (t: number, n: number) =>
      opts.align === 'corner' ? Math.round(t * (n - 1)) : Math.min(n - 1, Math.floor(t * n));
    return { i: pick(u, grid.width), j: pick(v, grid.height) };
  };

  const onPointerDown = (e: PointerEvent<SVGSVGElement>) => {
    if (e.button !== 0) return;
    const p = toUV(e);
    if (editing) {
      const n = nodeAt(p.u, p.v);
      onSelect(n.i, n.j);
      return;
    }
    const hit = HANDLE_HIT_PX * unitsPerPx;
    const near = (h: { u: number; v: number }) => Math.hypot(sx(h.u, win) - p.x, sy(h.v, win) - p.y) <= hit;
    const grab: Grab = near(bT) ? 'b' : near(aT) ? 'a' : 'query';
    e.currentTarget.setPointerCapture(e.pointerId);
    dragging.current = grab;
    moveRef.current(grab, p.u, p.v, false);
  };
  const onPointerMove = (e: PointerEvent<SVGSVGElement>) => {
    if (!dragging.current) return;
    pending.current = toUV(e);
    if (!raf.current) {
      raf.current = requestAnimationFrame(() => {
        raf.current = 0;
        const p = pending.current;
        if (p && dragging.current) moveRef.current(dragging.current, p.u, p.v, false);
      });
    }
  };
  const end = (e: PointerEvent<SVGSVGElement>) => {
    const grab = dragging.current;
    if (!grab) return;
    dragging.current = null;
    cancelAnimationFrame(raf.current);
    raf.current = 0;
    const p = pending.current ?? toUV(e);
    pending.current = null;
    moveRef.current(grab, p.u, p.v, true);
  };
  const arrow = (e: KeyboardEvent, from: { u: number; v: number }, grab: Grab) => {
    const step = e.shiftKey ? 0.1 : 0.01;
    let { u, v } = from;
    if (e.key === 'ArrowLeft') u -= step;
    else if (e.key === 'ArrowRight') u += step;
    else if (e.key === 'ArrowUp') v += step;
    else if (e.key === 'ArrowDown') v -= step;
    else return;
    e.preventDefault();
    e.stopPropagation();
    moveRef.current(grab, round4(Math.min(1, Math.max(0, u))), round4(Math.min(1, Math.max(0, v))), true);
  };
  const onKeyDown = (e: KeyboardEvent<SVGSVGElement>) => {
    if (e.target !== e.currentTarget) return; // the end handle has its own keys
    if (editing) {
      const cur = selected ?? { i: q.near.i, j: q.near.j };
      let { i, j } = cur;
      if (e.key === 'ArrowLeft') i--;
      else if (e.key === 'ArrowRight') i++;
      else if (e.key === 'ArrowUp') j++;
      else if (e.key === 'ArrowDown') j--;
      else if (e.key === 'Enter') {
        e.preventDefault();
        if (!selected) onSelect(i, j);
        onEditEnter();
        return;
      } else return;
      e.preventDefault();
      onSelect(Math.min(grid.width - 1, Math.max(0, i)), Math.min(grid.height - 1, Math.max(0, j)));
      return;
    }
    arrow(e, q.bil, 'query');
  };
  const bIn = inWindow(bT, win);
  // what the grid's memoized layers are drawn from
  const layer = { grid, opts, range, win, unitsPerPx, present };

  return (
    <div className={`tx-grid${present ? ' present' : ''}`}>
      <div className="tx-grid-box">
        <BaseCanvas grid={grid} opts={opts} range={range} win={win} />
        <svg
          ref={svgRef}
          className={`tx-grid-svg${editing ? ' editing' : ''}`}
          viewBox={`0 0 ${VB} ${VB}`}
          role="application"
          aria-roledescription="texel grid"
          aria-label={
            editing
              ? `Texel grid, editing: arrow keys choose a node${selected ? ` (now column ${selected.i}, row ${selected.j})` : ''}, Enter goes to its value; or click a node`
              : `Texel grid: the query point is at (${fmtShort(q.bil.u)}, ${fmtShort(q.bil.v)}). Arrow keys move it by 0.01 (Shift: 0.1), back at the start of its path; click or drag to move it; drag the square to move the path's end`
          }
          tabIndex={0}
          data-testid="texel-grid"
          onPointerDown={onPointerDown}
          onPointerMove={onPointerMove}
          onPointerUp={end}
          onPointerCancel={end}
          onKeyDown={onKeyDown}
        >
          <StaticLayer {...layer} />
          {ask ? null : <QueryLayer grid={grid} win={win} q={q} gRef={stencilRef} />}
          <LabelLayer {...layer} />
          <PathLayer path={path} vflip={opts.vflip} win={win} />
          <g
            ref={markerRef}
            className="tx-query"
            transform={`translate(${sx(q.bil.u, win)} ${sy(q.bil.v, win)})`}
            data-testid="query-marker"
          >
            <circle r={11} />
            <line x1={-22} x2={22} y1={0} y2={0} />
            <line y1={-22} y2={22} x1={0} x2={0} />
          </g>
          {inWindow(aT, win) ? (
            <g
              className="tx-handle a"
              transform={`translate(${sx(aT.u, win)} ${sy(aT.v, win)})`}
              aria-hidden="true"
            >
              <circle className="tx-handle-focus" r={Math.max(30, 16 * unitsPerPx)} />
              <circle className="tx-handle-mark" r={Math.max(14, 7 * unitsPerPx)} />
            </g>
          ) : null}
          {bIn ? (
            <g
              className="tx-handle b"
              transform={`translate(${sx(bT.u, win)} ${sy(bT.v, win)})`}
              tabIndex={editing ? -1 : 0}
              role="application"
              aria-roledescription="draggable point"
              aria-label={`End of the query's path at (u, v) = (${fmtShort(path.b[0])}, ${fmtShort(path.b[1])}): arrow keys move it by 0.01 (Shift: 0.1)`}
              data-testid="path-end-handle"
              onKeyDown={(e) => arrow(e, bT, 'b')}
            >
              <circle className="tx-handle-hit" r={HANDLE_HIT_PX * unitsPerPx} />
              <circle className="tx-handle-focus" r={Math.max(30, 16 * unitsPerPx)} />
              <rect
                className="tx-handle-mark"
                x={-Math.max(13, 7 * unitsPerPx)}
                y={-Math.max(13, 7 * unitsPerPx)}
                width={2 * Math.max(13, 7 * unitsPerPx)}
                height={2 * Math.max(13, 7 * unitsPerPx)}
              />
            </g>
          ) : null}
          {editing && selected ? (
            <circle
              cx={sx(nodeCoord(selected.i, grid.width, opts.align), win)}
              cy={sy(nodeCoord(selected.j, grid.height, opts.align), win)}
              r={Math.max(6, Math.min(22, (VB / Math.max(grid.width, grid.height)) * 0.22)) + 10}
              className="tx-selected"
            />
          ) : null}
        </svg>
      </div>
      <div className="tx-axis-note">
        u → right, {opts.vflip ? 'v′ = 1 − v' : 'v'} → up ·{' '}
        {opts.align === 'corner' ? 'nodes at i/(N − 1)' : 'texel centres at (i + ½)/N'} · ○ start (u, v) · □
        end (u₂, v₂)
      </div>
    </div>
  );
}

/** The four taps with their values and weights, and the magnified cell (follows the query). */
export function StencilDetail({
  q,
  drawRef,
}: {
  q: Lookup;
  drawRef?: { current: ((q: Lookup, text: boolean) => void) | null };
}) {
  const listRef = useRef<HTMLUListElement>(null);
  const closeRef = useRef<SVGSVGElement>(null);
  // The numbers are written directly (here after each render, and per animation frame through
  // drawRef without React): React renders the elements, not their changing text.
  const draw = (dq: Lookup, text: boolean) => {
    const ul = listRef.current;
    if (ul && text) {
      const b = dq.bil;
      const taps: [number, number, number, number][] = [
        [b.i0, b.j0, b.t00, b.w00],
        [b.i1, b.j0, b.t10, b.w10],
        [b.i0, b.j1, b.t01, b.w01],
        [b.i1, b.j1, b.t11, b.w11],
      ];
      const items = ul.children;
      for (let k = 0; k < 4 && k < items.length; k++) {
        const [i, j, t, w] = taps[k];
        const li = items[k] as HTMLElement;
        li.setAttribute('data-weight', String(w));
        setText(li.children[1], `${i},${j}`);
        setText(li.children[2], `=${fmtShort(t)}, w=${fmtShort(w)}`);
      }
    }
    // the close-up follows at the text's rate too (the grid's stencil moves every frame)
    if (closeRef.current && text) drawCloseUp(closeRef.current, dq, text);
  };
  if (drawRef) drawRef.current = draw;
  useLayoutEffect(() => draw(q, true));
  return (
    <div className="tx-closeup-row">
      <CellCloseUp svgRef={closeRef} />
      <ul
        className="tx-taps"
        aria-label="The four bilinear taps and their weights"
        data-testid="taps"
        ref={listRef}
      >
        {TAP_CLASS.map((cls) => (
          <li key={cls} data-testid={`tap-${cls}`}>
            <span className={`tx-chip ${cls}`} />T<sub />
            <span />
          </li>
        ))}
      </ul>
    </div>
  );
}

/** Sets an attribute if it changed (an unchanged write still invalidates style; per frame that adds up). */
function setAttr(el: Element, a: string, v: number): void {
  const s = String(v);
  if (el.getAttribute(a) !== s) el.setAttribute(a, s);
}

/** Sets an element's text if it changed (the element's children are not React's). */
function setText(el: Element | undefined | null, text: string): void {
  if (el && el.textContent !== text) el.textContent = text;
}

function inWindow(p: { u: number; v: number }, win: ViewWindow): boolean {
  return p.u >= win.min && p.u <= win.max && p.v >= win.min && p.v <= win.max;
}

function round4(x: number): number {
  return Math.round(x * 10000) / 10000;
}

function sx(u: number, win: ViewWindow): number {
  return ((u - win.min) / (win.max - win.min)) * VB;
}
function sy(v: number, win: ViewWindow): number {
  return ((win.max - v) / (win.max - win.min)) * VB;
}

/** Nearest-neighbour regions as an image (outside [0, 1]² dimmed by the SVG layer). */
const BaseCanvas = memo(function BaseCanvas({ grid, opts, range, win }: ShownTexture & { win: ViewWindow }) {
  const ref = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    const c = ref.current;
    if (!c) return;
    const res = 400;
    c.width = res;
    c.height = res;
    const g = c.getContext('2d');
    if (!g) return;
    const img = textureImage(grid, { ...opts, vflip: false }, 'nearest', res, res, range, {
      uMin: win.min,
      uMax: win.max,
      vMin: win.min,
      vMax: win.max,
    });
    g.putImageData(new ImageData(img as Uint8ClampedArray<ArrayBuffer>, res, res), 0, 0);
  }, [grid, opts, range, win]);
  return <canvas ref={ref} className="tx-grid-canvas" aria-hidden="true" />;
});

/** What the SVG layers over the texture draw from: the texture, the window, the scale, the mode. */
type LayerProps = ShownTexture & { win: ViewWindow; unitsPerPx: number; present: boolean };

/** A node of the grid where it stands in the window, with its value (and that value in [0, 1]). */
interface PlacedNode {
  i: number;
  j: number;
  x: number;
  y: number;
  value: number;
  t: number;
}

/** One element per node of the grid, row by row. */
function mapNodes(
  { grid, opts, range, win }: ShownTexture & { win: ViewWindow },
  draw: (node: PlacedNode) => React.ReactNode,
): React.ReactNode[] {
  const W = grid.width;
  const H = grid.height;
  const items: React.ReactNode[] = [];
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      const value = grid.values[j * W + i];
      items.push(
        draw({
          i,
          j,
          x: sx(nodeCoord(i, W, opts.align), win),
          y: sy(nodeCoord(j, H, opts.align), win),
          value,
          t: normalizeValue(value, range.min, range.max),
        }),
      );
    }
  }
  return items;
}

const StaticLayer = memo(function StaticLayer({ unitsPerPx, present, ...shown }: LayerProps) {
  const { grid, opts, win } = shown;
  const W = grid.width;
  const H = grid.height;
  const nmax = Math.max(W, H);
  const showDots = nmax <= 32;
  const items: React.ReactNode[] = [];
  // node lines (the bilinear cells' edges run through the nodes)
  if (nmax <= 32) {
    const line = (key: string, x1: number, y1: number, x2: number, y2: number) => (
      <line key={key} x1={x1} x2={x2} y1={y1} y2={y2} className="tx-node-line" />
    );
    const [u0, u1] = [sx(nodeCoord(0, W, opts.align), win), sx(nodeCoord(W - 1, W, opts.align), win)];
    const [v0, v1] = [sy(nodeCoord(0, H, opts.align), win), sy(nodeCoord(H - 1, H, opts.align), win)];
    for (let i = 0; i < W; i++) {
      const x = sx(nodeCoord(i, W, opts.align), win);
      items.push(line(`vl${i}`, x, v0, x, v1));
    }
    for (let j = 0; j < H; j++) {
      const y = sy(nodeCoord(j, H, opts.align), win);
      items.push(line(`hl${j}`, u0, y, u1, y));
    }
  }
  if (showDots)
    items.push(
      ...mapNodes(shown, ({ i, j, x, y, t }) => (
        <circle
          key={`d${i}-${j}`}
          cx={x}
          cy={y}
          r={nmax <= 16 ? 5 : 3}
          className={darkTextOn(t) ? 'tx-dot dark' : 'tx-dot'}
        />
      )),
    );
  // outside [0, 1]²: dim (this is where addressing decides)
  const x0 = sx(0, win);
  const x1 = sx(1, win);
  const y0 = sy(1, win);
  const y1 = sy(0, win);
  // ticks: at least 12.5 px on screen, 18 px in classroom mode
  const tickFont = Math.max(28, (present ? 18 : MIN_TEXT_PX) * unitsPerPx);
  // ticks at the nodes while they fit (a label is about 2.2 em wide), else 0, ½, 1
  const fits = (n: number) => n <= 5 && VB / (win.max - win.min) / Math.max(1, n - 1) > tickFont * 2.4;
  const ticks = fits(W) ? Array.from({ length: W }, (_, i) => nodeCoord(i, W, opts.align)) : [0, 0.5, 1];
  // v ticks sit in the left margin: keep those whose text fits there (monospace ≈ 0.62 em a digit)
  const vticks = (
    fits(H) ? Array.from({ length: H }, (_, j) => nodeCoord(j, H, opts.align)) : [0, 0.5, 1]
  ).filter((t) => 0.62 * tickFont * String(Number(t.toPrecision(3))).length + 4 <= x0 + 4);
  return (
    <g>
      <path
        d={`M0 0H${VB}V${VB}H0Z M${x0} ${y0}V${y1}H${x1}V${y0}Z`}
        className="tx-outside"
        fillRule="evenodd"
      />
      {items}
      <rect x={x0} y={y0} width={x1 - x0} height={y1 - y0} className="tx-frame" />
      {ticks.map((t) => (
        <text
          key={`ut${t}`}
          x={sx(t, win)}
          y={VB - 6}
          className="tx-tick"
          textAnchor="middle"
          fontSize={tickFont}
        >
          {Number(t.toPrecision(3))}
        </text>
      ))}
      {vticks.map((t) => (
        <text key={`vt${t}`} x={4} y={sy(t, win) + tickFont * 0.35} className="tx-tick" fontSize={tickFont}>
          {Number(t.toPrecision(3))}
        </text>
      ))}
    </g>
  );
});

/**
 * The node values, above the stencil and the nearest-node highlight so neither covers them. Each
 * label has a solid halo of the opposite colour, so it keeps its contrast on every cell colour and
 * on the dimmed border; labels are left out when they would be smaller than 12 px on screen.
 */
const LabelLayer = memo(function LabelLayer({ unitsPerPx, present, ...shown }: LayerProps) {
  const nmax = Math.max(shown.grid.width, shown.grid.height);
  const fontSize = Math.min(present ? 56 : 38, (VB / (nmax + 0.5)) * 0.34);
  if (nmax > 16 || fontSize / unitsPerPx < 12) return null;
  return (
    <g className="tx-labels">
      {mapNodes(shown, ({ i, j, x, y, value, t }) => (
        <text
          key={`t${i}-${j}`}
          x={x + 8}
          y={y - 8}
          fontSize={fontSize}
          className={darkTextOn(t) ? 'tx-val dark' : 'tx-val'}
          data-testid="node-label"
        >
          {fmtShort(value)}
        </text>
      ))}
    </g>
  );
});

/** The query's path (clipped to the plotted window). */
const PathLayer = memo(function PathLayer({
  path,
  vflip,
  win,
}: {
  path: QueryPath;
  vflip: boolean;
  win: ViewWindow;
}) {
  const n = path.kind === 'line' ? 1 : 96;
  const pts: string[] = [];
  for (let k = 0; k <= n; k++) {
    const p = pathPoint(path, k / n);
    pts.push(`${sx(p.u, win).toFixed(1)},${sy(vflip ? 1 - p.v : p.v, win).toFixed(1)}`);
  }
  return (
    <g aria-hidden="true">
      <clipPath id="tx-window">
        <rect x={0} y={0} width={VB} height={VB} />
      </clipPath>
      <polyline points={pts.join(' ')} className="tx-path" clipPath="url(#tx-window)" />
    </g>
  );
});

const TAP_CLASS = ['w00', 'w10', 'w01', 'w11'];

interface QueryGeometry {
  rects: { cls: string; x: number; y: number; w: number; h: number }[];
  cell: { x: number; y: number; w: number; h: number };
  taps: { x: number; y: number }[];
  ringR: number;
  nearest: { x: number; y: number; size: number };
}

/** Where the stencil's shapes go for a lookup (shared by the React layer and the per-frame drawer). */
function queryGeometry(grid: TextureGrid, win: ViewWindow, q: Lookup): QueryGeometry {
  const b = q.bil;
  const X = (u: number) => sx(u, win);
  const Y = (v: number) => sy(v, win);
  const qx = X(b.u);
  const qy = Y(b.v);
  // sub-rectangles: each tap's weight is the area of the sub-rectangle opposite to it
  const rects = [
    { cls: 'w00', x: qx, y: Y(b.v1), w: Math.max(0, X(b.u1) - qx), h: Math.max(0, qy - Y(b.v1)) }, // opposite (u0, v0): upper right
    { cls: 'w10', x: X(b.u0), y: Y(b.v1), w: Math.max(0, qx - X(b.u0)), h: Math.max(0, qy - Y(b.v1)) }, // opposite (u1, v0): upper left
    { cls: 'w01', x: qx, y: qy, w: Math.max(0, X(b.u1) - qx), h: Math.max(0, Y(b.v0) - qy) }, // opposite (u0, v1): lower right
    { cls: 'w11', x: X(b.u0), y: qy, w: Math.max(0, qx - X(b.u0)), h: Math.max(0, Y(b.v0) - qy) }, // opposite (u1, v1): lower left
  ];
  const taps = [
    { x: X(b.u0), y: Y(b.v0) },
    { x: X(b.u1), y: Y(b.v0) },
    { x: X(b.u0), y: Y(b.v1) },
    { x: X(b.u1), y: Y(b.v1) },
  ];
  const nmax = Math.max(grid.width, grid.height);
  const ringR = Math.max(6, Math.min(22, (VB / nmax) * 0.22));
  return {
    rects,
    cell: { x: X(b.u0), y: Y(b.v1), w: X(b.u1) - X(b.u0), h: Y(b.v0) - Y(b.v1) },
    taps,
    ringR,
    nearest: { x: X(q.near.nodeU) - ringR - 6, y: Y(q.near.nodeV) - ringR - 6, size: 2 * ringR + 12 },
  };
}

/** Writes a geometry into the children QueryLayer rendered (4 weight rects, the cell, 4 taps, the nearest box). */
function drawStencil(g: SVGGElement, geo: QueryGeometry): void {
  const kids = g.children;
  if (kids.length !== 10) return;
  const set = setAttr;
  for (let k = 0; k < 4; k++) {
    const r = geo.rects[k];
    set(kids[k], 'x', r.x);
    set(kids[k], 'y', r.y);
    set(kids[k], 'width', r.w);
    set(kids[k], 'height', r.h);
  }
  set(kids[4], 'x', geo.cell.x);
  set(kids[4], 'y', geo.cell.y);
  set(kids[4], 'width', geo.cell.w);
  set(kids[4], 'height', geo.cell.h);
  for (let k = 0; k < 4; k++) {
    set(kids[5 + k], 'cx', geo.taps[k].x);
    set(kids[5 + k], 'cy', geo.taps[k].y);
  }
  set(kids[9], 'x', geo.nearest.x);
  set(kids[9], 'y', geo.nearest.y);
}

/** The nearest node and the bilinear stencil with its weight rectangles (below the labels). */
const QueryLayer = memo(function QueryLayer({
  grid,
  win,
  q,
  gRef,
}: {
  grid: TextureGrid;
  win: ViewWindow;
  q: Lookup;
  gRef?: RefObject<SVGGElement | null>;
}) {
  const geo = queryGeometry(grid, win, q);
  return (
    <g data-testid="stencil" ref={gRef}>
      {geo.rects.map((r) => (
        <rect key={r.cls} x={r.x} y={r.y} width={r.w} height={r.h} className={`tx-wrect ${r.cls}`} />
      ))}
      <rect x={geo.cell.x} y={geo.cell.y} width={geo.cell.w} height={geo.cell.h} className="tx-cell" />
      {geo.taps.map((t, k) => (
        <circle key={k} cx={t.x} cy={t.y} r={geo.ringR} className={`tx-tap ${TAP_CLASS[k]}`} />
      ))}
      <rect
        x={geo.nearest.x}
        y={geo.nearest.y}
        width={geo.nearest.size}
        height={geo.nearest.size}
        className="tx-nearest"
        rx={4}
        data-testid="nearest-highlight"
      />
    </g>
  );
});

/** Short label: up to 4 significant digits. */
export function fmtShort(x: number): string {
  if (!Number.isFinite(x)) return '—';
  const s = Number(x.toPrecision(4));
  return String(s);
}

const CU_S = 200;
const CU_P = 34; // padding for the corner labels
const CU_C = CU_S - 2 * CU_P;
/** Corner nodes of the close-up (order of TAP_CLASS: w00, w10, w01, w11) and their label offsets. */
const CU_CORNERS = [
  { cx: CU_P, cy: CU_P + CU_C, dy: 26 },
  { cx: CU_P + CU_C, cy: CU_P + CU_C, dy: 26 },
  { cx: CU_P, cy: CU_P, dy: -14 },
  { cx: CU_P + CU_C, cy: CU_P, dy: -14 },
];

/**
 * The bilinear cell magnified: its four node values at the corners, the query at (fu, fv) inside,
 * and each node's weight written in the sub-rectangle opposite to it (same colour). React renders
 * the elements; {@link drawCloseUp} places them for a lookup (after each render and per frame).
 */
function CellCloseUp({ svgRef }: { svgRef: RefObject<SVGSVGElement | null> }) {
  return (
    <svg
      ref={svgRef}
      className="tx-closeup"
      viewBox={`0 0 ${CU_S} ${CU_S}`}
      role="img"
      data-testid="cell-closeup"
    >
      {TAP_CLASS.map((cls) => (
        <g key={cls}>
          <rect className={`tx-wrect ${cls}`} />
          <text textAnchor="middle" className="tx-closeup-w" />
        </g>
      ))}
      <rect x={CU_P} y={CU_P} width={CU_C} height={CU_C} className="tx-closeup-cell" />
      {TAP_CLASS.map((cls, k) => (
        <g key={cls}>
          <circle cx={CU_CORNERS[k].cx} cy={CU_CORNERS[k].cy} r={6} className={`tx-tap ${cls}`} />
          <text
            x={CU_CORNERS[k].cx}
            y={CU_CORNERS[k].cy + CU_CORNERS[k].dy}
            textAnchor="middle"
            className="tx-closeup-t"
          />
        </g>
      ))}
      <circle r={5} className="tx-closeup-q" />
    </svg>
  );
}

/** Places the close-up's weight rectangles and query for a lookup; with `text`, its numbers and label too. */
function drawCloseUp(svg: SVGSVGElement, q: Lookup, text: boolean): void {
  const kids = svg.children;
  if (kids.length !== 10) return;
  const b = q.bil;
  const x = CU_P + b.fu * CU_C;
  const y = CU_P + (1 - b.fv) * CU_C;
  const rects = [
    { x0: x, y0: CU_P, x1: CU_P + CU_C, y1: y, w: b.w00 },
    { x0: CU_P, y0: CU_P, x1: x, y1: y, w: b.w10 },
    { x0: x, y0: y, x1: CU_P + CU_C, y1: CU_P + CU_C, w: b.w01 },
    { x0: CU_P, y0: y, x1: x, y1: CU_P + CU_C, w: b.w11 },
  ];
  const set = setAttr;
  for (let k = 0; k < 4; k++) {
    const r = rects[k];
    const [rect, label] = kids[k].children;
    set(rect!, 'x', r.x0);
    set(rect!, 'y', r.y0);
    set(rect!, 'width', Math.max(0, r.x1 - r.x0));
    set(rect!, 'height', Math.max(0, r.y1 - r.y0));
    // a weight is written only where its rectangle has room for it
    const room = r.x1 - r.x0 > 30 && r.y1 - r.y0 > 16;
    set(label!, 'x', (r.x0 + r.x1) / 2);
    set(label!, 'y', (r.y0 + r.y1) / 2 + 5);
    const vis = room ? 'visible' : 'hidden';
    if (label!.getAttribute('visibility') !== vis) label!.setAttribute('visibility', vis);
    if (text) setText(label, String(Number(r.w.toPrecision(3))));
  }
  const values = [b.t00, b.t10, b.t01, b.t11];
  for (let k = 0; k < 4; k++) setText(kids[5 + k].children[1], fmtShort(values[k]));
  if (text) {
    svg.setAttribute(
      'aria-label',
      `The bilinear cell magnified: the query sits at fu = ${fmtShort(b.fu)}, fv = ${fmtShort(b.fv)} inside it`,
    );
  }
  set(kids[9], 'cx', x);
  set(kids[9], 'cy', y);
}
