/**
 * The hemisphere figure in words: what a sighted student reads from it now (the density and its k,
 * how many samples of which point set, where the morph is, where the samples bunch, the χ² test,
 * the followed stratum), as plain sentences with the live numbers. Pure: the figure's accessible
 * description and the stratum panel's text are built here and unit-tested.
 */
import { formatCount, formatSignificant } from '../../../ui/format';
import { HALF_PI, TWO_PI } from '../../../core/sampling';
import type { SequenceKind } from '../../../core/random';
import type { AnimKind, Lobe } from '../model';
import { CELLS, cellBounds, type Cell, type CellImage } from '../stratum';

const num = (x: number, digits = 3) => (Number.isFinite(x) ? formatSignificant(x, digits, 'times') : '—');

/** Where a marginal density puts its mass: its peak, its median and whether it is flat. */
export interface MarginalShape {
  peak: number;
  median: number;
  flat: boolean;
  lo: number;
  hi: number;
}

/** The shape of a density f on [lo, hi] from a fine grid (trapezoids for the median). */
export function marginalShape(f: (x: number) => number, lo: number, hi: number, m = 400): MarginalShape {
  const xs = new Float64Array(m + 1);
  const ys = new Float64Array(m + 1);
  let peak = lo;
  let yMax = -Infinity;
  let yMin = Infinity;
  for (let k = 0; k <= m; k++) {
    // the end of a half-open support (φ < 2π) is read just inside it
    const x = k === m ? hi - (hi - lo) * 1e-12 : lo + ((hi - lo) * k) / m;
    const y = Math.max(0, f(x));
    xs[k] = x;
    ys[k] = Number.isFinite(y) ? y : 0;
    if (ys[k] > yMax * (1 + 1e-9)) {
      yMax = ys[k];
      peak = x;
    }
    if (k > 0 && k < m) yMin = Math.min(yMin, ys[k]);
  }
  let total = 0;
  for (let k = 0; k < m; k++) total += 0.5 * (ys[k] + ys[k + 1]) * (xs[k + 1] - xs[k]);
  let acc = 0;
  let median = (lo + hi) / 2;
  for (let k = 0; k < m; k++) {
    const piece = 0.5 * (ys[k] + ys[k + 1]) * (xs[k + 1] - xs[k]);
    if (total > 0 && acc + piece >= total / 2) {
      const f0 = piece > 0 ? (total / 2 - acc) / piece : 0;
      median = xs[k] + f0 * (xs[k + 1] - xs[k]);
      break;
    }
    acc += piece;
  }
  return { peak, median, flat: yMax <= yMin * 1.001, lo, hi };
}

/** "around θ = 0.785 rad", "towards the pole", … for one marginal. */
function shapeText(s: MarginalShape, v: 'θ' | 'φ', lowEnd: string, highEnd: string): string {
  if (s.flat) return `evenly in ${v}`;
  const span = s.hi - s.lo;
  const where =
    s.peak <= s.lo + span * 0.01
      ? lowEnd
      : s.peak >= s.hi - span * 0.01
        ? highEnd
        : `around ${v} = ${num(s.peak)} rad`;
  return `${where} (median ${v} = ${num(s.median)} rad)`;
}

/** Where the samples of a lobe bunch up, from its marginals: "around θ = 0.785 rad (…) and towards φ = 2π (…)". */
export function whereTheyBunch(lobe: Lobe): string {
  const th = marginalShape(lobe.thetaPdf, 0, HALF_PI);
  const ph = marginalShape(lobe.phiPdf, 0, TWO_PI);
  return `${shapeText(th, 'θ', 'towards the pole (θ = 0)', 'towards the rim (θ = π/2)')} and ${shapeText(
    ph,
    'φ',
    'towards φ = 0',
    'towards φ = 2π',
  )}`;
}

