/**
 * The bilinear stencil beside the grid: the four taps with their values and weights, and the cell
 * magnified with the query inside it. Both follow the query per animation frame.
 */
import { useLayoutEffect, useRef, type RefObject } from 'react';
import { formatRounded } from '../../../core/format';
import type { Lookup } from '../model';
import { setAttr, setText } from './domWrite';
import { TAP_CLASS } from './StencilLayer';
import './marks.css';
import './StencilDetail.css';

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
        setText(li.children[2], `=${formatRounded(t)}, w=${formatRounded(w)}`);
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
    if (text) setText(label, formatRounded(r.w, 3));
  }
  const values = [b.t00, b.t10, b.t01, b.t11];
  for (let k = 0; k < 4; k++) setText(kids[5 + k].children[1], formatRounded(values[k]));
  if (text) {
    svg.setAttribute(
      'aria-label',
      `The bilinear cell magnified: the query sits at fu = ${formatRounded(b.fu)}, fv = ${formatRounded(b.fv)} inside it`,
    );
  }
  set(kids[9], 'cx', x);
  set(kids[9], 'cy', y);
}
