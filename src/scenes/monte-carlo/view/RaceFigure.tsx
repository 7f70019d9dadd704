/**
 * The animation of Q4: samples arrive one by one on the shared timeline (t = samples
 * drawn so far). Each xᵢ drops onto the integrand, its term f(xᵢ)/p(xᵢ) appears, and the running
 * estimate with its ± standard-error band and the |error| log-log curve grow with it — uniform and
 * importance sampling side by side, on the same random numbers ξᵢ. Everything at position t comes
 * from the model (raceAt / raceHeadAt at t); this file only draws it. While playing, React does not
 * re-render the figure at all: every frame, a timeline subscription writes the moving SVG nodes (the
 * rugs, the newest samples, the curves and bands) directly, and the readouts and their labels at most
 * TEXT_HZ times a second. The growing curves are polylines over fixed sample counts
 * (model.racePoints): their segments are formatted once per track, and a frame only joins the
 * segments up to t (appending to the previous frame's string) and adds the point at t itself.
 * React renders the exact position on pause, step, seek and reset.
 */
import { memo, useLayoutEffect, useMemo, useRef } from 'react';
import {
  DescribedFigure,
  formatNumber,
  LiveReadout,
  Revealed,
  STRATEGY_COLOR,
  TEXT_HZ,
  TimelineTransport,
  useTimeline,
  useTimelineFrame,
  writeReadout,
} from '../../../ui';
import { pow10Text } from '../../../ui/axis';
import { clampExponent, fmt, linearScale, logScale, type Scale } from '../../../ui/chartScale';
import { Axes, H, M, path, PH, PW, W } from './raceSvg';
import { RaceHistogram } from './RaceHistogram';
import { raceWords } from './RaceData';
import { gridAt } from '../curves';
import {
  RACE_DURATION,
  RACE_MAX,
  raceHeadAt,
  raceLaneAt,
  racePoints,
  type LaneState,
  type RaceTrack,
} from '../race';

// the shared strategy colours (src/ui/palette): 3 : 1 in both themes, apart under colour-vision deficiencies
const C_U = STRATEGY_COLOR.uniform;
const C_I = STRATEGY_COLOR.importance;

// the shared chart guard: every coordinate finite, for any data (../../../ui/chartScale)
const lin = linearScale;
const logS = logScale;

const N_TICKS: number[] = [1, 10, 100, 1000].filter((n) => n <= RACE_MAX);
/** Samples shown in each rug (the latest ones). */
const RECENT = 40;
/** React renders of the race while it plays: none (everything that moves is written per frame). */
const RENDER_HZ = 0;

