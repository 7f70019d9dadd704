/**
 * The texel grid with the query point. Three layers, so dragging stays cheap:
 * 1. a canvas with the nearest-neighbour regions coloured by value (redrawn only when the grid or
 *    the conventions change),
 * 2. a memoized SVG layer with the nodes, their values, the node lines and the axes,
 * 3. a small SVG layer with the query marker, the nearest node and the bilinear stencil — the only
 *    part that re-renders per pointer event.
 * Everything is drawn in the texture's own frame (u right, v′ up; v′ = 1 − v when flipped) with the
 * query brought into [0, 1]² by the wrap mode (an equivalent point: the lookup there is the same).
 */
import { memo, useEffect, useMemo, useRef, type KeyboardEvent, type PointerEvent } from 'react';
import { nodeCoord, type LookupOptions, type TextureGrid } from '../../../core/texture';
import { colorCss, darkTextOn, normalizeValue } from '../colormap';
import { textureImage, type Lookup } from '../model';

const VB = 1000; // viewBox size of the plotted window

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

interface Props {
  grid: TextureGrid;
  opts: LookupOptions;
  range: { min: number; max: number };
  /** The lookup drawn (from {@link drawnLookup}). */
  q: Lookup;
  /** Called with texture-frame (u, v′) in [0, 1]²; final = pointer released / key pressed. */
  onMove: (u: number, vt: number, final: boolean) => void;
  editing: boolean;
  selected: { i: number; j: number } | null;
  onSelect: (i: number, j: number) => void;
  present: boolean;
}

