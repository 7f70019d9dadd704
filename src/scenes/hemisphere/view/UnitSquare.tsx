/**
 * The unit square of (ξ₁, ξ₂): the first points of the chosen set and the 8 × 8 grid whose image
 * the 3D view draws on the hemisphere, in the same colours. Redrawn only when the inputs change.
 * The followed stratum is outlined and the rest of the square veiled (an SVG layer over the
 * pixels, so a new choice redraws nothing); its cells are radio buttons over the plot.
 */
import { formatCount } from '../../../ui/format';
import { useEffect, useMemo, useRef } from 'react';
import { fillSequence2D, type SequenceKind } from '../../../core/random';
import { nextTask, runChunked } from '../../../ui/chunked';
import { pointShade, xiColor } from './colors';
import { CELLS, cellBounds, cellCounts, type Cell } from '../stratum';
import { ShowAsTable } from '../../../ui';
import { describeSquare } from './describe';
import { StratumCells, type PickCell } from './StratumPicker';

const MAX_SHOWN = 4096;

/** The square's side s and its coordinates in a figure of `size` px: ξ₁ → x, ξ₂ → y (up). */
function squareAxes(size: number) {
  const pad = 22;
  const s = size - 2 * pad;
  return { s, X: (a: number) => pad + a * s, Y: (b: number) => pad + (1 - b) * s };
}

