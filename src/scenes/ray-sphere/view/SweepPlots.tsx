/**
 * The two animated plots of the sweep, drawn as light SVG of their own (not src/ui/Plot) so a
 * frame of the animation only moves a few elements: g(t) = a t² + b t + c on a window fixed for
 * the whole sweep (the parabola slides, its roots move), and Δ against the sweep coordinate
 * (robust and textbook), with the current position, the tangency crossings and the case of each
 * position underneath.
 * Sizes follow the element's width (one SVG unit = one CSS pixel), so labels stay ≥ 12 px.
 */
import { memo, useLayoutEffect, useMemo, useRef, type ReactNode } from 'react';
import type { RaySphereCase, RaySphereHit } from '../../../core/geometry';
import type { SweepSeries } from '../sweepSeries';
import { useWidth } from '../../../ui/useWidth';
import { linearScale } from '../../../ui/chartScale';
import { useSectionWidth } from '../../../ui/Deferred';
import { niceTicks, tickLabel } from '../../../ui/axis';
import './sweepPlots.css';

const PAD = { l: 62, r: 14, t: 30, b: 44 };

interface Frame {
  W: number;
  H: number;
  X: (x: number) => number;
  Y: (y: number) => number;
  x0: number;
  x1: number;
  y0: number;
  y1: number;
}

function makeFrame(
  W: number,
  H: number,
  xd: [number, number],
  yd: [number, number],
  padBottom = PAD.b,
  padTop = PAD.t,
): Frame {
  const x0 = PAD.l;
  const x1 = W - PAD.r;
  const y0 = padTop;
  const y1 = H - padBottom;
  // the shared chart guard: finite coordinates for any data (../../../ui/chartScale)
  const X = linearScale(xd[0], xd[1], x0, x1);
  const Y = linearScale(yd[0], yd[1], y1, y0);
  return { W, H, X, Y, x0, x1, y0, y1 };
}

/** Axes, ticks, grid, title and axis labels (static for a given frame). */
function Axes({
  f,
  xd,
  yd,
  title,
  xLabel,
  yLabel,
}: {
  f: Frame;
  xd: [number, number];
  yd: [number, number];
  title: string;
  xLabel: string;
  yLabel: string;
}) {
  const xt = niceTicks(xd[0], xd[1], Math.max(2, Math.floor((f.x1 - f.x0) / 80)));
  const yt = niceTicks(yd[0], yd[1], Math.max(2, Math.floor((f.y1 - f.y0) / 45)));
  return (
    <g className="mp-axes">
      <rect x={f.x0} y={f.y0} width={f.x1 - f.x0} height={f.y1 - f.y0} className="mp-bg" />
      {xt.ticks.map((v) => (
        <g key={`x${v}`}>
          <line x1={f.X(v)} x2={f.X(v)} y1={f.y0} y2={f.y1} className="mp-grid" />
          <text x={f.X(v)} y={f.y1 + 16} textAnchor="middle" className="mp-tick">
            {tickLabel(v, xt.step)}
          </text>
        </g>
      ))}
      {yt.ticks.map((v) => (
        <g key={`y${v}`}>
          <line x1={f.x0} x2={f.x1} y1={f.Y(v)} y2={f.Y(v)} className={v === 0 ? 'mp-zero' : 'mp-grid'} />
          <text x={f.x0 - 6} y={f.Y(v) + 4} textAnchor="end" className="mp-tick">
            {tickLabel(v, yt.step)}
          </text>
        </g>
      ))}
      <text x={f.x0} y={18} className="mp-title">
        {title}
      </text>
      <text x={(f.x0 + f.x1) / 2} y={f.H - 8} textAnchor="middle" className="mp-label">
        {xLabel}
      </text>
      <text
        x={4}
        y={(f.y0 + f.y1) / 2}
        textAnchor="middle"
        dominantBaseline="hanging"
        className="mp-label"
        transform={`rotate(-90 4 ${(f.y0 + f.y1) / 2})`}
      >
        {yLabel}
      </text>
    </g>
  );
}

/** The refs of a plot's box and SVG, and the width to draw at (the box's, at least 260 px). */
function usePlotBox() {
  const boxRef = useRef<HTMLDivElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const W = Math.max(260, useWidth(boxRef, useSectionWidth() ?? 520));
  return { boxRef, svgRef, W };
}

/** The two plots by name: what each shows (the SVG's data-label). */
const PLOT_LABELS = {
  g: 'The quadratic g(t) for the ray at the current position, with its real roots on the t axis',
  delta: 'The discriminant Δ against the sweep coordinate, robust and textbook, with the current position',
} as const;
type PlotName = keyof typeof PLOT_LABELS;

/** The id of a plot's clip path to its plot area (SvgBox draws it; the plot's curves use it). */
const clipId = (name: PlotName) => `rs-${name}-clip`;

