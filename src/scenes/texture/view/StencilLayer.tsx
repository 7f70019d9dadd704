/**
 * The grid's layer that follows the query: the nearest node's highlight and the bilinear stencil
 * (the cell, its four taps and the weight rectangles), rendered by React and moved per animation
 * frame by {@link drawStencil}.
 */
import { memo, type RefObject } from 'react';
import type { TextureGrid } from '../../../core/texture';
import type { Lookup } from '../model';
import { setAttr } from './domWrite';
import { VB, sx, sy, type ViewWindow } from './gridFrame';

/** The four taps' classes, in the order w00 (i0, j0), w10 (i1, j0), w01 (i0, j1), w11 (i1, j1). */
export const TAP_CLASS = ['w00', 'w10', 'w01', 'w11'];

interface QueryGeometry {
  rects: { cls: string; x: number; y: number; w: number; h: number }[];
  cell: { x: number; y: number; w: number; h: number };
  taps: { x: number; y: number }[];
  ringR: number;
  nearest: { x: number; y: number; size: number };
}

/** Where the stencil's shapes go for a lookup (shared by the React layer and the per-frame drawer). */
export function queryGeometry(grid: TextureGrid, win: ViewWindow, q: Lookup): QueryGeometry {
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
export function drawStencil(g: SVGGElement, geo: QueryGeometry): void {
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
export const QueryLayer = memo(function QueryLayer({
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