export function UnitSquare({
  kind,
  seed,
  n,
  size = 240,
  cell = null,
  onPick,
  captioned = true,
  dark = false,
}: {
  kind: SequenceKind;
  seed: number;
  n: number;
  /** Side in CSS px: 240 or more keeps each of the 64 cells a 24 px target (WCAG 2.5.8). */
  size?: number;
  /** The followed stratum (null: none) and the way to choose another (absent: no picking). */
  cell?: Cell | null;
  onPick?: PickCell;
  /** Show the caption under the square (the classroom stage leaves it out). */
  captioned?: boolean;
  /** The dark theme (the colours are drawn at full brightness there, shaded on the light theme). */
  dark?: boolean;
}) {
  const canvas = useRef<HTMLCanvasElement>(null);
  const shown = Math.min(n, MAX_SHOWN);
  const { s, X, Y } = squareAxes(size);
  // the first sample, which the 3D view and the worked example track (ringed)
  const first = useMemo(
    () => (shown > 0 ? fillSequence2D(kind, seed, n, new Float64Array(2), 0, 1, 0) : null),
    [kind, seed, n, shown],
  );
  const counts = useMemo(() => cellCounts(kind, seed, n, shown), [kind, seed, n, shown]);
  const rows = useMemo(
    () =>
      Array.from({ length: CELLS }, (_, r) => {
        const j = CELLS - 1 - r; // the top row first, as drawn
        return [`${j}`, ...Array.from({ length: CELLS }, (_, i) => String(counts[j * CELLS + i]))];
      }),
    [counts],
  );
  useEffect(() => {
    const c = canvas.current;
    const g = c?.getContext('2d', { willReadFrequently: true });
    if (!c || !g) return;
    const { X, Y } = squareAxes(size);
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const W = Math.round(size * dpr);
    const H = W;
    // Everything coloured goes straight into the pixels (grid segments and points, one colour each):
    // a stroke and a colour string per segment and per point was tens of ms of a phone's load.
    // Two short tasks: the grid and the first half of the points, then the rest.
    const img = new ImageData(W, H);
    const px = img.data;
    const rgb = new Uint8Array(3);
    const shade = pointShade(dark);
    const fill = (x0: number, x1: number, y0: number, y1: number) => {
      const [r, gr, b] = [rgb[0] * shade, rgb[1] * shade, rgb[2] * shade];
      const xa = Math.max(0, Math.round(x0 * dpr));
      const xb = Math.min(W, Math.round(x1 * dpr));
      const ya = Math.max(0, Math.round(y0 * dpr));
      const yb = Math.min(H, Math.round(y1 * dpr));
      for (let y = ya; y < yb; y++) {
        for (let x = xa, k = (y * W + xa) * 4; x < xb; x++, k += 4) {
          px[k] = r;
          px[k + 1] = gr;
          px[k + 2] = b;
          px[k + 3] = 255;
        }
      }
    };
    const drawGrid = () => {
      // the 8 × 8 grid in the warp colours, 1.5 px wide, each line in 16 segments
      const half = 0.75;
      for (let l = 0; l <= 8; l++) {
        const f = l / 8;
        for (let q = 0; q < 16; q++) {
          const t0 = q / 16;
          const t1 = (q + 1) / 16;
          xiColor(f, (t0 + t1) / 2, rgb);
          fill(X(f) - half, X(f) + half, Y(t1), Y(t0));
          xiColor((t0 + t1) / 2, f, rgb);
          fill(X(t0), X(t1), Y(f) - half, Y(f) + half);
        }
      }
    };
    const u = new Float64Array(2 * shown);
    const r = shown > 1000 ? 1.2 : 2;
    const drawPoints = (from: number, to: number) => {
      if (from === 0) fillSequence2D(kind, seed, n, u, 0, shown, 0);
      for (let i = from; i < to; i++) {
        const a = u[2 * i];
        const b = u[2 * i + 1];
        xiColor(a, b, rgb);
        fill(X(a) - r, X(a) + r, Y(b) - r, Y(b) + r);
      }
    };
    const finish = () => {
      c.width = W; // (clears the canvas)
      c.height = H;
      g.putImageData(img, 0, 0);
    };
    let alive = true;
    const mid = shown >> 1;
    const cancel = runChunked(() => {
      drawGrid();
      drawPoints(0, mid);
      nextTask(() => {
        if (!alive) return;
        drawPoints(mid, shown);
        finish();
      });
    });
    return () => {
      alive = false;
      cancel();
    };
  }, [kind, seed, n, shown, size, dark]);
  // The frame, the axis labels and the ring are drawn over the pixels in the text colour
  // (currentColor): reading the theme's colour for the canvas forced a style recalculation of the
  // whole page while it loaded (42 ms on the Lighthouse trace), and a theme switch now
  // recolours them without a redraw.
  return (
    <figure className="hemi-square">
      <div className="hemi-square-plot" style={{ width: size, height: size }}>
        <canvas
          ref={canvas}
          style={{ width: size, height: size }}
          role="img"
          aria-label={`The unit square of (ξ₁, ξ₂) and the grid whose image is drawn on the hemisphere: ${describeSquare(counts, shown, n, kind)}`}
        />
        <svg viewBox={`0 0 ${size} ${size}`} width={size} height={size} aria-hidden="true" focusable="false">
          <rect x={X(0)} y={Y(1)} width={s} height={s} fill="none" stroke="currentColor" strokeWidth={1} />
          {cell ? <StratumMark cell={cell} X={X} Y={Y} /> : null}
          {first && (
            <circle
              cx={X(first[0])}
              cy={Y(first[1])}
              r={6}
              fill="none"
              stroke="currentColor"
              strokeWidth={2}
            />
          )}
          <g
            fill="currentColor"
            style={{ fontSize: 'var(--tick-size, 12px)' }}
            fontFamily="sans-serif"
            textAnchor="middle"
            dominantBaseline="hanging"
          >
            <text x={X(0.5)} y={Y(0) + 3}>
              ξ₁ →
            </text>
            <text x={X(0)} y={Y(0) + 3}>
              0
            </text>
            <text x={X(1)} y={Y(0) + 3}>
              1
            </text>
            <text transform={`translate(${X(0) - 3} ${Y(0.5)}) rotate(-90)`} dominantBaseline="auto">
              ξ₂ →
            </text>
          </g>
        </svg>
        {onPick ? <StratumCells cell={cell} onPick={onPick} inset={22 / size} /> : null}
      </div>
      <figcaption className={captioned ? undefined : 'sr-only'}>
        (ξ₁, ξ₂): first {formatCount(shown)} {kind} points; each colour lands where the same colour appears on
        the hemisphere; the ringed point is the first sample.
        {cell ? ` The outlined cell is the followed stratum (${cell.i}, ${cell.j}).` : ''}
      </figcaption>
      <ShowAsTable
        caption={`Points of the square in each cell (first ${formatCount(shown)}): rows j of ξ₂ from the top, columns i of ξ₁`}
        columns={['j \\ i', ...Array.from({ length: CELLS }, (_, i) => String(i))]}
        rows={rows}
        testId="square-table"
      />
    </figure>
  );
}

/** The followed cell: the rest of the square veiled, the cell outlined twice (dark and light, for both themes). */
function StratumMark({ cell, X, Y }: { cell: Cell; X: (a: number) => number; Y: (b: number) => number }) {
  const { xi1, xi2 } = cellBounds(cell);
  const x0 = X(xi1[0]);
  const x1 = X(xi1[1]);
  const y0 = Y(xi2[1]);
  const y1 = Y(xi2[0]);
  const outer = `M${X(0)} ${Y(1)}H${X(1)}V${Y(0)}H${X(0)}Z`;
  const hole = `M${x0} ${y0}V${y1}H${x1}V${y0}Z`;
  return (
    <g data-testid="stratum-mark">
      <path d={`${outer}${hole}`} fillRule="evenodd" style={{ fill: 'var(--surface)' }} opacity={0.72} />
      <rect
        x={x0}
        y={y0}
        width={x1 - x0}
        height={y1 - y0}
        fill="none"
        stroke="currentColor"
        strokeWidth={3}
      />
      <rect
        x={x0 + 2}
        y={y0 + 2}
        width={x1 - x0 - 4}
        height={y1 - y0 - 4}
        fill="none"
        style={{ stroke: 'var(--surface)' }}
        strokeWidth={1}
      />
    </g>
  );
}
