/** The race's hand-drawn SVG plots: their frame (viewBox, margins), axes and polylines. */
import { coordText, type Scale } from '../../../ui/chartScale';

export const W = 360;
export const H = 190;
export const M = { l: 64, r: 10, t: 10, b: 30 };
export const PW = W - M.l - M.r;
export const PH = H - M.t - M.b;

/** A polyline through the finite points (xs[k], ys[k]), k ≥ from. */
export function path(xs: readonly number[], ys: readonly number[], sx: Scale, sy: Scale, from = 0): string {
  let d = '';
  for (let k = from; k < xs.length; k++) {
    const y = ys[k];
    if (!Number.isFinite(y)) continue;
    d += `${d ? 'L' : 'M'}${coordText(sx(xs[k]))},${coordText(sy(y))}`;
  }
  return d;
}

/** The frame, ticks, grid lines and axis titles of a plot `h` units tall (the plot area is PW wide). */
export function Axes({
  xTicks,
  yTicks,
  xLabel,
  yLabel,
  h = H,
}: {
  xTicks: [number, string][];
  yTicks: [number, string][];
  xLabel: string;
  yLabel: string;
  h?: number;
}) {
  const ph = h - M.t - M.b;
  return (
    <g className="mc-svg-axes">
      <rect x={M.l} y={M.t} width={PW} height={ph} className="mc-svg-frame" />
      {xTicks.map(([x, s]) => (
        <text key={`x${s}`} x={x} y={M.t + ph + 14} textAnchor="middle">
          {s}
        </text>
      ))}
      {yTicks.map(([y, s]) => (
        <g key={`y${s}`}>
          <line x1={M.l} x2={M.l + PW} y1={y} y2={y} className="mc-svg-grid" />
          <text x={M.l - 4} y={y + 4} textAnchor="end">
            {s}
          </text>
        </g>
      ))}
      <text x={M.l + PW / 2} y={h - 2} textAnchor="middle" className="mc-svg-axis-title">
        {xLabel}
      </text>
      <text
        x={11}
        y={M.t + ph / 2}
        textAnchor="middle"
        transform={`rotate(-90 11 ${M.t + ph / 2})`}
        className="mc-svg-axis-title mc-svg-ytitle"
      >
        {yLabel}
      </text>
    </g>
  );
}
