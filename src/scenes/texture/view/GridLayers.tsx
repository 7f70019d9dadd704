/**
 * The texel grid's layers that change only with the texture, the conventions or the size: the
 * nearest-neighbour regions as a canvas, the nodes, node lines, frame and ticks below the stencil,
 * the node values above it, and the query's path.
 */
import { memo, useEffect, useRef } from 'react';
import { nodeCoord } from '../../../core/texture';
import { darkTextOn, normalizeValue } from '../../../core/colormap';
import { formatRounded } from '../../../core/format';
import { pathPoint, type QueryPath } from '../path';
import { nearestRects, texelColours, textureImage } from '../textureImage';
import type { ShownTexture } from '../model';
import { VB, sx, sy, type ViewWindow } from './gridFrame';

/** Smallest on-screen size of any text in the figure, in CSS pixels (at least 12 px on phones). */
const MIN_TEXT_PX = 12.5;

export /** Nearest-neighbour regions as an image (outside [0, 1]² dimmed by the SVG layer). */
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
    const o = { ...opts, vflip: false };
    const view = { uMin: win.min, uMax: win.max, vMin: win.min, vMax: win.max };
    // one filled rectangle per texel region (the same pixels as the image written pixel by pixel,
    // which cost a long task on a phone's first render); pixel by pixel for a grid finer than that
    const rects = nearestRects(grid, o, res, res, view);
    if (rects) {
      const lut = texelColours(grid, range);
      for (const r of rects) {
        const k = 4 * r.texel;
        g.fillStyle = `rgb(${lut[k]} ${lut[k + 1]} ${lut[k + 2]})`;
        g.fillRect(r.x, r.y, r.w, r.h);
      }
      return;
    }
    const img = textureImage(grid, o, 'nearest', res, res, range, view);
    g.putImageData(new ImageData(img as Uint8ClampedArray<ArrayBuffer>, res, res), 0, 0);
  }, [grid, opts, range, win]);
  return <canvas ref={ref} className="tx-grid-canvas" aria-hidden="true" />;
});

/** What the SVG layers over the texture draw from: the texture, the window, the scale, the mode. */
export type LayerProps = ShownTexture & { win: ViewWindow; unitsPerPx: number; present: boolean };

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

export const StaticLayer = memo(function StaticLayer({ unitsPerPx, present, ...shown }: LayerProps) {
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
  ).filter((t) => 0.62 * tickFont * formatRounded(t, 3).length + 4 <= x0 + 4);
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
          {formatRounded(t, 3)}
        </text>
      ))}
      {vticks.map((t) => (
        <text key={`vt${t}`} x={4} y={sy(t, win) + tickFont * 0.35} className="tx-tick" fontSize={tickFont}>
          {formatRounded(t, 3)}
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
export const LabelLayer = memo(function LabelLayer({ unitsPerPx, present, ...shown }: LayerProps) {
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
          {formatRounded(value)}
        </text>
      ))}
    </g>
  );
});

/** The query's path (clipped to the plotted window). */
export const PathLayer = memo(function PathLayer({
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
