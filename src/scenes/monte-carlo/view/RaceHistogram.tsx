/**
 * One lane's histogram of every sample drawn so far, as a density (count / (t · bin width)) against
 * the lane's pdf p(x) drawn over it: uniform samples fill the bins evenly, importance samples crowd
 * where p (and f) is large. The bars follow the timeline frame by frame (one path's `d`, written
 * directly, like the rest of the race); the counts behind them are on the path as `data-counts`,
 * with `data-t`, the samples they count.
 */
import { useLayoutEffect, useMemo, useRef } from 'react';
import {
  DescribedFigure,
  formatNumber,
  ShowAsTable,
  TEXT_HZ,
  useTimelineFrame,
  type Timeline,
} from '../../../ui';
import { coordText, linearScale } from '../../../ui/chartScale';
import { binRange, countIn, raceBinIndex, raceCounts, RACE_BINS } from '../raceHistogram';
import { gridAt } from '../curves';
import { describeHistogram } from './describeRace';
import { Axes, M, path, PW } from './raceSvg';

/** Height of a histogram's viewBox (its width is the race's W). */
export const HIST_H = 150;
const PH = HIST_H - M.t - M.b;

export interface RaceHistogramProps {
  /** "uniform" or "importance": the test id (race-hist-…) and the words. */
  id: 'uniform' | 'importance';
  /** The lane's samples, in the order they are drawn. */
  xs: Float64Array;
  a: number;
  b: number;
  /** The lane's pdf on a grid over [a, b]. */
  px: ArrayLike<number>;
  py: ArrayLike<number>;
  /** e.g. "p(x) = 1/(b − a)". */
  pdfLabel: string;
  /** Top of the density axis (the same for both lanes, so their bars compare). */
  yMax: number;
  color: string;
  tl: Pick<Timeline, 'subscribe' | 'now'>;
  /** The position React renders (the paused t). */
  t: number;
  /** The half of [a, b] where the importance pdf is heavier: the description says how many fell there. */
  half: [number, number] | null;
  /** Classroom mode: a shorter caption. */
  staged: boolean;
}

/** The bars of a density histogram (bins of equal width over [a, b]) as one path, clipped at yMax. */
function barsPath(counts: Uint32Array, t: number, a: number, b: number, yMax: number): string {
  if (t < 1) return '';
  const bins = counts.length;
  const w = (b - a) / bins;
  const x = (k: number) => M.l + (PW * k) / bins;
  const y0 = M.t + PH;
  let d = '';
  for (let k = 0; k < bins; k++) {
    const c = counts[k];
    if (!c) continue;
    const dens = Math.min(yMax, c / (t * w));
    d += `M${coordText(x(k))},${y0}V${coordText(y0 - (PH * dens) / yMax)}H${coordText(x(k + 1))}V${y0}Z`;
  }
  return d;
}

/** The histogram's caption for the first `t` samples (classroom mode: the stage's shorter one). */
function captionOf(t: number, staged: boolean, pdfLabel: string): string {
  return staged
    ? `All ${t} samples against p(x)`
    : `Where all ${t === 1 ? 'the sample' : `${t} samples`} fell, against ${pdfLabel}`;
}

