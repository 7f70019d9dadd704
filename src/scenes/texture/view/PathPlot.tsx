/**
 * The looked-up value along the query's path, under the grid: nearest as a step
 * function, bilinear as a continuous curve with its cell borders marked (solid where the slope
 * changes, a kink; dotted where it does not), and the current position. Drawn in CSS pixels (the
 * SVG is as wide as its box), so text stays at its stated size on phones. The curves are memoized
 * on the profile; only the position marker re-renders per animation frame. Until the profile is
 * computed (a task after the page's first render, so loading has no long task) the figure keeps its size, empty.
 */
import { memo, useMemo, useRef, type ReactNode } from 'react';
import { DescribedFigure } from '../../../ui';
import { useWidth } from '../../../ui/useWidth';
import { niceTicks } from '../../../ui/axis';
import type { PathProfile } from '../pathProfile';
import { linearScale } from '../../../ui/chartScale';
import { formatRounded } from '../../../core/format';
import './PathPlot.css';

const M = { l: 46, r: 12, t: 10, b: 34 };

interface Scale {
  w: number;
  h: number;
  y0: number;
  y1: number;
}
// the shared chart guard: finite coordinates for any data (../../../ui/chartScale)
const X = (s: Scale, t: number) => linearScale(0, 1, M.l, s.w - M.r)(t);
const Y = (s: Scale, y: number) => linearScale(s.y1, s.y0, M.t, s.h - M.b)(y);

const Curves = memo(function Curves({ profile, s }: { profile: PathProfile; s: Scale }) {
  // bilinear: one path, moving (M) where it breaks at a jump
  let d = '';
  const brk = new Set(profile.breaks);
  profile.ts.forEach((t, k) => {
    d += `${k === 0 || brk.has(k) ? 'M' : 'L'}${X(s, t).toFixed(1)} ${Y(s, profile.bil[k]).toFixed(1)}`;
  });
  // nearest: horizontal pieces joined by vertical risers at the switches
  let n = '';
  profile.near.forEach((p, k) => {
    const y = Y(s, p.value).toFixed(1);
    n += `${k === 0 ? 'M' : 'L'}${X(s, p.t0).toFixed(1)} ${y}L${X(s, p.t1).toFixed(1)} ${y}`;
  });
  const yt = niceTicks(s.y0, s.y1, 4, 'atLeast').ticks;
  const bottom = s.h - M.b;
  return (
    <g>
      <rect x={M.l} y={M.t} width={s.w - M.l - M.r} height={bottom - M.t} className="tx-plot-bg" />
      {profile.borders.map((b, k) => (
        <line
          key={k}
          x1={X(s, b.t)}
          x2={X(s, b.t)}
          y1={M.t}
          y2={bottom}
          className={b.kink ? 'tx-plot-border kink' : b.jump ? 'tx-plot-border jump' : 'tx-plot-border'}
        />
      ))}
      {yt.map((y) => (
        <g key={y}>
          <line x1={M.l - 4} x2={M.l} y1={Y(s, y)} y2={Y(s, y)} className="tx-plot-axis" />
          <text x={M.l - 6} y={Y(s, y) + 4} textAnchor="end" className="tx-plot-text">
            {formatRounded(y)}
          </text>
        </g>
      ))}
      {[0, 0.25, 0.5, 0.75, 1].map((t) => (
        <g key={t}>
          <line x1={X(s, t)} x2={X(s, t)} y1={bottom} y2={bottom + 4} className="tx-plot-axis" />
          <text x={X(s, t)} y={bottom + 17} textAnchor="middle" className="tx-plot-text">
            {t}
          </text>
        </g>
      ))}
      <text x={s.w - M.r} y={s.h - 2} textAnchor="end" className="tx-plot-text">
        position on the path, t
      </text>
      <path d={n} className="tx-plot-near" />
      <path d={d} className="tx-plot-bil" />
      <line x1={M.l} x2={M.l} y1={M.t} y2={bottom} className="tx-plot-axis" />
      <line x1={M.l} x2={s.w - M.r} y1={bottom} y2={bottom} className="tx-plot-axis" />
    </g>
  );
});

export function PathPlot({
  profile,
  t,
  near,
  bil,
  present,
  description,
  children,
  drawRef,
}: {
  /** null while it is computed: the figure keeps its box (no layout shift), without curves. */
  profile: PathProfile | null;
  t: number;
  near: number;
  bil: number;
  present: boolean;
  /** What the plot shows, in words (its accessible description). */
  description: string;
  /** Under the legend: the plot's data as a table and as sound. */
  children?: ReactNode;
  /** Set to a function that moves the marker directly (per animation frame; the label follows on pause). */
  drawRef?: { current: ((t: number, near: number, bil: number) => void) | null };
}) {
  const ref = useRef<HTMLDivElement>(null);
  const markerRef = useRef<SVGGElement>(null);
  const w = useWidth(ref, 480);
  const h = present ? 230 : 180;
  const s = useMemo<Scale | null>(() => {
    if (!profile) return null;
    const pad = Math.max(1e-9, (profile.max - profile.min) * 0.08, Math.abs(profile.max) * 1e-9);
    return { w, h, y0: profile.min - pad, y1: profile.max + pad };
  }, [profile, w, h]);
  if (drawRef) {
    drawRef.current = (tt, n, b) => {
      const g = markerRef.current;
      if (!s || !g || g.children.length !== 3) return;
      const [line, nd, bd] = g.children;
      const x = String(X(s, tt));
      line.setAttribute('x1', x);
      line.setAttribute('x2', x);
      nd.setAttribute('cx', x);
      nd.setAttribute('cy', String(Y(s, n)));
      bd.setAttribute('cx', x);
      bd.setAttribute('cy', String(Y(s, b)));
    };
  }
  return (
    <DescribedFigure
      label="The looked-up value along the path: nearest and bilinear against the position t"
      description={description}
      testId="path-plot-figure"
      quiet
    >
      <div
        className="tx-plot"
        data-testid="path-plot"
        data-borders={profile?.borders.length}
        data-kinks={profile ? profile.borders.filter((b) => b.kink).length : undefined}
        data-jumps={profile ? profile.borders.filter((b) => b.jump).length : undefined}
        data-steps={profile?.nearSwitches.length}
      >
        <div ref={ref} className="tx-plot-box">
          <svg width={w} height={h} viewBox={`0 0 ${w} ${h}`} aria-hidden="true">
            {profile && s ? (
              <>
                <Curves profile={profile} s={s} />
                <g data-testid="path-plot-marker" ref={markerRef}>
                  <line x1={X(s, t)} x2={X(s, t)} y1={M.t} y2={h - M.b} className="tx-plot-now" />
                  <circle cx={X(s, t)} cy={Y(s, near)} r={5} className="tx-plot-near-dot" />
                  <circle cx={X(s, t)} cy={Y(s, bil)} r={5} className="tx-plot-bil-dot" />
                </g>
              </>
            ) : null}
          </svg>
        </div>
        <div className="tx-plot-legend" aria-hidden="true">
          <span>
            <span className="tx-lg bil" /> bilinear
          </span>
          <span>
            <span className="tx-lg near" /> nearest (steps)
          </span>
          <span>
            <span className="tx-lg kink" /> cell border with a kink
          </span>
          <span>
            <span className="tx-lg border" /> cell border, no kink
          </span>
        </div>
        {children}
      </div>
    </DescribedFigure>
  );
}