/** The followed stratum in words: where it is in the square, the patch it lands on, its samples. */
export function describeStratum(
  cell: Cell | null,
  image: CellImage | null,
  count: number | null,
  n: number,
  ask = false,
): string {
  if (!cell) return 'No stratum followed.';
  const { xi1, xi2 } = cellBounds(cell);
  const head = `Stratum (${cell.i}, ${cell.j}): ξ₁ from ${xi1[0]} to ${xi1[1]}, ξ₂ from ${xi2[0]} to ${xi2[1]}, 1/${CELLS * CELLS} of the square.`;
  if (ask) return `${head} Where it lands is hidden until you reveal.`;
  if (!image) return `${head} There is no density to carry it onto the hemisphere.`;
  const theta = image.pole
    ? `from the pole to θ = ${num(image.theta[1])} rad`
    : `θ ${num(image.theta[0])} to ${num(image.theta[1])} rad`;
  const phi = image.pole
    ? ''
    : `, φ ${num(image.phi[0])} to ${num(image.phi[1])} rad${image.phiWraps ? ' (across φ = 0)' : ''}`;
  const about = image.approximate ? 'about ' : '';
  const ratio = image.densityRatio;
  const dense =
    Math.abs(ratio - 1) < 0.005
      ? 'as dense as uniform sampling'
      : ratio > 1
        ? `${num(ratio)} times as dense as uniform sampling`
        : `${num(1 / ratio)} times sparser than uniform sampling`;
  const samples =
    count === null
      ? ' Counting its samples…'
      : ` ${formatCount(count)} of the ${formatCount(n)} samples lie in it (expected ${num(n / (CELLS * CELLS), 4)}).`;
  return `${head} It lands on ${theta}${phi}: a patch of ${about}${num(image.solidAngle)} sr, ${num(
    100 * image.share,
  )} % of the hemisphere, holding 1/${CELLS * CELLS} of the probability, so the samples there are ${dense}.${samples}`;
}

export interface HemisphereState {
  /** The sampled lobe (null: nothing sampled). */
  lobe: Lobe | null;
  /** Why nothing is sampled (when lobe is null). */
  noLobe: string;
  kind: SequenceKind;
  n: number;
  anim: AnimKind;
  t: number;
  /** Morph fraction s at t (warp) and points drawn at t (growth). */
  s: number;
  shown: number;
  /** χ² of the current draw (null while computing or without samples). */
  chi2: { pValue: number; pass: boolean; alpha: number } | null;
  /** The stratum sentence (describeStratum), or '' when none is followed. */
  stratum: string;
  /** Results hidden until the student reveals them. */
  ask: boolean;
}

const KIND_TEXT: Record<SequenceKind, string> = {
  independent: 'independent',
  stratified: 'stratified',
  halton: 'Halton',
  sobol: 'Sobol',
};

/** The figure's description: density, samples, the animation's position, where they bunch, χ², the stratum. */
export function describeHemisphere(st: HemisphereState): string {
  if (!st.lobe) return `No samples: ${st.noLobe}`;
  const lobe = st.lobe;
  const parts: string[] = [];
  parts.push(
    `Density p(ω) = ${lobe.label}, k = ${num(lobe.k, 4)}; ${formatCount(st.n)} ${KIND_TEXT[st.kind]} samples (ξ₁, ξ₂).`,
  );
  if (st.anim === 'warp') {
    const where =
      st.s <= 0
        ? 'all points lie in the unit square on the base plane'
        : st.s >= 1
          ? 'every point sits on its direction on the hemisphere'
          : `the points are ${num(100 * st.s, 2)} % of the way from the square to their directions`;
    parts.push(`Warp morph at t = ${st.t.toFixed(2)} (s = ${st.s.toFixed(2)}): ${where}.`);
  } else {
    parts.push(
      `Samples appearing at t = ${st.t.toFixed(2)}: ${formatCount(st.shown)} of ${formatCount(st.n)} drawn.`,
    );
  }
  if (st.ask) {
    parts.push('The samples on the hemisphere and the histograms are hidden until you reveal them.');
  } else {
    parts.push(`On the hemisphere the samples bunch ${whereTheyBunch(lobe)}.`);
    if (st.chi2) {
      parts.push(
        `χ² test: p = ${num(st.chi2.pValue, 3)}, ${st.chi2.pass ? 'consistent with p(ω)' : `rejected at α = ${st.chi2.alpha}`}.`,
      );
    }
  }
  if (st.stratum) parts.push(st.stratum);
  return parts.join(' ');
}
