/**
 * The hemisphere figure in words: what a sighted student reads from it now (the density and its k,
 * how many samples of which point set, where the morph is, where the samples bunch, the χ² test,
 * the followed stratum), as plain sentences with the live numbers. Pure: the figure's accessible
 * description and the stratum panel's text are built here and unit-tested.
 */
import { formatCount, formatSignificant } from '../../../ui/format';
import { summarizeSeries } from '../../../ui/summary';
import { HALF_PI, TWO_PI } from '../../../core/sampling';
import type { SequenceKind } from '../../../core/random';
import type { AnimKind } from '../animation';
import type { Lobe } from '../lobe';
import { CELLS, cellBounds, type Cell, type CellImage } from '../stratum';
import { marginalShape, type MarginalShape } from '../marginals';

const num = (x: number, digits = 3) => (Number.isFinite(x) ? formatSignificant(x, digits, 'times') : '—');

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

const bunchText = new WeakMap<Lobe, string>();

/**
 * Where the samples of a lobe bunch up, from its marginals: "around θ = 0.785 rad (…) and towards
 * φ = 2π (…)". Kept per lobe: the figure's description asks again at every change of seed or t.
 */
export function whereTheyBunch(lobe: Lobe): string {
  let text = bunchText.get(lobe);
  if (text === undefined) bunchText.set(lobe, (text = bunchOf(lobe)));
  return text;
}

function bunchOf(lobe: Lobe): string {
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

/** The unit square's points in words: how many, and how evenly the 64 cells share them. */
export function describeSquare(
  counts: ArrayLike<number>,
  shown: number,
  n: number,
  kind: SequenceKind,
): string {
  let lo = Infinity;
  let hi = -Infinity;
  for (let k = 0; k < counts.length; k++) {
    lo = Math.min(lo, counts[k]);
    hi = Math.max(hi, counts[k]);
  }
  const of = shown < n ? ` (the first of ${formatCount(n)})` : '';
  return `${formatCount(shown)} ${KIND_TEXT[kind]} points (ξ₁, ξ₂) in the unit square${of}; each of its ${counts.length} cells holds from ${formatCount(lo)} to ${formatCount(hi)} of them (${num(shown / counts.length, 4)} expected).`;
}

/** A marginal histogram against its density, in words: both series summarized and where they differ most. */
export function describeMarginal(
  h: {
    centers: ArrayLike<number>;
    density: ArrayLike<number>;
    curveX: ArrayLike<number>;
    curveY: ArrayLike<number>;
  },
  v: 'θ' | 'φ',
  n: number,
  density: (x: number) => number,
): string {
  // a density that is zero to rounding at an end (sin 2θ at π/2) reads as 0
  const opts = { xLabel: v, format: (x: number) => (Math.abs(x) < 1e-9 ? '0' : num(x)) };
  let gap = 0;
  let at = 0;
  for (let b = 0; b < h.centers.length; b++) {
    const d = Math.abs(h.density[b] - density(h.centers[b]));
    if (d > gap) {
      gap = d;
      at = h.centers[b];
    }
  }
  return [
    `Histogram of ${formatCount(n)} sampled ${v} (rad) in ${h.centers.length} bins against the density p(${v}).`,
    summarizeSeries(h.centers, h.density, { ...opts, yLabel: 'the histogram' }),
    summarizeSeries(h.curveX, h.curveY, { ...opts, yLabel: `p(${v})` }),
    `They differ most at ${v} = ${num(at)} rad, by ${num(gap)}.`,
  ].join(' ');
}

/** The centre of χ² bin k (cos θ, φ) and its standardized difference (O − E)/√E (0 where E = 0). */
export function chi2Bin(
  c: { observed: ArrayLike<number>; expected: ArrayLike<number>; cosThetaBins: number; phiBins: number },
  k: number,
): { cosTheta: number; phi: number; o: number; e: number; z: number } {
  const i = Math.floor(k / c.phiBins);
  const j = k % c.phiBins;
  const o = c.observed[k];
  const e = c.expected[k];
  return {
    cosTheta: (i + 0.5) / c.cosThetaBins,
    phi: ((j + 0.5) * TWO_PI) / c.phiBins,
    o,
    e,
    z: e > 0 ? (o - e) / Math.sqrt(e) : 0,
  };
}

/** The χ² bins in words: counts observed and expected, and the bin where they differ most. */
export function describeChi2Bins(c: Parameters<typeof chi2Bin>[0]): string {
  const m = c.cosThetaBins * c.phiBins;
  let oLo = Infinity,
    oHi = -Infinity,
    eLo = Infinity,
    eHi = -Infinity,
    worst = 0;
  for (let k = 0; k < m; k++) {
    const b = chi2Bin(c, k);
    oLo = Math.min(oLo, b.o);
    oHi = Math.max(oHi, b.o);
    eLo = Math.min(eLo, b.e);
    eHi = Math.max(eHi, b.e);
    if (Math.abs(b.z) > Math.abs(chi2Bin(c, worst).z)) worst = k;
  }
  const w = chi2Bin(c, worst);
  return (
    `${m} bins of equal solid angle, ${c.cosThetaBins} in cos θ by ${c.phiBins} in φ: observed counts from ` +
    `${formatCount(oLo)} to ${formatCount(oHi)}, expected from ${num(eLo)} to ${num(eHi)}. The largest ` +
    `standardized difference (O − E)/√E is ${num(w.z).replace(/^-/, '−')}, at cos θ = ${num(w.cosTheta)}, ` +
    `φ = ${num(w.phi)} rad (${formatCount(w.o)} observed, ${num(w.e)} expected).`
  );
}
