/** The race's hand-drawn SVG plots: their frame (viewBox, margins), axes and polylines. */
import { formatNumber } from '../../../ui';
import { pow10Text } from '../../../ui/axis';
import {
  clampExponent,
  coordText,
  linearScale as lin,
  logScale as logS,
  type Scale,
} from '../../../ui/chartScale';
import { RACE_MAX, type RaceTrack } from '../race';

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

const N_TICKS: number[] = [1, 10, 100, 1000].filter((n) => n <= RACE_MAX);

/** f and the importance pdf scaled to f's height, on a grid over [a, b]. */
export interface RaceCurve {
  x: Float64Array;
  f: Float64Array;
  p: Float64Array;
  scale: number;
}
/** A small key of line styles: a stroke sample (solid or dashed) and its name per row. */
export function LineKey({ x, y, items }: { x: number; y: number; items: [string, string, boolean][] }) {
  return (
    <g className="mc-svg-key" aria-hidden="true">
      {items.map(([name, color, dashed], k) => (
        <g key={name} transform={`translate(${x} ${y + 15 * k})`}>
          <line
            x1={0}
            x2={22}
            y1={-4}
            y2={-4}
            style={{ stroke: color }}
            className={dashed ? 'mc-svg-line mc-svg-dashed' : 'mc-svg-line'}
          />
          <text x={27} y={0}>
            {name}
          </text>
        </g>
      ))}
    </g>
  );
}

/** v rounded up to two significant digits (a density axis's top). */
export function roundUp2(v: number): number {
  if (!(v > 0 && Number.isFinite(v))) return 1;
  const u = 10 ** (Math.floor(Math.log10(v)) - 1);
  return Math.ceil(v / u - 1e-9) * u;
}

/** The race figure's static scales, ticks and curves (keyed on the track and the curve, not on t). */
export function raceScales(track: RaceTrack, curve: RaceCurve, a: number, b: number) {
  const I = track.exact;
  const s = Math.abs(I) || 1;
  let lo = 0;
  let hi = 0;
  for (let k = 0; k < curve.f.length; k++) {
    const v = curve.f[k];
    const p = curve.p[k];
    if (Number.isFinite(v)) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
    if (Number.isFinite(p)) hi = Math.max(hi, p);
  }
  if (!(hi > lo)) hi = lo + 1;
  hi += 0.08 * (hi - lo);
  const sx = lin(a, b, M.l, M.l + PW);
  const sy = lin(lo, hi, M.t + PH - 22, M.t);
  const xs = Array.from(curve.x);
  const fPath = path(xs, Array.from(curve.f), sx, sy);
  const pPath = path(xs, Array.from(curve.p), sx, sy);
  const xt: [number, string][] = [0, 0.25, 0.5, 0.75, 1].map((q) => [
    sx(a + q * (b - a)),
    formatNumber(a + q * (b - a), 3),
  ]);
  let fmax = 0;
  for (const v of curve.f) if (Number.isFinite(v)) fmax = Math.max(fmax, v);
  const yt: [number, string][] = (lo < 0 ? [lo, 0, fmax] : [0, fmax / 2, fmax]).map((v) => [
    sy(v),
    formatNumber(v, 3),
  ]);
  // running estimate: the same y range for both lanes, around the exact value
  let R = 0;
  for (let k = 3; k < track.max; k++)
    R = Math.max(R, Math.abs(track.uniform.mean[k] - I), Math.abs(track.importance.mean[k] - I));
  R = Math.max(R * 1.1, 1e-6 * s);
  const ex = logS(1, track.max, M.l, M.l + PW);
  const ey = lin(I - R, I + R, M.t + PH, M.t);
  const nt: [number, string][] = N_TICKS.map((n) => [ex(n), String(n)]);
  const et: [number, string][] = [-1, 0, 1].map((q) => [ey(I + q * R), formatNumber(I + q * R, 4)]);
  // |error| log-log: from 10⁻⁵·|I| to |I| (smaller errors sit on the floor line)
  // (decades of a subnormal |I| stop at 10⁻³²³, the smallest power of ten a double holds)
  const e1 = clampExponent(Math.ceil(Math.log10(s)));
  const e0 = clampExponent(Math.min(e1 - 1, Math.floor(Math.log10(s)) - 5));
  const ly = logS(10 ** e0, 10 ** e1, M.t + PH, M.t);
  const lt: [number, string][] = [];
  for (let e = e0; e <= e1; e += e1 - e0 > 4 ? 2 : 1) lt.push([ly(10 ** e), pow10Text(e)]);
  // N⁻½ guide through the uniform lane's final standard deviation: sd/√N is the expected error scale
  const last = track.max - 1;
  const sd = Math.sqrt(track.uniform.m2[last] / Math.max(1, last));
  const guide = `M${coordText(ex(1))},${coordText(ly(Math.max(sd, 10 ** e0)))}L${coordText(ex(track.max))},${coordText(ly(Math.max(sd / Math.sqrt(track.max), 10 ** e0)))}`;
  return { sx, sy, fPath, pPath, xt, yt, ex, ey, nt, et, ly, lt, floor: 10 ** e0, guide, R };
}