export function RaceHistogram({
  id,
  xs,
  a,
  b,
  px,
  py,
  pdfLabel,
  yMax,
  color,
  tl,
  t,
  half,
  staged,
}: RaceHistogramProps) {
  const index = useMemo(() => raceBinIndex(xs, a, b, RACE_BINS), [xs, a, b]);
  const counts = useRef(new Uint32Array(RACE_BINS));
  const bars = useRef<SVGPathElement>(null);
  const caption = useRef<HTMLElement>(null);
  const lastText = useRef(-Infinity);
  const axes = useMemo(() => {
    const sx = linearScale(a, b, M.l, M.l + PW);
    const sy = linearScale(0, yMax, M.t + PH, M.t);
    const xt: [number, string][] = [0, 0.5, 1].map((q) => [
      sx(a + q * (b - a)),
      formatNumber(a + q * (b - a), 3),
    ]);
    const yt: [number, string][] = [0, 0.5, 1].map((q) => [sy(q * yMax), formatNumber(q * yMax, 2)]);
    return { xt, yt, pPath: path(Array.from(px), Array.from(py), sx, sy) };
  }, [a, b, yMax, px, py]);

  const draw = (tt: number, playing: boolean) => {
    const el = bars.current;
    if (!el) return;
    const n = Math.max(0, Math.min(xs.length, Math.floor(tt)));
    writeCaption(n, playing);
    if (el.getAttribute('data-t') === String(n) && el.hasAttribute('d')) return;
    const c = raceCounts(index, n, RACE_BINS, counts.current);
    el.setAttribute('d', barsPath(c, n, a, b, yMax));
    el.setAttribute('data-counts', c.join(','));
    el.setAttribute('data-t', String(n));
  };
  // the caption counts the samples the bars show: while playing it follows them at most TEXT_HZ
  // times a second (its text node is React's, changed in place; React renders it on pause)
  const writeCaption = (n: number, playing: boolean) => {
    const node = caption.current?.firstChild;
    if (!node || node.nodeType !== 3) return;
    const now = performance.now();
    if (playing && now - lastText.current < 1000 / TEXT_HZ - 1) return;
    lastText.current = now;
    const text = captionOf(n, staged, pdfLabel);
    if (node.nodeValue !== text) node.nodeValue = text;
  };
  const drawRef = useRef(draw);
  drawRef.current = draw;
  useTimelineFrame(tl, (tt, playing) => drawRef.current(tt, playing));
  // after every render (a new track or position): the bars of the position now, rewritten
  useLayoutEffect(() => {
    bars.current?.removeAttribute('data-t');
    drawRef.current(tl.now(), false);
  });

  // the words and the table: the counts at the rendered position
  const data = useMemo(() => {
    const c = raceCounts(index, t, RACE_BINS);
    const description = describeHistogram({
      lane: id,
      pdf: pdfLabel,
      counts: c,
      t,
      a,
      b,
      half,
      inHalf: half ? countIn(xs, t, half[0], half[1]) : 0,
    });
    const w = (b - a) / RACE_BINS;
    const rows = Array.from(c, (n, k) => {
      const [lo, hi] = binRange(k, a, b, RACE_BINS);
      return [lo, hi, n, t > 0 ? n / (t * w) : NaN, gridAt(px, py, (lo + hi) / 2)];
    });
    return { description, rows };
  }, [index, t, id, pdfLabel, a, b, half, xs, px, py]);

  return (
    <>
      <DescribedFigure
        className="mc-svg-fig mc-hist"
        label={`Histogram of every ${id} sample drawn so far, against ${pdfLabel}`}
        description={data.description}
        quiet
        testId={`race-histogram-${id}`}
      >
        <figcaption ref={caption} data-testid={`race-hist-caption-${id}`}>
          {captionOf(t, staged, pdfLabel)}
        </figcaption>
        <svg viewBox={`0 0 360 ${HIST_H}`} aria-hidden="true">
          <Axes xTicks={axes.xt} yTicks={axes.yt} xLabel="x" yLabel="density" h={HIST_H} />
          <path
            ref={bars}
            className="mc-svg-bars"
            style={{ fill: color, stroke: color }}
            data-testid={`race-hist-${id}`}
          />
          <path d={axes.pPath} className="mc-svg-pdf" />
          <text x={M.l + PW - 4} y={M.t + 14} textAnchor="end" className="mc-svg-pdf-label">
            — p(x)
          </text>
        </svg>
      </DescribedFigure>
      <ShowAsTable
        caption={`Histogram of the ${t} ${id} samples drawn so far, ${RACE_BINS} bins, against ${pdfLabel}`}
        columns={['from x', 'to x', 'count', 'density', 'p(x) at the bin centre']}
        rows={data.rows}
        testId={`race-hist-table-${id}`}
      />
    </>
  );
}