/** A plot's box and SVG, sized by its frame `f`; its test id is `<name>-plot`. */
function SvgBox({
  children,
  name,
  boxRef,
  svgRef,
  f,
}: {
  children: ReactNode;
  name: PlotName;
  boxRef: React.RefObject<HTMLDivElement | null>;
  svgRef?: React.RefObject<SVGSVGElement | null>;
  f: Frame;
}) {
  const { W, H: height } = f;
  return (
    <div ref={boxRef} className="mp-box">
      <svg
        ref={svgRef}
        viewBox={`0 0 ${W} ${height}`}
        width="100%"
        height={height}
        // named and described by the figure around it (view/Described.tsx): the SVG's ticks and
        // labels would only repeat its summary, piece by piece
        aria-hidden="true"
        data-label={PLOT_LABELS[name]}
        data-testid={`${name}-plot`}
        className="mp-svg"
      >
        <defs>
          <clipPath id={clipId(name)}>
            <rect x={f.x0} y={f.y0} width={f.x1 - f.x0} height={f.y1 - f.y0} />
          </clipPath>
        </defs>
        {children}
      </svg>
    </div>
  );
}

// ---------------------------------------------------------------------------------------------

export interface GPlotProps {
  res: RaySphereHit | null;
  window: SweepSeries['gWindow'];
  /**
   * Set to a function that redraws the parabola and its roots for another ray directly (per
   * animation frame, without React); `res` is then only the first drawing.
   */
  drawRef?: { current: ((res: RaySphereHit | null) => void) | null };
}

/** Writes g(t) and its root marks (two groups rendered by GSweepPlot) for `res`. */
function drawG(svg: SVGSVGElement, f: Frame, w: SweepSeries['gWindow'], res: RaySphereHit | null): void {
  const pathEl = svg.querySelector<SVGPathElement>('path.mp-g');
  const marks = svg.querySelectorAll<SVGGElement>('g[data-root]');
  let path = '';
  const roots = !res || res.t0 === null ? [] : res.t0 === res.t1 ? [res.t0] : [res.t0, res.t1!];
  if (res) {
    const tv = -res.b / (2 * res.a);
    const k = res.discriminant / (4 * res.a);
    const n = 96;
    for (let i = 0; i <= n; i++) {
      const t = w.tMin + ((w.tMax - w.tMin) * i) / n;
      // vertex form: accurate where the expanded form would cancel
      const g = res.a * (t - tv) * (t - tv) - k;
      const y = Math.max(-1e4, Math.min(1e4, f.Y(g)));
      path += `${i ? 'L' : 'M'}${f.X(t - w.shift).toFixed(1)},${y.toFixed(1)}`;
    }
  }
  if (pathEl && pathEl.getAttribute('d') !== path) pathEl.setAttribute('d', path);
  marks.forEach((g, i) => {
    const t = roots[i];
    if (t === undefined || !res) {
      g.setAttribute('display', 'none');
      return;
    }
    g.removeAttribute('display');
    const isHit = t === res.tHit;
    g.setAttribute('class', `mp-root${isHit ? ' hit' : ''}${t < 0 ? ' behind' : ''}`);
    g.setAttribute('transform', `translate(${f.X(t - w.shift).toFixed(1)} ${f.Y(0).toFixed(1)})`);
    g.firstElementChild?.setAttribute('r', isHit ? '6.5' : '5');
    const text = `${roots.length === 1 ? 't₀ = t₁' : i === 0 ? 't₀' : 't₁'}${isHit ? ' hit' : t < 0 ? ' < 0' : ''}`;
    const label = g.lastElementChild;
    if (label && label.textContent !== text) label.textContent = text;
  });
}