export interface RaceProps {
  track: RaceTrack;
  /** f and the importance pdf scaled to f's height, on a grid over [a, b]. */
  curve: { x: Float64Array; f: Float64Array; p: Float64Array; scale: number };
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

/** What a lane's ± s/√N reads when the terms' spread is zero to rounding (model.zeroToRounding). */
export const ZERO_TEXT = '0 (zero variance)';

/** A small key of line styles: a stroke sample (solid or dashed) and its name per row. */
function LineKey({ x, y, items }: { x: number; y: number; items: [string, string, boolean][] }) {
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
function roundUp2(v: number): number {
  if (!(v > 0 && Number.isFinite(v))) return 1;
  const u = 10 ** (Math.floor(Math.log10(v)) - 1);
  return Math.ceil(v / u - 1e-9) * u;
}

/** The readouts of a lane: written directly (see drawLane), not rendered by React. */
interface LaneRefs {
  x: React.RefObject<HTMLOutputElement | null>;
  term: React.RefObject<HTMLOutputElement | null>;
  estimate: React.RefObject<HTMLOutputElement | null>;
  stderr: React.RefObject<HTMLOutputElement | null>;
  /** The label's sample index (x<sub>n</sub>) and count (⟨I⟩ after n). */
  sub: React.RefObject<HTMLElement | null>;
  after: React.RefObject<HTMLSpanElement | null>;
}

function useLaneRefs(): LaneRefs {
  return {
    x: useRef(null),
    term: useRef(null),
    estimate: useRef(null),
    stderr: useRef(null),
    sub: useRef(null),
    after: useRef(null),
  };
}

function drawLane(r: LaneRefs, s: LaneState): void {
  writeReadout(r.x.current, s.n ? s.x : null, 6);
  writeReadout(r.term.current, s.n ? s.term : null, 6);
  writeReadout(r.estimate.current, s.n ? s.estimate : null, 7);
  writeReadout(r.stderr.current, s.n > 1 ? s.stderr : null, 3);
  // a spread that is rounding noise reads as what it is (the value itself stays in data-value)
  const el = r.stderr.current;
  if (el && s.zeroVariance && el.textContent !== ZERO_TEXT) el.textContent = ZERO_TEXT;
  const sub = String(s.n || 'i');
  if (r.sub.current && r.sub.current.textContent !== sub) r.sub.current.textContent = sub;
  const after = String(s.n);
  if (r.after.current && r.after.current.textContent !== after) r.after.current.textContent = after;
}

/** A lane's readouts: its newest sample and term, its estimate and ± s/√N (written per frame). */
function LaneReadouts({ id, r }: { id: string; r: LaneRefs }) {
  return (
    <div className="readouts mc-lane-readouts mc-half">
      <LiveReadout
        id={`race-${id}-x`}
        label={
          <>
            x<sub ref={r.sub} />
          </>
        }
        outRef={r.x}
      />
      <LiveReadout id={`race-${id}-term`} label="its term f/p" outRef={r.term} />
      <LiveReadout
        id={`race-${id}-estimate`}
        label={
          <>
            ⟨I⟩ after <span ref={r.after} />
          </>
        }
        outRef={r.estimate}
      />
      <LiveReadout id={`race-${id}-stderr`} label="± s/√N" outRef={r.stderr} />
    </div>
  );
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
  const s = Math.abs(I) || 1;

  // --- static parts (keyed on the track and the curve, not on t) ----------------------------
  const fig = useMemo(() => {
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
    const guide = `M${fmt(ex(1))},${fmt(ly(Math.max(sd, 10 ** e0)))}L${fmt(ex(track.max))},${fmt(ly(Math.max(sd / Math.sqrt(track.max), 10 ** e0)))}`;
    return { sx, sy, fPath, pPath, xt, yt, ex, ey, nt, et, ly, lt, floor: 10 ** e0, guide, R };
  }, [track, curve, a, b, I, s]);

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
      className="mc-svg-fig mc-tall-only"
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
        className="mc-svg-fig mc-tall-only"
        label={`The ${id} running estimate with its ± s/√N band, against N on a log axis`}
        description={words[id]}
        quiet
        testId={`race-estimate-${id}`}
      >
        <figcaption>⟨I⟩ against N, with its ± s/√N band</figcaption>
        <svg viewBox={`0 0 ${W} ${H}`} aria-hidden="true">
          <Axes xTicks={fig.nt} yTicks={fig.et} xLabel="N (samples)" yLabel="estimate" />
          <line x1={M.l} x2={M.l + PW} y1={ey(I)} y2={ey(I)} className="mc-svg-exact" />
          <path ref={setPath(`${k}Band`)} d={g[`${k}Band`]} style={{ fill: color }} className="mc-svg-band" />
          <path
            ref={setPath(`${k}Est`)}
            d={g[`${k}Est`]}
            style={{ stroke: color }}
            className={k === 'i' ? 'mc-svg-line mc-svg-dashed' : 'mc-svg-line'}
          />
        </svg>
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
            format={(n) => `${n} of ${RACE_MAX} samples`}
            testId="timeline"
          >
            <span className="mc-note" data-testid="race-rate">
              {formatNumber(rate, 4)} samples/s
            </span>
          </TimelineTransport>
        </Revealed>
        <div className={staged ? 'mc-race-grid stage-figure' : 'mc-race-grid'}>
          {staged
            ? [U.title, Im.title, U.readouts, Im.readouts, U.hist, fPlot, Im.hist, U.est, xPlot, Im.est]
            : [
                fPlot,
                xPlot,
                ...lanes.map((L) => (
                  <div key={L.id} className="mc-lane" style={{ borderTopColor: L.color }}>
                    {L.title}
                    {L.readouts}
                    {L.hist}
                    {L.est}
                  </div>
                )),
              ]}
        </div>
        <p className="mc-note mc-race-note">
          Solid blue: uniform; dashed orange: importance (its pdf dashed on f). Grey dashes: the exact I ={' '}
          {formatNumber(I, 8)}; the grey line: the N⁻½ trend σ/√N. Both estimators use the same random numbers
          ξᵢ (seeded): uniform puts xᵢ = a + (b − a)ξᵢ, importance xᵢ = P⁻¹(ξᵢ). Errors below{' '}
          {pow10Text(Math.round(Math.log10(fig.floor)))} sit on the bottom line.
        </p>
      </DescribedFigure>
    </div>
  );
});

/**
 * The growing curves (|error|, estimate, ± standard-error band of each lane) as polylines over the
 * sample counts `points` below t, plus the point at t itself: the segments at `points` are formatted
 * once; `at(t)` joins those below t, reusing the previous call's joined prefix when t grew.
 */