export function GridView({ grid, opts, range, q, onMove, editing, selected, onSelect, present }: Props) {
  const win = useMemo(() => viewWindow(grid, opts), [grid, opts]);
  const svgRef = useRef<SVGSVGElement>(null);
  const dragging = useRef(false);
  const pending = useRef<{ u: number; v: number } | null>(null);
  const raf = useRef(0);
  const moveRef = useRef(onMove);
  moveRef.current = onMove;
  useEffect(() => () => cancelAnimationFrame(raf.current), []);

  const toUV = (e: PointerEvent<SVGSVGElement>) => {
    const r = svgRef.current!.getBoundingClientRect();
    const fx = (e.clientX - r.left) / r.width;
    const fy = (e.clientY - r.top) / r.height;
    const span = win.max - win.min;
    const clamp01 = (t: number) => Math.min(1, Math.max(0, t));
    return { u: round4(clamp01(win.min + fx * span)), v: round4(clamp01(win.max - fy * span)) };
  };

  const nodeAt = (u: number, v: number) => {
    const pick = (t: number, n: number) => (opts.align === 'corner' ? Math.round(t * (n - 1)) : Math.min(n - 1, Math.floor(t * n)));
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
    e.currentTarget.setPointerCapture(e.pointerId);
    dragging.current = true;
    moveRef.current(p.u, p.v, false);
  };
  const onPointerMove = (e: PointerEvent<SVGSVGElement>) => {
    if (!dragging.current) return;
    pending.current = toUV(e);
    if (!raf.current) {
      raf.current = requestAnimationFrame(() => {
        raf.current = 0;
        const p = pending.current;
        if (p) moveRef.current(p.u, p.v, false);
      });
    }
  };
  const end = (e: PointerEvent<SVGSVGElement>) => {
    if (!dragging.current) return;
    dragging.current = false;
    cancelAnimationFrame(raf.current);
    raf.current = 0;
    const p = pending.current ?? toUV(e);
    pending.current = null;
    moveRef.current(p.u, p.v, true);
  };
  const onKeyDown = (e: KeyboardEvent<SVGSVGElement>) => {
    const step = e.shiftKey ? 0.1 : 0.01;
    let { u, v } = q.bil;
    if (e.key === 'ArrowLeft') u -= step;
    else if (e.key === 'ArrowRight') u += step;
    else if (e.key === 'ArrowUp') v += step;
    else if (e.key === 'ArrowDown') v -= step;
    else return;
    e.preventDefault();
    moveRef.current(round4(Math.min(1, Math.max(0, u))), round4(Math.min(1, Math.max(0, v))), true);
  };

  return (
    <div className={`tx-grid${present ? ' present' : ''}`}>
      <div className="tx-grid-box">
        <BaseCanvas grid={grid} opts={opts} range={range} win={win} />
        <svg
          ref={svgRef}
          className={`tx-grid-svg${editing ? ' editing' : ''}`}
          viewBox={`0 0 ${VB} ${VB}`}
          role="application"
          aria-label={
            editing
              ? 'Texel grid: click a node to edit its value'
              : 'Texel grid: click or drag to move the query point; arrow keys move it by 0.01 (Shift: 0.1)'
          }
          tabIndex={0}
          data-testid="texel-grid"
          onPointerDown={onPointerDown}
          onPointerMove={onPointerMove}
          onPointerUp={end}
          onPointerCancel={end}
          onKeyDown={onKeyDown}
        >
          <StaticLayer grid={grid} opts={opts} range={range} win={win} present={present} />
          <QueryLayer grid={grid} opts={opts} win={win} q={q} selected={editing ? selected : null} />
        </svg>
      </div>
      <div className="tx-closeup-row">
        <CellCloseUp q={q} />
        <ul className="tx-taps" aria-label="The four bilinear taps and their weights">
          {(
            [
              ['w00', q.bil.i0, q.bil.j0, q.bil.t00, q.bil.w00],
              ['w10', q.bil.i1, q.bil.j0, q.bil.t10, q.bil.w10],
              ['w01', q.bil.i0, q.bil.j1, q.bil.t01, q.bil.w01],
              ['w11', q.bil.i1, q.bil.j1, q.bil.t11, q.bil.w11],
            ] as const
          ).map(([cls, i, j, t, w]) => (
            <li key={cls}>
              <span className={`tx-chip ${cls}`} />
              T<sub>{i},{j}</sub>={fmtShort(t)}, w={fmtShort(w)}
            </li>
          ))}
        </ul>
      </div>
      <div className="tx-axis-note">
        u → right, {opts.vflip ? 'v′ = 1 − v' : 'v'} → up · {opts.align === 'corner' ? 'nodes at i/(N − 1)' : 'texel centres at (i + ½)/N'}
      </div>
    </div>
  );
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
const BaseCanvas = memo(function BaseCanvas({ grid, opts, range, win }: { grid: TextureGrid; opts: LookupOptions; range: { min: number; max: number }; win: ViewWindow }) {
  const ref = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    const c = ref.current;
    if (!c) return;
    const res = 400;
    c.width = res;
    c.height = res;
    const g = c.getContext('2d');
    if (!g) return;
    const img = textureImage(grid, { ...opts, vflip: false }, 'nearest', res, res, range, { uMin: win.min, uMax: win.max, vMin: win.min, vMax: win.max });
    g.putImageData(new ImageData(img as Uint8ClampedArray<ArrayBuffer>, res, res), 0, 0);
  }, [grid, opts, range, win]);
  return <canvas ref={ref} className="tx-grid-canvas" aria-hidden="true" />;
});

