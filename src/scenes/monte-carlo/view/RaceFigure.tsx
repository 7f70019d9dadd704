/**
 * The animation of Q4: samples arrive one by one on the shared timeline (t = samples
 * drawn so far). Each xᵢ drops onto the integrand, its term f(xᵢ)/p(xᵢ) appears, and the running
 * estimate with its ± standard-error band and the |error| log-log curve grow with it — uniform and
 * importance sampling side by side, on the same random numbers ξᵢ. Everything at position t comes
 * from the race (raceAt / raceHeadAt at t); this file only draws it. While playing, React does not
 * re-render the figure at all: every frame, a timeline subscription writes the moving SVG nodes (the
 * rugs, the newest samples, the curves and bands) directly, and the readouts and their labels at most
 * TEXT_HZ times a second. The growing curves are polylines over fixed sample counts
 * (race.ts's racePoints): their segments are formatted once per track, and a frame only joins the
 * segments up to t (appending to the previous frame's string) and adds the point at t itself.
 * React renders the exact position on pause, step, seek and reset.
 */
import { memo, useLayoutEffect, useMemo, useRef } from 'react';
import {
  DescribedFigure,
  formatNumber,
  keepTextParenthesesTogether,
  Revealed,
  STRATEGY_COLOR,
  TEXT_HZ,
  TimelineTransport,
  useTimeline,
  useTimelineFrame,
} from '../../../ui';
import { pow10Text } from '../../../ui/axis';
import { Fold } from '../../../ui/Fold';
import { RunningEstimatePlot } from '../../../ui/RunningEstimatePlot';
import { Axes, H, LineKey, M, PW, raceScales, roundUp2, W, type RaceCurve } from './raceSvg';
import { RaceHistogram } from './RaceHistogram';
import { raceWords } from './RaceData';
import { gridAt } from '../curves';
import {
  drawDot,
  drawRug,
  raceCurves,
  rugPaths,
  rugY,
  RECENT,
  RUG_BUCKETS,
  type RaceGeom,
} from './raceCurves';
import { drawLane, LaneReadouts, useLaneRefs } from './LaneReadouts';
import { RACE_DURATION, RACE_MAX, raceHeadAt, racePoints, type RaceTrack } from '../race';

// the shared strategy colours (src/ui/palette): 3 : 1 in both themes, apart under colour-vision deficiencies
const C_U = STRATEGY_COLOR.uniform;
const C_I = STRATEGY_COLOR.importance;

// the shared chart guard: every coordinate finite, for any data (../../../ui/chartScale)

/** React renders of the race while it plays: none (everything that moves is written per frame). */
const RENDER_HZ = 0;

export interface RaceProps {
  track: RaceTrack;
  /** f and the importance pdf scaled to f's height, on a grid over [a, b]. */
  curve: RaceCurve;
  a: number;
  b: number;
  /** e.g. "p ∝ f, p = 3(x + 2)²/56". */
  importanceLabel: string;
  /** The importance pdf, short ("p ∝ f"), for the figure's description. */
  importanceName: string;
  /** The half of [a, b] where the importance pdf is heavier (the description says how many fell there). */
  half: [number, number] | null;
  /** Classroom mode: the race is the stage, its plots in a grid sized to the first screen. */
  staged: boolean;
  /** ask=1: held at its start, its transport hidden (nothing can play) until revealed. */
  held: boolean;
  t: number;
  play: boolean;
  setParams: (patch: { t?: number; play?: boolean }) => void;
}

/**
 * The race's clock: t counts the samples drawn (whole numbers, 0…RACE_MAX), at a fixed duration and
 * redraw rate, running only while `box` is on screen; the keyboard shortcuts are off while held.
 */
function useRaceClock(t: number, play: boolean, setParams: RaceProps['setParams'], held: boolean) {
  const box = useRef<HTMLDivElement>(null);
  const tl = useTimeline({
    t,
    play,
    setParams,
    max: RACE_MAX,
    integer: true,
    duration: RACE_DURATION,
    visibleRef: box,
    renderHz: RENDER_HZ,
    shortcuts: !held,
  });
  return { box, tl };
}