/** g(t) of the ray at the current position, on the sweep's fixed window. */
export function GSweepPlot({ res, window: w, drawRef }: GPlotProps) {
  const plot = usePlotBox();
  const { W, svgRef: svg } = plot;
  const H = Math.round(Math.min(300, Math.max(220, W * 0.5)));
  const xd = useMemo<[number, number]>(() => [w.tMin - w.shift, w.tMax - w.shift], [w.tMin, w.tMax, w.shift]);
  const yd = useMemo<[number, number]>(() => [w.gMin, w.gMax], [w.gMin, w.gMax]);
  const f = useMemo(() => makeFrame(W, H, xd, yd), [W, H, xd, yd]);
  const xLabel = w.shift ? `t − ${w.shift.toPrecision(12)}` : 't (grey: behind the origin, t < 0)';
  const axes = useMemo(
    () => <Axes f={f} xd={xd} yd={yd} title="g(t) = a t² + b t + c" xLabel={xLabel} yLabel="g(t)" />,
    [f, xd, yd, xLabel],
  );
  // the last ray drawn (from a render or a frame), so a re-render (resize, new window) redraws it
  const last = useRef(res);
  const draw = (r: RaySphereHit | null) => {
    last.current = r;
    if (svg.current) drawG(svg.current, f, w, r);
  };
  if (drawRef) drawRef.current = draw;
  else last.current = res;
  useLayoutEffect(() => draw(last.current));
  const showBehind = w.shift === 0 && w.tMin < 0;
  return (
    <SvgBox {...plot} name="g" f={f}>
      {axes}
      {showBehind ? (
        <rect
          x={f.X(w.tMin)}
          y={f.y0}
          width={Math.max(0, f.X(0) - f.X(w.tMin))}
          height={f.y1 - f.y0}
          className="mp-behind"
        />
      ) : null}
      <g clipPath={`url(#${clipId('g')})`}>
        <path className="mp-g" />
      </g>
      {[0, 1].map((i) => (
        <g key={i} data-root={i} className="mp-root" display="none">
          <circle r={5} />
          <text
            y={i === 0 ? -10 : 20}
            x={i === 0 ? -4 : 4}
            textAnchor={i === 0 ? 'end' : 'start'}
            className="mp-rootlabel"
          />
        </g>
      ))}
    </SvgBox>
  );
}

// ---------------------------------------------------------------------------------------------

export const CASE_COLOURS: Record<RaySphereCase, string> = {
  miss: 'case-miss',
  tangent: 'case-tangent',
  'two-hits': 'case-two-hits',
  inside: 'case-inside',
  behind: 'case-behind',
};
const CASE_SHORT: Record<RaySphereCase, string> = {
  miss: 'miss',
  tangent: 'tangent',
  'two-hits': 'two hits',
  inside: 'inside',
  behind: 'behind',
};

export interface DeltaPlotProps {
  series: SweepSeries;
  /** The sweep coordinate of each tangency. */
  tangentX: number[];
  /** Current position: sweep coordinate and each method's Δ there. */
  x: number;
  discStable: number | null;
  discNaive: number | null;
  xLabel: string;
  method: 'naive' | 'stable';
}

/** The static layer of the Δ plot (curves, case strip, tangency marks): redrawn only when the sweep changes. */
const DeltaStatic = memo(function DeltaStatic({
  series: s,
  tangentX,
  f,
  xd,
  yd,
  xLabel,
}: Omit<DeltaPlotProps, 'x' | 'discStable' | 'discNaive'> & {
  f: Frame;
  xd: [number, number];
  yd: [number, number];
}) {
  const clampY = (v: number) => Math.max(-1e4, Math.min(1e4, f.Y(v)));
  let robust = '';
  s.x.forEach((x, i) => {
    if (!Number.isFinite(x)) return;
    robust += `${robust ? 'L' : 'M'}${f.X(x).toFixed(1)},${clampY(s.discStable[i]).toFixed(1)}`;
  });
  // the textbook Δ as dots: its rounding noise shows as scatter, its wrong signs as dots across 0.
  // Two paths of circles (right sign, wrong sign) rather than an element per sample: ~240 fewer
  // SVG nodes to build, style and lay out when the page opens.
  let dotsOk = '';
  let dotsWrong = '';
  let nWrong = 0;
  const circle = (cx: string, cy: string, r: number) =>
    `M${cx},${cy}m${-r},0a${r},${r} 0 1,0 ${2 * r},0a${r},${r} 0 1,0 ${-2 * r},0`;
  s.x.forEach((x, i) => {
    if (!Number.isFinite(x)) return;
    const v = s.discNaive[i];
    const wrong = Math.sign(v) !== Math.sign(s.discStable[i]);
    const cx = f.X(x).toFixed(1);
    const cy = clampY(v).toFixed(1);
    if (wrong) {
      dotsWrong += circle(cx, cy, 2.6);
      nWrong++;
    } else dotsOk += circle(cx, cy, 1.4);
  });
  // case strip for the chosen method: merge equal neighbours into segments
  const segs: { x0: number; x1: number; c: RaySphereCase }[] = [];
  s.x.forEach((x, i) => {
    const c = s.cases[i];
    const prev = i > 0 ? s.x[i - 1] : x;
    const next = i < s.x.length - 1 ? s.x[i + 1] : x;
    const a = (prev + x) / 2;
    const b = (x + next) / 2;
    const last = segs[segs.length - 1];
    if (last && last.c === c) last.x1 = b;
    else segs.push({ x0: a, x1: b, c });
  });
  const stripY = f.y1 + 32;
  const title = 'Δ against the sweep';
  return (
    <g>
      <Axes f={f} xd={xd} yd={yd} title={title} xLabel={xLabel} yLabel="Δ = b² − 4ac" />
      <g clipPath={`url(#${clipId('delta')})`}>
        {tangentX.map((x, i) => (
          <line key={i} x1={f.X(x)} x2={f.X(x)} y1={f.y0} y2={f.y1} className="mp-tangent" />
        ))}
        <path d={dotsOk} className="mp-naive" />
        <path d={dotsWrong} className="mp-naive wrong" data-count={nWrong} />
        <path d={robust} className="mp-robust" />
      </g>
      {tangentX.map((x, i) => (
        <text key={i} x={f.X(x) + 4} y={f.y0 + 14} textAnchor="start" className="mp-tick mp-tangent-label">
          tangent
        </text>
      ))}
      <g className="mp-strip" aria-hidden="true">
        {segs.map((g, i) => (
          <rect
            key={i}
            x={Math.min(f.X(g.x0), f.X(g.x1))}
            width={Math.max(0.5, Math.abs(f.X(g.x1) - f.X(g.x0)))}
            y={stripY - 8}
            height={8}
            className={`mp-case ${CASE_COLOURS[g.c]}`}
          >
            <title>{CASE_SHORT[g.c]}</title>
          </rect>
        ))}
      </g>
      <g className="mp-legend">
        <line x1={f.x0} x2={f.x0 + 20} y1={f.y0 - 12} y2={f.y0 - 12} className="mp-robust" />
        <text x={f.x0 + 25} y={f.y0 - 7} className="mp-tick">
          robust
        </text>
        <circle cx={f.x0 + 100} cy={f.y0 - 12} r={2.6} className="mp-naive" />
        <text x={f.x0 + 107} y={f.y0 - 7} className="mp-tick">
          textbook (dots)
        </text>
      </g>
    </g>
  );
});