const StaticLayer = memo(function StaticLayer({
  grid,
  opts,
  range,
  win,
  present,
}: {
  grid: TextureGrid;
  opts: LookupOptions;
  range: { min: number; max: number };
  win: ViewWindow;
  present: boolean;
}) {
  const W = grid.width;
  const H = grid.height;
  const nmax = Math.max(W, H);
  const showLabels = nmax <= 16;
  const showDots = nmax <= 32;
  const fontSize = Math.min(present ? 44 : 38, (VB / (nmax + 0.5)) * 0.34);
  const items: React.ReactNode[] = [];
  // node lines (the bilinear cells' edges run through the nodes)
  if (nmax <= 32) {
    for (let i = 0; i < W; i++) {
      const x = sx(nodeCoord(i, W, opts.align), win);
      items.push(<line key={`vl${i}`} x1={x} x2={x} y1={sy(nodeCoord(0, H, opts.align), win)} y2={sy(nodeCoord(H - 1, H, opts.align), win)} className="tx-node-line" />);
    }
    for (let j = 0; j < H; j++) {
      const y = sy(nodeCoord(j, H, opts.align), win);
      items.push(<line key={`hl${j}`} y1={y} y2={y} x1={sx(nodeCoord(0, W, opts.align), win)} x2={sx(nodeCoord(W - 1, W, opts.align), win)} className="tx-node-line" />);
    }
  }
  if (showDots) {
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const x = sx(nodeCoord(i, W, opts.align), win);
        const y = sy(nodeCoord(j, H, opts.align), win);
        const val = grid.values[j * W + i];
        const t = normalizeValue(val, range.min, range.max);
        items.push(<circle key={`d${i}-${j}`} cx={x} cy={y} r={showLabels ? 5 : 3} className={darkTextOn(t) ? 'tx-dot dark' : 'tx-dot'} />);
        if (showLabels) {
          items.push(
            <text key={`t${i}-${j}`} x={x + 8} y={y - 8} fontSize={fontSize} className={darkTextOn(t) ? 'tx-val dark' : 'tx-val'}>
              {fmtShort(val)}
            </text>,
          );
        }
      }
    }
  }
  // outside [0, 1]²: dim (this is where addressing decides)
  const x0 = sx(0, win);
  const x1 = sx(1, win);
  const y0 = sy(1, win);
  const y1 = sy(0, win);
  const ticks = nmax <= 8 ? Array.from({ length: W }, (_, i) => nodeCoord(i, W, opts.align)) : [0, 0.5, 1];
  const vticks = nmax <= 8 ? Array.from({ length: H }, (_, j) => nodeCoord(j, H, opts.align)) : [0, 0.5, 1];
  return (
    <g>
      <path d={`M0 0H${VB}V${VB}H0Z M${x0} ${y0}V${y1}H${x1}V${y0}Z`} className="tx-outside" fillRule="evenodd" />
      {items}
      <rect x={x0} y={y0} width={x1 - x0} height={y1 - y0} className="tx-frame" />
      {ticks.map((t) => (
        <text key={`ut${t}`} x={sx(t, win)} y={VB - 8} className="tx-tick" textAnchor="middle" fontSize={28}>
          {Number(t.toPrecision(3))}
        </text>
      ))}
      {vticks.map((t) => (
        <text key={`vt${t}`} x={4} y={sy(t, win) + 8} className="tx-tick" fontSize={28}>
          {Number(t.toPrecision(3))}
        </text>
      ))}
    </g>
  );
});

const TAP_CLASS = ['w00', 'w10', 'w01', 'w11'];

/** The query marker, the nearest node and the bilinear stencil with its weight rectangles. */
const QueryLayer = memo(function QueryLayer({
  grid,
  opts,
  win,
  q,
  selected,
}: {
  grid: TextureGrid;
  opts: LookupOptions;
  win: ViewWindow;
  q: Lookup;
  selected: { i: number; j: number } | null;
}) {
  const b = q.bil;
  const X = (u: number) => sx(u, win);
  const Y = (v: number) => sy(v, win);
  const qx = X(b.u);
  const qy = Y(b.v);
  // sub-rectangles: each tap's weight is the area of the sub-rectangle opposite to it
  const rects = [
    { cls: 'w00', x: qx, y: Y(b.v1), w: X(b.u1) - qx, h: qy - Y(b.v1), weight: b.w00 }, // opposite (u0, v0): upper right
    { cls: 'w10', x: X(b.u0), y: Y(b.v1), w: qx - X(b.u0), h: qy - Y(b.v1), weight: b.w10 }, // opposite (u1, v0): upper left
    { cls: 'w01', x: qx, y: qy, w: X(b.u1) - qx, h: Y(b.v0) - qy, weight: b.w01 }, // opposite (u0, v1): lower right
    { cls: 'w11', x: X(b.u0), y: qy, w: qx - X(b.u0), h: Y(b.v0) - qy, weight: b.w11 }, // opposite (u1, v1): lower left
  ];
  const taps = [
    { u: b.u0, v: b.v0, w: b.w00 },
    { u: b.u1, v: b.v0, w: b.w10 },
    { u: b.u0, v: b.v1, w: b.w01 },
    { u: b.u1, v: b.v1, w: b.w11 },
  ];
  const n = q.near;
  const nmax = Math.max(grid.width, grid.height);
  const ringR = Math.max(6, Math.min(22, (VB / nmax) * 0.22));
  return (
    <g>
      {rects.map((r) => (
        <rect key={r.cls} x={r.x} y={r.y} width={Math.max(0, r.w)} height={Math.max(0, r.h)} className={`tx-wrect ${r.cls}`} />
      ))}
      <rect x={X(b.u0)} y={Y(b.v1)} width={X(b.u1) - X(b.u0)} height={Y(b.v0) - Y(b.v1)} className="tx-cell" />
      {taps.map((t, k) => (
        <g key={k}>
          <circle cx={X(t.u)} cy={Y(t.v)} r={ringR} className={`tx-tap ${TAP_CLASS[k]}`} />
        </g>
      ))}
      <rect x={X(n.nodeU) - ringR - 6} y={Y(n.nodeV) - ringR - 6} width={2 * ringR + 12} height={2 * ringR + 12} className="tx-nearest" rx={4} />
      <g className="tx-query" transform={`translate(${qx} ${qy})`}>
        <circle r={11} />
        <line x1={-22} x2={22} y1={0} y2={0} />
        <line y1={-22} y2={22} x1={0} x2={0} />
      </g>
      {selected ? (
        <circle
          cx={X(nodeCoord(selected.i, grid.width, opts.align))}
          cy={Y(nodeCoord(selected.j, grid.height, opts.align))}
          r={ringR + 10}
          className="tx-selected"
        />
      ) : null}
    </g>
  );
});