/** The race figure with its transport. Memoised: only a change of track or position redraws it. */
export const RaceFigure = memo(function RaceFigure({
  track,
  curve,
  a,
  b,
  importanceLabel,
  importanceName,
  half,
  staged,
  held,
  t,
  play,
  setParams,
}: RaceProps) {
  const { box, tl } = useRaceClock(t, play, setParams, held);
  const points = useMemo(() => racePoints(track.max), [track.max]);
  const fr = useMemo(() => raceHeadAt(track, tl.t, RECENT), [track, tl.t]);
  const I = track.exact;

  // --- static parts (keyed on the track and the curve, not on t) ----------------------------
  const fig = useMemo(() => raceScales(track, curve, a, b), [track, curve, a, b]);

  // the histograms' pdfs on the drawn grid (the importance curve is drawn scaled to f: unscale it), and
  // one density axis for both lanes, so their bars compare
  const hist = useMemo(() => {
    const pu = new Float64Array(curve.x.length).fill(1 / (b - a));
    const pi = curve.p.map((v) => v / curve.scale);
    let top = 1 / (b - a);
    for (const v of pi) if (Number.isFinite(v)) top = Math.max(top, v);
    return { pu, pi, yMax: roundUp2(1.35 * top) };
  }, [curve, a, b]);

  const { sx, sy, ey } = fig;
  // the growing curves' segments, formatted once per track (see the module comment)
  const curves = useMemo(() => raceCurves(track, points, fig, I), [track, points, fig, I]);
  // what moves, as a function of t (shared by the React render and the per-frame writes)
  const geomAt = (t: number): RaceGeom => {
    const f = raceHeadAt(track, t, RECENT);
    const dot = (n: number, x: number, fx: number) => (n ? { x: sx(x), y: sy(fx) } : null);
    return {
      ...curves.at(f.t),
      rugU: f.recentU.map(sx),
      rugI: f.recentI.map(sx),
      dotU: dot(f.uniform.n, f.uniform.x, f.uniform.term / (b - a)),
      dotI: dot(f.importance.n, f.importance.x, gridAt(curve.x, curve.f, f.importance.x)),
    };
  };
  const g = geomAt(fr.t);
  const rate = (RACE_MAX / RACE_DURATION) * tl.speed;
  // the figures in words at the rendered position (React renders it on pause, step, seek and reset)
  const words = useMemo(
    () => raceWords({ track, t: fr.t, points, importanceName, half, a, b, fValues: curve.f, held }),
    [track, fr.t, points, importanceName, half, a, b, curve.f, held],
  );

  // per-frame writes (see the module comment); React's render below is the same geometry at tl.t
  const svgF = useRef<SVGSVGElement>(null);
  const pathRefs = useRef<
    Record<keyof Pick<RaceGeom, 'uErr' | 'iErr' | 'uBand' | 'iBand' | 'uEst' | 'iEst'>, SVGPathElement | null>
  >({ uErr: null, iErr: null, uBand: null, iBand: null, uEst: null, iEst: null });
  const laneU = useLaneRefs();
  const laneI = useLaneRefs();
  const lastText = useRef(-Infinity);
  const draw = (tt: number, playing: boolean) => {
    const gg = geomAt(tt);
    for (const k of ['uErr', 'iErr', 'uBand', 'iBand', 'uEst', 'iEst'] as const) {
      const el = pathRefs.current[k];
      if (el && el.getAttribute('d') !== gg[k]) el.setAttribute('d', gg[k]);
    }
    const svg = svgF.current;
    if (svg) {
      drawRug(svg.querySelector('[data-rug="0"]'), gg.rugU, rugY(0));
      drawRug(svg.querySelector('[data-rug="1"]'), gg.rugI, rugY(1));
      drawDot(svg.querySelector('[data-dot="0"]'), gg.dotU);
      drawDot(svg.querySelector('[data-dot="1"]'), gg.dotI);
    }
    // text: at most TEXT_HZ times a second while playing, exact when paused
    const now = performance.now();
    if (playing && now - lastText.current < 1000 / TEXT_HZ - 1) return;
    lastText.current = now;
    const h = raceHeadAt(track, tt, 0);
    drawLane(laneU, h.uniform);
    drawLane(laneI, h.importance);
  };
  const drawRef = useRef(draw);
  drawRef.current = draw;
  useTimelineFrame(tl, (tt, playing) => drawRef.current(tt, playing));
  // after every render too (a new track at the same position changes the numbers React does not render)
  useLayoutEffect(() => drawRef.current(tl.now(), tl.playing));
  const setPath = (k: keyof typeof pathRefs.current) => (el: SVGPathElement | null) => {
    pathRefs.current[k] = el;
  };

  // while playing the newest dot keeps its element (no drop animation per frame); stepped, it drops in
  const newestDot = (d: { x: number; y: number } | null, color: string, row: number) => (
    <g
      key={tl.playing ? `${row}` : `${row}-${fr.t}`}
      className="mc-drop"
      data-dot={row}
      style={d ? undefined : { display: 'none' }}
    >
      <line
        x1={d?.x ?? 0}
        x2={d?.x ?? 0}
        y1={M.t}
        y2={d?.y ?? 0}
        style={{ stroke: color }}
        strokeDasharray="2 3"
      />
      {/* filled for uniform, hollow for importance: the shape tells the lanes apart, not only the colour */}
      <circle
        cx={d?.x ?? 0}
        cy={d?.y ?? 0}
        r={5}
        style={row ? { stroke: color } : { fill: color }}
        className={row ? 'mc-dot-hollow' : undefined}
      />
    </g>
  );
  // the rug: RUG_BUCKETS paths per row, older samples fainter, so a frame writes a few `d`s
  const rug = (xs: number[], color: string, row: number) => {
    const d = rugPaths(xs, rugY(row));
    return (
      <g data-rug={row}>
        {d.map((p, k) => (
          <path
            key={k}
            d={p}
            style={{ stroke: color, strokeOpacity: 0.25 + (0.75 * (k + 1)) / RUG_BUCKETS }}
          />
        ))}
      </g>
    );
  };

  // the figure's pieces: the shared plots, and per lane its title, readouts, histogram and
  // running estimate; the page groups them by lane, the stage lays them out in one grid
  const fPlot = (
    <DescribedFigure
      key="f"
      className="mc-svg-fig"
      label="Each sample drops onto f"
      description={words.integrand}
      quiet
      testId="race-integrand"
    >
      <figcaption>
        Each xᵢ drops onto f
        {staged ? null : ` (● uniform, ○ importance; newest ${RECENT} as ticks, uniform above)`}
      </figcaption>
      <svg ref={svgF} viewBox={`0 0 ${W} ${H}`} aria-hidden="true">
        <Axes xTicks={fig.xt} yTicks={fig.yt} xLabel="x" yLabel="f(x)" />
        <path d={fig.fPath} className="mc-svg-f" />
        <path d={fig.pPath} style={{ stroke: C_I }} className="mc-svg-p" />
        {rug(g.rugU, C_U, 0)}
        {rug(g.rugI, C_I, 1)}
        {newestDot(g.dotU, C_U, 0)}
        {newestDot(g.dotI, C_I, 1)}
      </svg>
    </DescribedFigure>
  );
  // held (ask=1): no |error| and no running estimates (their axes would give the exact value away)
  const xPlot = held ? null : (
    <DescribedFigure
      key="x"
      className="mc-svg-fig"
      label="|error| of the running estimates against N, log–log"
      description={words.errors}
      quiet
      testId="race-errors"
    >
      <figcaption>|⟨I⟩ − I| against N, log-log</figcaption>
      <svg viewBox={`0 0 ${W} ${H}`} aria-hidden="true">
        <Axes xTicks={fig.nt} yTicks={fig.lt} xLabel="N (samples)" yLabel="|error|" />
        <path d={fig.guide} className="mc-svg-guide" />
        <path ref={setPath('uErr')} d={g.uErr} style={{ stroke: C_U }} className="mc-svg-line" />
        <path
          ref={setPath('iErr')}
          d={g.iErr}
          style={{ stroke: C_I }}
          className="mc-svg-line mc-svg-dashed"
        />
        <LineKey
          x={M.l + PW - 140}
          y={M.t + 14}
          items={[
            ['uniform', C_U, false],
            ['importance', C_I, true],
          ]}
        />
      </svg>
    </DescribedFigure>
  );
  // what the two lanes' histograms share: the interval, the grid of the pdf curve, the count scale, the clock
  const histShared = { a, b, px: curve.x, yMax: hist.yMax, tl, t: fr.t, half, staged };
  const lanes = (
    [
      {
        id: 'uniform',
        name: 'Uniform, p = 1/(b − a)',
        color: C_U,
        refs: laneU,
        k: 'u',
        xs: track.uniform.x,
        py: hist.pu,
        pdf: `p(x) = ${formatNumber(1 / (b - a), 4)}`,
      },
      {
        id: 'importance',
        name: `Importance, ${importanceLabel}`,
        color: C_I,
        refs: laneI,
        k: 'i',
        xs: track.importance.x,
        py: hist.pi,
        pdf: importanceName === 'p ∝ f' ? 'p(x) ∝ f(x)' : `p(x), ${importanceName}`,
      },
    ] as const
  ).map(({ id, name, color, refs, k, xs, py, pdf }) => ({
    id,
    color,
    title: (
      <h4 key={`t${k}`} className="mc-lane-title mc-half" style={{ color }}>
        {name}
      </h4>
    ),
    readouts: <LaneReadouts key={`r${k}`} id={id} r={refs} />,
    hist: (
      <RaceHistogram key={`h${k}`} {...histShared} id={id} xs={xs} py={py} pdfLabel={pdf} color={color} />
    ),
    est: held ? null : (
      <DescribedFigure
        key={`e${k}`}
        className="mc-svg-fig"
        label={`The ${id} running estimate with its ± s/√N band, against N on a log axis`}
        description={words[id]}
        quiet
        testId={`race-estimate-${id}`}
      >
        <figcaption>⟨I⟩ against N, with its ± s/√N band</figcaption>
        <RunningEstimatePlot
          width={W}
          height={H}
          margin={M}
          xTicks={fig.nt}
          yTicks={fig.et}
          xLabel="N (samples)"
          yLabel="estimate"
          exactY={ey(I)}
          band={g[`${k}Band`]}
          line={g[`${k}Est`]}
          color={color}
          dashed={k === 'i'}
          bandRef={setPath(`${k}Band`)}
          lineRef={setPath(`${k}Est`)}
        />
      </DescribedFigure>
    ),
  }));
  const [U, Im] = lanes;

  return (
    <div className={staged ? 'mc-race mc-race-staged' : 'mc-race'} ref={box} data-testid="race">
      <DescribedFigure
        label="The race: uniform against importance sampling, one sample at a time"
        description={words.main}
        playing={tl.playing}
        testId="race-figure"
      >
        <Revealed ask={held} what="the samples: reveal, then play them" testId="ask-hidden-race">
          <TimelineTransport
            timeline={tl}
            label="Samples arriving"
            // the race's own length, not the side panel's N (the samples of the estimate ⟨I⟩)
            format={(n) => `${n} of the race’s ${RACE_MAX} samples`}
            testId="timeline"
          >
            <span className="mc-note" data-testid="race-rate">
              {formatNumber(rate, 4)} samples/s
            </span>
          </TimelineTransport>
        </Revealed>
        <div className={`mc-race-grid${staged ? ' stage-figure' : ''}${held ? ' is-held' : ''}`}>
          {staged
            ? [U.title, Im.title, U.readouts, Im.readouts, U.hist, fPlot, Im.hist, U.est, xPlot, Im.est]
            : [
                fPlot,
                xPlot,
                ...lanes.map((L) => (
                  <div key={L.id} className="mc-lane" style={{ borderTopColor: L.color }}>
                    {L.title}
                    {L.readouts}
                    {held ? L.hist : null}
                    {L.est}
                  </div>
                )),
                // on the page the histograms are one click away (while asking they are the setup to
                // predict on, so they stay)
                held ? null : (
                  <Fold
                    key="hists"
                    name="race-histograms"
                    className="mc-race-hists"
                    summary="Where the samples fell: each lane’s histogram against its pdf p(x)"
                  >
                    <div className="mc-race-grid">
                      {lanes.map((L) => (
                        <div key={L.id} className="mc-lane" style={{ borderTopColor: L.color }}>
                          {L.hist}
                        </div>
                      ))}
                    </div>
                  </Fold>
                ),
              ]}
        </div>
        <p className="mc-note mc-race-note">
          Solid blue: uniform; dashed orange: importance (its pdf dashed on f). Grey dashes: the exact I ={' '}
          {formatNumber(I, 8)}; the grey line: the N⁻½ trend σ/√N. Both estimators use the same random numbers
          ξᵢ (seeded): uniform puts xᵢ = a + {keepTextParenthesesTogether('(b − a)ξᵢ')}, importance xᵢ =
          P⁻¹(ξᵢ). Errors below {pow10Text(Math.round(Math.log10(fig.floor)))} sit on the bottom line.
        </p>
      </DescribedFigure>
    </div>
  );
});
