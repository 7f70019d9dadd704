/**
 * The running-estimate plot both Monte Carlo scenes draw: the estimate after N samples against N (a
 * log axis), its ± standard-error band, and the exact (or reference) value as a dashed line. The
 * caller computes the scales, the ticks and the paths (each scene has its own clock); this
 * component draws them the same way everywhere, with the same contrast variables
 * (runningEstimate.css). Paths that move per animation frame are reachable through `bandRef` and
 * `lineRef`, and `clipWidth` reveals a precomputed curve up to a position. The figure's words and
 * its table stay with the scene (a DescribedFigure around the plot, or the scene's data panel).
 */
import { useId, type ReactNode, type Ref } from 'react';
import './runningEstimate.css';

/** Margins of the plot area inside the viewBox. */
export interface PlotMargin {
  l: number;
  r: number;
  t: number;
  b: number;
}

export interface RunningEstimatePlotProps {
  width: number;
  height: number;
  margin: PlotMargin;
  /** Tick positions (viewBox units) and labels. */
  xTicks: readonly (readonly [number, string])[];
  yTicks: readonly (readonly [number, string])[];
  xLabel: string;
  yLabel?: string;
  /** The exact value's y (viewBox units), or null when there is none. */
  exactY: number | null;
  /** The ± band (a closed path) and the estimate's polyline. */
  band: string;
  line: string;
  /** The lane's colour (a CSS colour or var); the default series colour when absent. */
  color?: string;
  /** Draw the estimate dashed (the second lane of a comparison, told apart by more than colour). */
  dashed?: boolean;
  bandRef?: Ref<SVGPathElement>;
  lineRef?: Ref<SVGPathElement>;
  /** Show the band and the line only left of this x (viewBox units); everything when absent. */
  clipWidth?: number;
  svgRef?: Ref<SVGSVGElement>;
  className?: string;
  /** An accessible name makes the svg an image; without one it is hidden (its figure describes it). */
  ariaLabel?: string;
  testId?: string;
  /** Extra marks drawn on top (a marker at the current position). */
  children?: ReactNode;
}

export function RunningEstimatePlot({
  width: W,
  height: H,
  margin: M,
  xTicks,
  yTicks,
  xLabel,
  yLabel,
  exactY,
  band,
  line,
  color,
  dashed,
  bandRef,
  lineRef,
  clipWidth,
  svgRef,
  className,
  ariaLabel,
  testId,
  children,
}: RunningEstimatePlotProps) {
  const clip = useId().replace(/:/g, '');
  const pw = W - M.l - M.r;
  const ph = H - M.t - M.b;
  const a11y = ariaLabel ? { role: 'img', 'aria-label': ariaLabel } : { 'aria-hidden': true as const };
  return (
    <svg
      ref={svgRef}
      viewBox={`0 0 ${W} ${H}`}
      className={className ? `rep ${className}` : 'rep'}
      data-testid={testId}
      {...a11y}
    >
      {clipWidth === undefined ? null : (
        <defs>
          <clipPath id={clip}>
            <rect x={0} y={0} width={Math.max(0, clipWidth)} height={H} />
          </clipPath>
        </defs>
      )}
      <g className="rep-axes">
        <rect x={M.l} y={M.t} width={pw} height={ph} className="rep-frame" />
        {xTicks.map(([x, s]) => (
          <text key={`x${s}`} x={x} y={M.t + ph + 14} textAnchor="middle">
            {s}
          </text>
        ))}
        {yTicks.map(([y, s]) => (
          <g key={`y${s}`}>
            <line x1={M.l} x2={M.l + pw} y1={y} y2={y} className="rep-grid" />
            <text x={M.l - 4} y={y + 4} textAnchor="end">
              {s}
            </text>
          </g>
        ))}
        <text x={M.l + pw / 2} y={H - 2} textAnchor="middle" className="rep-title">
          {xLabel}
        </text>
        {yLabel ? (
          <text
            x={11}
            y={M.t + ph / 2}
            textAnchor="middle"
            transform={`rotate(-90 11 ${M.t + ph / 2})`}
            className="rep-title rep-ytitle"
          >
            {yLabel}
          </text>
        ) : null}
      </g>
      {exactY === null || !Number.isFinite(exactY) ? null : (
        <line x1={M.l} x2={M.l + pw} y1={exactY} y2={exactY} className="rep-exact" />
      )}
      <g clipPath={clipWidth === undefined ? undefined : `url(#${clip})`}>
        <path ref={bandRef} d={band} className="rep-band" style={color ? { fill: color } : undefined} />
        <path
          ref={lineRef}
          d={line}
          className={dashed ? 'rep-line rep-dashed' : 'rep-line'}
          style={color ? { stroke: color } : undefined}
        />
      </g>
      {children}
    </svg>
  );
}