/** Short label: up to 4 significant digits. */
export function fmtShort(x: number): string {
  if (!Number.isFinite(x)) return '—';
  const s = Number(x.toPrecision(4));
  return String(s);
}

/** CSS colour of a value on the grid's range (legend). */
export function valueColor(x: number, range: { min: number; max: number }): string {
  return colorCss(normalizeValue(x, range.min, range.max));
}

/**
 * The bilinear cell magnified: its four node values at the corners, the query at (fu, fv) inside,
 * and each node's weight written in the sub-rectangle opposite to it (same colour).
 */
function CellCloseUp({ q }: { q: Lookup }) {
  const b = q.bil;
  const S = 200;
  const P = 34; // padding for the corner labels
  const C = S - 2 * P;
  const x = P + b.fu * C;
  const y = P + (1 - b.fv) * C;
  const rects = [
    { cls: 'w00', x0: x, y0: P, x1: P + C, y1: y, w: b.w00 },
    { cls: 'w10', x0: P, y0: P, x1: x, y1: y, w: b.w10 },
    { cls: 'w01', x0: x, y0: y, x1: P + C, y1: P + C, w: b.w01 },
    { cls: 'w11', x0: P, y0: y, x1: x, y1: P + C, w: b.w11 },
  ];
  const corners = [
    { cls: 'w00', cx: P, cy: P + C, t: b.t00, dy: 26 },
    { cls: 'w10', cx: P + C, cy: P + C, t: b.t10, dy: 26 },
    { cls: 'w01', cx: P, cy: P, t: b.t01, dy: -14 },
    { cls: 'w11', cx: P + C, cy: P, t: b.t11, dy: -14 },
  ];
  return (
    <svg className="tx-closeup" viewBox={`0 0 ${S} ${S}`} role="img" aria-label={`The bilinear cell magnified: the query sits at fu = ${fmtShort(b.fu)}, fv = ${fmtShort(b.fv)} inside it`} data-testid="cell-closeup">
      {rects.map((r) => (
        <g key={r.cls}>
          <rect x={r.x0} y={r.y0} width={Math.max(0, r.x1 - r.x0)} height={Math.max(0, r.y1 - r.y0)} className={`tx-wrect ${r.cls}`} />
          {r.x1 - r.x0 > 30 && r.y1 - r.y0 > 16 ? (
            <text x={(r.x0 + r.x1) / 2} y={(r.y0 + r.y1) / 2 + 5} textAnchor="middle" className="tx-closeup-w">
              {fmtShort(r.w)}
            </text>
          ) : null}
        </g>
      ))}
      <rect x={P} y={P} width={C} height={C} className="tx-closeup-cell" />
      {corners.map((c) => (
        <g key={c.cls}>
          <circle cx={c.cx} cy={c.cy} r={6} className={`tx-tap ${c.cls}`} />
          <text x={c.cx} y={c.cy + c.dy} textAnchor="middle" className="tx-closeup-t">
            {fmtShort(c.t)}
          </text>
        </g>
      ))}
      <circle cx={x} cy={y} r={5} className="tx-closeup-q" />
    </svg>
  );
}
