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
import { useEffect, useMemo, useRef, type KeyboardEvent, type PointerEvent } from 'react';
import { nodeCoord } from '../../../core/texture';
import { formatRounded } from '../../../core/format';
import type { Lookup, ShownTexture } from '../model';
import type { QueryPath } from '../path';
import { VB, inWindow, round4, sx, sy, viewWindow } from './gridFrame';
import { BaseCanvas, LabelLayer, PathLayer, StaticLayer } from './GridLayers';
import { QueryLayer, drawStencil, queryGeometry } from './StencilLayer';
import './marks.css';
import './GridView.css';

/** Radius of a handle's hit area in CSS pixels (a ≥ 24 px target on touch screens). */
const HANDLE_HIT_PX = 20;

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
              : `Texel grid: the query point is at (${formatRounded(q.bil.u)}, ${formatRounded(q.bil.v)}). Arrow keys move it by 0.01 (Shift: 0.1), back at the start of its path; click or drag to move it; drag the square to move the path's end`
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
              aria-label={`End of the query's path at (u, v) = (${formatRounded(path.b[0])}, ${formatRounded(path.b[1])}): arrow keys move it by 0.01 (Shift: 0.1)`}
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
