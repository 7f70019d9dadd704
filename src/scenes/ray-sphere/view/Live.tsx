/**
 * The figures at the sweep's live position. The scene does not re-render while the sweep plays:
 * the figures that move every frame (the cross-section, the two plots) are drawn directly on each
 * timeline frame; the text (case banner, 3D view) re-renders at most RENDER_HZ times a second.
 */
import { useLayoutEffect, useRef, type ReactNode } from 'react';
import { useCoarsePosition, useTimelineFrame, type Timeline } from '../../../ui';
import type { RaySphereHit } from '../../../core/geometry';
import { caseBanner } from '../caseText';
import { sweepAt, type Sweep } from '../sweep';
import { activeRows, type RaySphereModel } from '../model';
import { type SweepSeries } from '../sweepSeries';
import type { Vec3 } from '../../../core/vec3';
import type { RaySphereParams } from '../params';
import { CrossSection, type CrossRay } from './CrossSection';
import { DeltaSweepPlot, GSweepPlot } from './SweepPlots';
import { View3D, type View3DProps } from './View3D';

/**
 * How often the scene's text (readouts, case, notes, the 3D view) re-renders while the sweep plays:
 * those parts subscribe to the timeline themselves (useCoarsePosition); the scene itself does not
 * re-render while playing (renderHz 0), and the figures move every frame by direct writes.
 */
export const RENDER_HZ = 4;

/** The model at a timeline position (memoised on the last position asked for). */
export type ModelAt = (t: number) => RaySphereModel;

/** What every live part reads: the timeline and the model along the sweep. */
export interface LiveProps {
  tl: Timeline;
  modelAt: ModelAt;
}

/** The model at the coarse position (see RENDER_HZ). */
export function useCoarseModel({ tl, modelAt }: LiveProps): { t: number; model: RaySphereModel } {
  const t = useCoarsePosition(tl, RENDER_HZ);
  return { t, model: modelAt(t) };
}

/**
 * Calls `draw` with the live position on every timeline frame and after every render: the latest
 * `draw` (a ref), so it may close over this render's props.
 */
function useDrawEveryFrame(tl: Timeline, draw: (t: number) => void): void {
  const latest = useRef(draw);
  latest.current = draw;
  useTimelineFrame(tl, (t) => latest.current(t));
  useLayoutEffect(() => latest.current(tl.now()));
}

/**
 * The cross-section at the live position: React renders it when the inputs change; every frame
 * (and after each render) the ray is drawn directly (CrossSection's drawRef).
 */
export function LiveCrossSection({
  tl,
  modelAt,
  onChange,
  fitExtra,
  hideResults = false,
  fill,
}: LiveProps & {
  onChange: (patch: Partial<RaySphereParams>) => void;
  fitExtra: readonly Vec3[];
  /** Draw the ray and the sphere only, without the roots (ask=1 before Reveal). */
  hideResults?: boolean;
  fill?: boolean;
}) {
  const drawRef = useRef<((ray: CrossRay) => void) | null>(null);
  const rayAt = (t: number): CrossRay => {
    const m = modelAt(t);
    return { ...m.input, res: hideResults ? null : m.chosen, distanceRatio: m.distanceRatio };
  };
  useDrawEveryFrame(tl, (t) => drawRef.current?.(rayAt(t)));
  const first = rayAt(tl.now());
  return <CrossSection {...first} onChange={onChange} fitExtra={fitExtra} drawRef={drawRef} fill={fill} />;
}

function CaseBanner({ model, method }: { model: RaySphereModel; method: RaySphereParams['method'] }) {
  const res = model.chosen;
  if (!res) return null;
  const exact = activeRows(model).reference?.case ?? null;
  const form = method === 'naive' ? 'textbook' : 'robust';
  const b = caseBanner(res.case, exact, form, model.precision === 'f32' ? 'float32' : 'double');
  return (
    <div className={`rs-case case-${res.case}`} data-testid="case-banner">
      <strong>{b.name}</strong>
      <span>{b.text}</span>
      {b.wrong ? <span data-testid="case-banner-wrong">{b.wrong}</span> : null}
    </div>
  );
}

/** The case banner at the coarse position. */
export function LiveCaseBanner(props: LiveProps & { method: RaySphereParams['method'] }) {
  return <CaseBanner model={useCoarseModel(props).model} method={props.method} />;
}

/** The 3D view at the coarse position (below the fold). */
export function LiveView3D({
  tl,
  modelAt,
  ...rest
}: LiveProps & Pick<View3DProps, 'height' | 'dark' | 'fitExtra'>) {
  const m = useCoarseModel({ tl, modelAt }).model;
  const { o, d, c, r } = m.input;
  return <View3D o={o} d={d} c={c} r={r} res={m.chosen} distanceRatio={m.distanceRatio} {...rest} />;
}

/**
 * g(t) and Δ against the sweep at the live position: React renders the plots when the sweep or the
 * sizes change; every frame (and after each render) the moving parts are written directly.
 */
export function LivePlots({
  tl,
  modelAt,
  sweep,
  series,
  tangentX,
  xLabel,
  method,
  aroundG = (el) => el,
  aroundDelta = (el) => el,
}: LiveProps & {
  sweep: Sweep;
  series: SweepSeries;
  tangentX: number[];
  xLabel: string;
  method: RaySphereParams['method'];
  /** What goes around each plot (its described figure, its table and audio trace). */
  aroundG?: (plot: ReactNode) => ReactNode;
  aroundDelta?: (plot: ReactNode) => ReactNode;
}) {
  const g = useRef<((res: RaySphereHit | null) => void) | null>(null);
  const delta = useRef<((x: number, discStable: number | null, discNaive: number | null) => void) | null>(
    null,
  );
  const at = (t: number) => {
    const m = modelAt(t);
    return {
      res: m.chosen,
      x: sweepAt(sweep, t).x,
      stable: m.rows.find((x) => x.method === 'stable')?.res.discriminant ?? null,
      naive: m.rows.find((x) => x.method === 'naive')?.res.discriminant ?? null,
    };
  };
  useDrawEveryFrame(tl, (t) => {
    const a = at(t);
    g.current?.(a.res);
    delta.current?.(a.x, a.stable, a.naive);
  });
  const first = at(tl.now());
  return (
    <>
      {aroundG(<GSweepPlot res={first.res} window={series.gWindow} drawRef={g} />)}
      {aroundDelta(
        <DeltaSweepPlot
          series={series}
          tangentX={tangentX}
          x={first.x}
          discStable={first.stable}
          discNaive={first.naive}
          xLabel={xLabel}
          method={method}
          drawRef={delta}
        />,
      )}
    </>
  );
}