export function raceCurves(
  track: RaceTrack,
  points: readonly number[],
  fig: { ex: Scale; ey: Scale; ly: Scale; floor: number; R: number },
  I: number,
) {
  const { ex, ey, ly, floor, R } = fig;
  const clampY = (v: number) => Math.max(I - R, Math.min(I + R, v));
  const xy = (n: number, y: number) => `${fmt(ex(n))},${fmt(y)}`;
  type Seg = { err: string | null; est: string | null; up: string | null; dn: string | null };
  const seg = (s: LaneState): Seg => {
    const n = s.n;
    const est = clampY(s.estimate);
    const ok = Number.isFinite(s.stderr);
    return {
      err: Number.isFinite(s.absError) ? xy(n, ly(Math.max(s.absError, floor))) : null,
      est: Number.isFinite(est) ? xy(n, ey(est)) : null,
      up: ok ? xy(n, ey(clampY(s.estimate + s.stderr))) : null,
      dn: ok ? xy(n, ey(clampY(s.estimate - s.stderr))) : null,
    };
  };
  const segU = points.map((n) => seg(raceLaneAt(track.uniform, n, I)));
  const segI = points.map((n) => seg(raceLaneAt(track.importance, n, I)));
  /** A polyline's joined prefix over the first k points (forward, or reversed for a band's lower edge). */
  const prefix = (segs: Seg[], key: keyof Seg, reversed: boolean) => {
    let k = 0;
    let s = '';
    return (upTo: number) => {
      if (upTo < k) {
        k = 0;
        s = '';
      }
      for (; k < upTo; k++) {
        const g = segs[k][key];
        if (g) s = s ? (reversed ? `${g}L${s}` : `${s}L${g}`) : g;
      }
      return s;
    };
  };
  const lanes = ([segU, segI] as const).map((segs) => ({
    err: prefix(segs, 'err', false),
    est: prefix(segs, 'est', false),
    up: prefix(segs, 'up', false),
    dn: prefix(segs, 'dn', true),
  }));
  const join = (...parts: (string | null)[]) => parts.filter((p) => p).join('L');
  return {
    at(t: number): Pick<RaceGeom, 'uErr' | 'iErr' | 'uBand' | 'iBand' | 'uEst' | 'iEst'> {
      t = Math.max(0, Math.min(track.max, Math.floor(t)));
      // the points below t (points is increasing)
      let lo = 0;
      let hi = points.length;
      while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (points[mid] < t) lo = mid + 1;
        else hi = mid;
      }
      const k = lo;
      const out = [] as string[][];
      for (const [L, lane] of [
        [lanes[0], track.uniform],
        [lanes[1], track.importance],
      ] as const) {
        const tail: Seg = t >= 1 ? seg(raceLaneAt(lane, t, I)) : { err: null, est: null, up: null, dn: null };
        const err = join(L.err(k), tail.err);
        const est = join(L.est(k), tail.est);
        const up = join(L.up(k), tail.up);
        const dn = join(tail.dn, L.dn(k));
        out.push([err ? `M${err}` : '', est ? `M${est}` : '', up ? `M${up}L${dn}Z` : '']);
      }
      return {
        uErr: out[0][0],
        uEst: out[0][1],
        uBand: out[0][2],
        iErr: out[1][0],
        iEst: out[1][1],
        iBand: out[1][2],
      };
    },
  };
}

interface RaceGeom {
  uErr: string;
  iErr: string;
  uBand: string;
  iBand: string;
  uEst: string;
  iEst: string;
  /** Screen x of the latest samples, oldest first. */
  rugU: number[];
  rugI: number[];
  dotU: { x: number; y: number } | null;
  dotI: { x: number; y: number } | null;
}

const rugY = (row: number) => M.t + PH - 16 + row * 9;
/** Opacity steps of a rug (the latest RECENT samples, in age order). */
const RUG_BUCKETS = 4;

/** A rug's tick marks as RUG_BUCKETS paths, oldest first: sample j of the RECENT slots goes to bucket ⌊j·B/RECENT⌋. */
function rugPaths(xs: number[], y: number): string[] {
  const out: string[] = Array.from({ length: RUG_BUCKETS }, () => '');
  const off = RECENT - xs.length;
  for (let j = 0; j < xs.length; j++) {
    const b = Math.min(RUG_BUCKETS - 1, Math.floor(((j + off) * RUG_BUCKETS) / RECENT));
    out[b] += `M${fmt(xs[j])},${fmt(y)}v7`;
  }
  return out;
}

/** Moves a rug to the latest samples. */
function drawRug(g: Element | null, xs: number[], y: number): void {
  if (!g) return;
  const d = rugPaths(xs, y);
  const kids = g.children;
  for (let k = 0; k < kids.length && k < d.length; k++) kids[k].setAttribute('d', d[k]);
}

/** Moves a newest-sample marker (a dashed drop line and a dot). */
function drawDot(g: Element | null, d: { x: number; y: number } | null): void {
  if (!g) return;
  const el = g as SVGGElement;
  if (!d) {
    el.style.display = 'none';
    return;
  }
  if (el.style.display) el.style.display = '';
  const [line, dot] = g.children;
  const x = String(d.x);
  line?.setAttribute('x1', x);
  line?.setAttribute('x2', x);
  line?.setAttribute('y2', String(d.y));
  dot?.setAttribute('cx', x);
  dot?.setAttribute('cy', String(d.y));
}