/** Δ against the sweep coordinate; the current position moves along it. */
export function DeltaSweepPlot(
  p: DeltaPlotProps & {
    drawRef?: { current: ((x: number, discStable: number | null, discNaive: number | null) => void) | null };
  },
) {
  const plot = usePlotBox();
  const { W, svgRef: svg } = plot;
  const H = Math.round(Math.min(340, Math.max(270, W * 0.58)));
  const s = p.series;
  const xd = useMemo<[number, number]>(() => {
    const xs = s.x.filter(Number.isFinite);
    const lo = Math.min(...xs);
    const hi = Math.max(...xs);
    return hi > lo ? [lo, hi] : [lo - 1, lo + 1];
  }, [s]);
  const yd = useMemo<[number, number]>(() => {
    const ys = [...s.discStable, ...s.discNaive, 0].filter(Number.isFinite);
    const lo = Math.min(...ys);
    const hi = Math.max(...ys);
    const pad = 0.08 * (hi - lo || 1);
    return [lo - pad, hi + pad];
  }, [s]);
  // the case strip sits between the x tick labels and the axis label
  const f = useMemo(() => makeFrame(W, H, xd, yd, 64, 50), [W, H, xd, yd]);
  // the current position (line and two dots) is written directly: after each render, and per
  // animation frame through drawRef (the last position drawn is kept for the next render)
  const last = useRef<[number, number | null, number | null]>([p.x, p.discStable, p.discNaive]);
  const draw = (x: number, discStable: number | null, discNaive: number | null) => {
    last.current = [x, discStable, discNaive];
    const el = svg.current;
    if (!el) return;
    const cx = (Number.isFinite(x) ? f.X(Math.max(xd[0], Math.min(xd[1], x))) : f.x0).toFixed(1);
    const [line, dn, ds] = [
      el.querySelector('line.mp-now'),
      el.querySelector('circle.mp-now-naive'),
      el.querySelector('circle.mp-now-robust'),
    ];
    line?.setAttribute('x1', cx);
    line?.setAttribute('x2', cx);
    const dot = (c: Element | null, v: number | null) => {
      if (!c) return;
      if (v === null || !Number.isFinite(v)) {
        c.setAttribute('display', 'none');
        return;
      }
      c.removeAttribute('display');
      c.setAttribute('cx', cx);
      c.setAttribute('cy', Math.max(f.y0, Math.min(f.y1, f.Y(v))).toFixed(1));
    };
    dot(dn, discNaive);
    dot(ds, discStable);
  };
  if (p.drawRef) p.drawRef.current = draw;
  else last.current = [p.x, p.discStable, p.discNaive];
  useLayoutEffect(() => draw(...last.current));
  return (
    <SvgBox {...plot} name="delta" f={f}>
      <DeltaStatic
        series={s}
        tangentX={p.tangentX}
        f={f}
        xd={xd}
        yd={yd}
        xLabel={p.xLabel}
        method={p.method}
      />
      <line y1={f.y0} y2={f.y1 + 34} className="mp-now" />
      <circle r={5.5} className="mp-now-naive" display="none" />
      <circle r={5.5} className="mp-now-robust" display="none" />
    </SvgBox>
  );
}
