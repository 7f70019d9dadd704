/**
 * The hemisphere scene's model: pure functions of the parameters (and of compiled user
 * expressions), calling the core. No DOM, React, three or Plotly here; the worker and the views
 * both use these functions, so the numbers on screen are the ones the tests check.
 */
import {
  EXAM_E2PI_M1,
  TabulatedHemisphere,
  cosineHemispherePdf,
  examLobeK,
  examLobePdf,
  examPhiCdf,
  examPhiPdf,
  examThetaCdf,
  examThetaPdf,
  invertedJacobianPartialIntegral,
  phongLobePdf,
  phongThetaPdf,
  sampleCosineHemisphere,
  sampleCosineHemisphereBatch,
  sampleExamLobe,
  sampleExamLobeBatch,
  samplePhongLobe,
  samplePhongLobeBatch,
  sampleUniformHemisphere,
  sampleUniformHemisphereBatch,
  HALF_PI,
  TWO_PI,
  sphericalPhi,
  sphericalTheta,
  tabulateHemisphereDensity,
  uniformHemispherePdf,
  type TabulateResult,
} from '../../core/sampling';
import { fillSequence2D, runSeed, type SequenceKind } from '../../core/random';
import { hemisphereChi2, adaptiveIntegrate2D, type HemisphereChi2Result } from '../../core/verify';
import { estimateFromTerms, type McEstimate } from '../../core/estimators';
import { superscript } from '../../ui/axis';
import type { LobeId } from './params';

/** A sampling density on the hemisphere, as the scene uses it: sampler, pdf and marginals. */
export interface Lobe {
  id: LobeId;
  /** Short name for legends. */
  label: string;
  /** Normalization constant of p(ω) as the derivation defines it (k of k·(shape)). */
  k: number;
  /** Batched sampler: (ξ₁, ξ₂) pairs in u → unit vectors in out, i ∈ [start, n). */
  sampleBatch: (u: Float64Array, out: Float64Array, n: number, start?: number) => void;
  /** One sample (for the warped grid). */
  sample: (u1: number, u2: number, out: Float64Array | number[], o?: number) => void;
  /** Density per steradian (0 outside the hemisphere). */
  pdf: (x: number, y: number, z: number) => number;
  /** Marginal density of θ (per unit θ). */
  thetaPdf: (theta: number) => number;
  /** Marginal density of φ (per unit φ). */
  phiPdf: (phi: number) => number;
  /** True when p(θ, φ) = p(θ) p(φ). */
  separable: boolean;
}

/**
 * The lobe the parameters ask for — the one builder the page, the worker and the tests share.
 * Built-in ids directly; 'custom' by tabulating the typed density (`density`, null while it does
 * not compile), with the tabulation's verdict in `tab` (null when nothing was tabulated).
 */
export function lobeFromParams(
  id: LobeId,
  exponent: number,
  density?: Integrand | null,
): { lobe: Lobe | null; tab: TabulateResult | null } {
  if (id !== 'custom') return { lobe: makeLobe(id, exponent), tab: null };
  if (!density) return { lobe: null, tab: null };
  const tab = tabulateHemisphereDensity(density);
  return { lobe: tab.ok ? makeLobe('custom', exponent, tab.lobe) : null, tab };
}

/** A built-in lobe for the exponent n (only Phong reads it): every column is a core function. */
type LobeRow = (n: number) => Omit<Lobe, 'id'>;

/**
 * The built-in lobes as a table. Every sampler takes (u1, u2, …params, out, o) and every pdf the
 * direction (x, y, z), so the rows name core functions directly; only Phong binds its exponent.
 */
const LOBES: { readonly [K in Exclude<LobeId, 'custom'>]: LobeRow } = {
  exam: () => ({
    label: 'k cos θ eᵠ',
    k: examLobeK(),
    separable: true,
    sampleBatch: sampleExamLobeBatch,
    sample: sampleExamLobe,
    pdf: examLobePdf,
    thetaPdf: examThetaPdf,
    phiPdf: examPhiPdf,
  }),
  uniform: () => ({
    label: 'uniform 1/(2π)',
    k: 1 / TWO_PI,
    separable: true,
    sampleBatch: sampleUniformHemisphereBatch,
    sample: sampleUniformHemisphere,
    pdf: uniformHemispherePdf,
    thetaPdf: (t) => phongThetaPdf(t, 0),
    phiPdf: uniformPhiPdf,
  }),
  cosine: () => ({
    label: 'cos θ / π',
    k: 1 / Math.PI,
    separable: true,
    sampleBatch: sampleCosineHemisphereBatch,
    sample: sampleCosineHemisphere,
    pdf: cosineHemispherePdf,
    thetaPdf: (t) => phongThetaPdf(t, 1),
    phiPdf: uniformPhiPdf,
  }),
  phong: (n) => ({
    label: `(n+1)/(2π) cos${superscript(String(n))} θ`,
    k: (n + 1) / TWO_PI,
    separable: true,
    sampleBatch: (u, out, count, start) => samplePhongLobeBatch(u, n, out, count, start),
    sample: (a, b, out, o) => samplePhongLobe(a, b, n, out, o),
    pdf: (x, y, z) => phongLobePdf(x, y, z, n),
    thetaPdf: (t) => phongThetaPdf(t, n),
    phiPdf: uniformPhiPdf,
  }),
};

/** The lobe of the given id. `exponent` is used by Phong; `custom` needs its tabulated density. */
export function makeLobe(id: LobeId, exponent: number, custom?: TabulatedHemisphere | null): Lobe | null {
  if (id !== 'custom') return { id, ...LOBES[id](exponent) };
  if (!custom) return null;
  return {
    id,
    label: 'typed p(θ, φ), tabulated',
    k: custom.k,
    sampleBatch: (u, out, n, start) => custom.sampleBatch(u, out, n, start),
    sample: (a, b, out, o) => custom.sample(a, b, out, o),
    pdf: (x, y, z) => custom.pdf(x, y, z),
    thetaPdf: (t) => custom.thetaPdf(t),
    phiPdf: (p) => custom.phiPdf(p),
    separable: false,
  };
}

function uniformPhiPdf(phi: number): number {
  return phi >= 0 && phi < TWO_PI ? 1 / TWO_PI : 0;
}

/** The n points (ξ₁, ξ₂) of the chosen set, interleaved, into `out` (length ≥ 2n). */
export function drawUniforms(
  kind: SequenceKind,
  seed: number,
  n: number,
  out = new Float64Array(2 * n),
): Float64Array {
  return fillSequence2D(kind, seed, n, out);
}

/** Directions of the lobe for the n points of the set: 3n numbers. */
export function drawDirections(
  lobe: Lobe,
  kind: SequenceKind,
  seed: number,
  n: number,
): { u: Float64Array; dirs: Float64Array } {
  const u = drawUniforms(kind, seed, n);
  const dirs = new Float64Array(3 * n);
  lobe.sampleBatch(u, dirs, n);
  return { u, dirs };
}

/** A histogram normalized as a density (counts/(N·Δ)), with bin centres, beside the model density. */
export interface DensityHistogram {
  centers: Float64Array;
  density: Float64Array;
  /** Model density evaluated on a fine grid (for the curve). */
  curveX: Float64Array;
  curveY: Float64Array;
  width: number;
}

/** Histograms of θ over [0, π/2] and of φ over [0, 2π) against the lobe's marginals. */
export function marginalHistograms(
  lobe: Lobe,
  dirs: Float64Array,
  n: number,
  bins = 36,
): { theta: DensityHistogram; phi: DensityHistogram } {
  const ct = new Float64Array(bins);
  const cp = new Float64Array(bins);
  const wt = HALF_PI / bins;
  const wp = TWO_PI / bins;
  for (let i = 0; i < n; i++) {
    const x = dirs[3 * i];
    const y = dirs[3 * i + 1];
    const z = dirs[3 * i + 2];
    const t = sphericalTheta(x, y, z);
    const p = sphericalPhi(x, y);
    if (t >= 0 && t <= HALF_PI) ct[Math.min(bins - 1, Math.floor(t / wt))]++;
    if (p >= 0 && p < TWO_PI) cp[Math.min(bins - 1, Math.floor(p / wp))]++;
  }
  const make = (
    counts: Float64Array,
    w: number,
    lo: number,
    hi: number,
    f: (x: number) => number,
  ): DensityHistogram => {
    const centers = new Float64Array(bins);
    const density = new Float64Array(bins);
    for (let b = 0; b < bins; b++) {
      centers[b] = lo + (b + 0.5) * w;
      density[b] = n > 0 ? counts[b] / (n * w) : 0;
    }
    const m = 200;
    const curveX = new Float64Array(m + 1);
    const curveY = new Float64Array(m + 1);
    for (let j = 0; j <= m; j++) {
      const x = lo + ((hi - lo) * j) / m;
      curveX[j] = x;
      const xe = j === m ? hi * (1 - 1e-12) : x; // the half-open support of φ
      curveY[j] = f(xe);
    }
    return { centers, density, curveX, curveY, width: w };
  };
  return { theta: make(ct, wt, 0, HALF_PI, lobe.thetaPdf), phi: make(cp, wp, 0, TWO_PI, lobe.phiPdf) };
}

/** χ² test of the drawn directions against the lobe's pdf (core/verify, as in the unit tests). */
export function chi2OfDirections(lobe: Lobe, dirs: Float64Array, n: number): HemisphereChi2Result {
  const custom = lobe.id === 'custom';
  // bins of the typed lobe align with its 64 × 128 table (8 × 8 cells per bin), so the quadrature
  // of a piecewise-constant pdf stays cheap and exact
  return hemisphereChi2(
    dirs,
    n,
    lobe.pdf,
    custom ? { cosThetaBins: 8, phiBins: 16 } : { cosThetaBins: 10, phiBins: 20 },
  );
}

/** An integrand of (θ, φ) (compiled user expression). */
export type Integrand = (theta: number, phi: number) => number;

/**
 * ∫ f dω over the upper hemisphere = ∫₀^{2π} ∫₀^{π/2} f(θ, φ) sin θ dθ dφ, by adaptive
 * Gauss–Legendre quadrature (core/verify). NaN when f is not finite somewhere it is evaluated.
 */
export function exactIntegral(f: Integrand): number {
  return checkedIntegral(f).value;
}

/** ∫ f dω, or NaN with the reason it has no value. */
export interface CheckedIntegral {
  value: number;
  /** Why there is no value (f not finite somewhere, the quadrature does not converge); null if fine. */
  problem: string | null;
  /** The quadrature's own error estimate (summed over its final cells). */
  error: number;
  /** Set when the value is usable but less accurate than the readout's digits. */
  note?: string;
}

/** Relative error above which the quadrature's value is not trusted (a divergent or unresolved integral). */
const UNRESOLVED_REL = 1e-6;
/** An unresolved error must shrink at least this much per level of refinement to count as converging. */
const SHRINK_RATIO = 0.75;
/** Relative error above which the value is not shown at all. */
const UNTRUSTED_REL = 1e-2;

function deg(x: number): string {
  return `${(x * (180 / Math.PI)).toFixed(1)}°`;
}

/** A point (θ, φ) of a 64 × 128 grid (cell centres and edges) where f is not finite, or null. */
export function findNonFinite(f: Integrand): { theta: number; phi: number } | null {
  for (let i = 0; i <= 128; i++) {
    const t = (i / 128) * HALF_PI;
    for (let j = 0; j < 256; j++) {
      const p = (j / 256) * TWO_PI;
      if (!Number.isFinite(f(t, p))) return { theta: t, phi: p };
    }
  }
  return null;
}

/**
 * ∫ f dω with a verdict, like the monte-carlo scene's: NaN and a reason when f is not finite
 * somewhere on the hemisphere, or when the adaptive quadrature's error does not shrink (at its
 * depth limit a divergent integral, e.g. tan θ or 1/cos θ at the horizon, θ⁻² at the pole, or
 * 1/(θ − 0.5) inside, keeps an error of the order of the integral itself).
 */
export function checkedIntegral(f: Integrand): CheckedIntegral {
  const report = { error: NaN, resolved: false };
  const v = adaptiveIntegrate2D((t, p) => f(t, p) * Math.sin(t), 0, HALF_PI, 0, TWO_PI, {
    relTol: 1e-12,
    maxDepth: 6,
    report,
  });
  if (!Number.isFinite(v)) {
    const at = findNonFinite(f);
    return {
      value: NaN,
      error: Infinity,
      problem: at
        ? `f is not finite (NaN or ±∞) at θ = ${deg(at.theta)}, φ = ${deg(at.phi)}, so ∫ f dω has no value`
        : 'f is not finite (NaN or ±∞) somewhere on the hemisphere, so ∫ f dω has no value',
    };
  }
  if (!(report.error <= UNRESOLVED_REL * Math.abs(v) + 1e-12)) {
    // Not resolved to the tolerance: an integrable singularity's error still shrinks with depth
    // (by 2^-1/2 per bisection for 1/√cos θ), a divergent one's does not (ln 2 · coefficient per
    // bisection for a 1/x blow-up). Compare one level shallower.
    const coarse = { error: NaN, resolved: false };
    adaptiveIntegrate2D((t, p) => f(t, p) * Math.sin(t), 0, HALF_PI, 0, TWO_PI, {
      relTol: 1e-12,
      maxDepth: 5,
      report: coarse,
    });
    if (!(report.error < SHRINK_RATIO * coarse.error) || !(report.error <= UNTRUSTED_REL * Math.abs(v)))
      return {
        value: NaN,
        error: report.error,
        problem: `the quadrature does not converge (its error estimate stays at ${report.error.toPrecision(2)} while refining): ∫ f dω diverges, or f has a singularity too strong to resolve`,
      };
    return {
      value: v,
      error: report.error,
      problem: null,
      note: `accurate to about ±${report.error.toPrecision(2)} only (f has a singularity the quadrature resolves slowly)`,
    };
  }
  return { value: v, error: report.error, problem: null };
}

/** The two Q2 estimators on the same point set: uniform (2π/N) Σ f and importance (1/N) Σ f/p. */
export interface Q2Estimates {
  uniform: McEstimate;
  importance: McEstimate;
  /** Samples (of both point sets) where f itself is NaN or ±∞: the estimators have no value then. */
  fNonFinite: number;
  /** Importance samples where p = 0 (or is not finite) although f ≠ 0. */
  pZero: number;
}

/**
 * Q2 estimates from n points u (ξ pairs): the uniform estimator warps them with the uniform
 * hemisphere map, the importance estimator with the lobe (its directions `dirs`).
 * Terms: Yᵢ = 2π f(Xᵢ) and Yᵢ = f(Xᵢ)/p(Xᵢ) (0 when f = 0; invalid when p = 0 and f ≠ 0).
 */
export function q2Estimates(
  lobe: Lobe | null,
  f: Integrand,
  u: Float64Array,
  dirs: Float64Array | null,
  n: number,
  scratch?: { uni: Float64Array; terms: Float64Array },
): Q2Estimates {
  const uni = scratch?.uni ?? new Float64Array(3 * n);
  const terms = scratch?.terms ?? new Float64Array(n);
  sampleUniformHemisphereBatch(u, uni, n);
  let fNonFinite = 0;
  let pZero = 0;
  for (let i = 0; i < n; i++) {
    const x = uni[3 * i];
    const y = uni[3 * i + 1];
    const z = uni[3 * i + 2];
    const fv = f(sphericalTheta(x, y, z), sphericalPhi(x, y));
    if (!Number.isFinite(fv)) fNonFinite++;
    terms[i] = TWO_PI * fv;
  }
  const uniform = estimateFromTerms(terms, 0, n);
  let importance: McEstimate = { n: 0, estimate: NaN, variance: NaN, stderr: NaN, invalid: 0 };
  if (lobe && dirs) {
    for (let i = 0; i < n; i++) {
      const x = dirs[3 * i];
      const y = dirs[3 * i + 1];
      const z = dirs[3 * i + 2];
      const fv = f(sphericalTheta(x, y, z), sphericalPhi(x, y));
      const p = lobe.pdf(x, y, z);
      if (!Number.isFinite(fv)) fNonFinite++;
      else if (fv !== 0 && !(p > 0 && Number.isFinite(p))) pZero++;
      terms[i] = fv === 0 ? 0 : p > 0 && Number.isFinite(p) && Number.isFinite(fv) ? fv / p : NaN;
    }
    importance = estimateFromTerms(terms, 0, n);
  }
  return { uniform, importance, fNonFinite, pZero };
}

/**
 * "Repeat many times": `runs` independent estimates with `perRun` samples each (point set of
 * kind `kind`, seeds derived from `seed`), for the histogram of estimates (Q2(c): unbiasedness).
 */
export function repeatEstimates(
  lobe: Lobe | null,
  f: Integrand,
  kind: SequenceKind,
  seed: number,
  runs: number,
  perRun: number,
  onProgress?: (fraction: number) => void,
): { uniform: Float64Array; importance: Float64Array } {
  const uniform = new Float64Array(runs);
  const importance = new Float64Array(runs);
  const u = new Float64Array(2 * perRun);
  const dirs = new Float64Array(3 * perRun);
  const scratch = { uni: new Float64Array(3 * perRun), terms: new Float64Array(perRun) };
  for (let r = 0; r < runs; r++) {
    fillSequence2D(kind, runSeed(seed, r), perRun, u);
    if (lobe) lobe.sampleBatch(u, dirs, perRun);
    const e = q2Estimates(lobe, f, u, lobe ? dirs : null, perRun, scratch);
    uniform[r] = e.uniform.estimate;
    importance[r] = e.importance.estimate;
    if (onProgress && (r & 63) === 63) onProgress((r + 1) / runs);
  }
  return { uniform, importance };
}

/** Everything the scene shows about one draw of n samples (computed in the worker for big n). */
export interface DrawStats {
  n: number;
  chi2: HemisphereChi2Result | null;
  hist: { theta: DensityHistogram; phi: DensityHistogram } | null;
  exact: number;
  /** Why ∫ f dω has no value (see {@link checkedIntegral}); null when it has one. */
  exactProblem: string | null;
  /** Set when the value is less accurate than its digits. */
  exactNote?: string;
  q2: Q2Estimates;
  /** Variances of one term of each estimator, by quadrature (null without a lobe, f or a finite ∫ f). */
  variance: VarianceCheck | null;
  /** For stratified / Halton / Sobol points: the RMSE over randomized runs (s/√N does not apply). */
  rmse: RmseResult | null;
}

/** Draw n samples of the lobe from the point set and compute all statistics the scene shows. */
export function computeDrawStats(
  lobe: Lobe | null,
  f: Integrand | null,
  kind: SequenceKind,
  seed: number,
  n: number,
): DrawStats {
  const u = drawUniforms(kind, seed, n);
  let dirs: Float64Array | null = null;
  if (lobe) {
    dirs = new Float64Array(3 * n);
    lobe.sampleBatch(u, dirs, n);
  }
  const nan: McEstimate = { n: 0, estimate: NaN, variance: NaN, stderr: NaN, invalid: 0 };
  const exact = f ? checkedIntegral(f) : null;
  const ev = exact ? exact.value : NaN;
  const haveExact = !!f && Number.isFinite(ev);
  return {
    n,
    chi2: lobe && dirs ? chi2OfDirections(lobe, dirs, n) : null,
    hist: lobe && dirs ? marginalHistograms(lobe, dirs, n) : null,
    exact: ev,
    exactProblem: exact ? exact.problem : null,
    ...(exact?.note ? { exactNote: exact.note } : {}),
    q2: f ? q2Estimates(lobe, f, u, dirs, n) : { uniform: nan, importance: nan, fNonFinite: 0, pZero: 0 },
    variance: lobe && f && haveExact ? varianceCheck(lobe, f, ev) : null,
    rmse: f && haveExact && kind !== 'independent' ? rmseOverRuns(lobe, f, kind, seed, n, ev) : null,
  };
}

/** The key's inverted-Jacobian variant: the partial θ-integral ∫_ε^{π/2} cot θ dθ for shrinking ε. */
export function invertedJacobianSeries(points = 40): { eps: Float64Array; partial: Float64Array } {
  const eps = new Float64Array(points);
  const partial = new Float64Array(points);
  for (let i = 0; i < points; i++) {
    const e = 10 ** (-(i * 15) / (points - 1)); // 1 … 1e-15
    eps[i] = e;
    partial[i] = invertedJacobianPartialIntegral(e);
  }
  return { eps, partial };
}

// ---- the animation: a pure function of (params, seed, t) ---------------------------------------

/** Which animation the shared timeline plays: the warp morph (square → hemisphere) or the growth. */
export type AnimKind = 'warp' | 'grow';

/** Seconds from t = 0 to t = 1 at 1× speed. Growth keeps its old pace: 0.7 s per decade of N. */
export function animDuration(anim: AnimKind, n: number): number {
  return anim === 'warp' ? 4 : Math.max(1.5, 0.7 * Math.log10(Math.max(10, n)));
}

/** Growth: how many of the n samples are on screen at position t ∈ [0, 1] (geometric, 0 at t = 0, n at t = 1). */
export function growCount(n: number, t: number): number {
  if (!(t > 0) || n <= 0) return 0;
  if (t >= 1) return n;
  return Math.min(n, Math.max(1, Math.round(Math.pow(n, t))));
}

/** Warp morph: the eased fraction s(t) = t²(3 − 2t) of the way from the square to the hemisphere. */
export function morphFraction(t: number): number {
  const c = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0));
  return c * c * (3 - 2 * c);
}

/**
 * Where the point (ξ₁, ξ₂) sits in the unit square as drawn in 3D: the square [−1, 1]² in the base
 * plane z = 0, ξ₁ along +x and ξ₂ along +y (so it frames the hemisphere's base disk).
 */
export function squarePoint(
  xi1: number,
  xi2: number,
  out: number[] | Float64Array = [0, 0, 0],
  o = 0,
): number[] | Float64Array {
  out[o] = 2 * xi1 - 1;
  out[o + 1] = 2 * xi2 - 1;
  out[o + 2] = 0;
  return out;
}

/** The morphed position: (1 − s)·square + s·direction (the view's shader evaluates the same mix). */
export function morphPoint(
  sq: ArrayLike<number>,
  dir: ArrayLike<number>,
  s: number,
  out: number[] | Float64Array = [0, 0, 0],
  o = 0,
  so = 0,
  dOff = 0,
): number[] | Float64Array {
  // GLSL's mix(x, y, s) = x(1 − s) + y s: exactly the square at s = 0 and the direction at s = 1
  const r = 1 - s;
  out[o] = sq[so] * r + dir[dOff] * s;
  out[o + 1] = sq[so + 1] * r + dir[dOff + 1] * s;
  out[o + 2] = sq[so + 2] * r + dir[dOff + 2] * s;
  return out;
}

/** Number of grid lines per axis of the warped (ξ₁, ξ₂) grid (8 strata of each ξ). */
export const GRID_LINES = 8;

/** What the animation shows at position t (readouts the view prints and the tests recompute). */
export interface AnimFrame {
  anim: AnimKind;
  /** Samples drawn (growth) or morphed (warp). */
  shown: number;
  /** Morph fraction s (1 for the growth animation: points sit on the hemisphere). */
  s: number;
  /** The tracked sample: the first of the set, its (ξ₁, ξ₂), its direction and where it is now. */
  tracked: {
    xi1: number;
    xi2: number;
    theta: number;
    phi: number;
    dir: [number, number, number];
    pos: [number, number, number];
  } | null;
}

/** The animation frame for (lobe, point set, seed, n) at position t. */
export function animFrame(
  lobe: Lobe | null,
  kind: SequenceKind,
  seed: number,
  n: number,
  anim: AnimKind,
  t: number,
): AnimFrame {
  const s = anim === 'warp' ? morphFraction(t) : 1;
  const shown = !lobe ? 0 : anim === 'warp' ? n : growCount(n, t);
  let tracked: AnimFrame['tracked'] = null;
  if (lobe && n > 0 && shown > 0) {
    const u = new Float64Array(2);
    fillSequence2D(kind, seed, n, u, 0, 1, 0);
    const d = new Float64Array(3);
    lobe.sampleBatch(u, d, 1);
    const sq = squarePoint(u[0], u[1]);
    const p = morphPoint(sq, d, s);
    tracked = {
      xi1: u[0],
      xi2: u[1],
      theta: sphericalTheta(d[0], d[1], d[2]),
      phi: sphericalPhi(d[0], d[1]),
      dir: [d[0], d[1], d[2]],
      pos: [p[0], p[1], p[2]],
    };
  }
  return { anim, shown, s, tracked };
}

/**
 * The warped grid at morph fraction s: line segments (pairs of points, 3 numbers each) of the
 * GRID_LINES + 1 lines of constant ξ₁ and of constant ξ₂, `segments` pieces each, morphed from
 * the square to the lobe's image. `xi` receives the (ξ₁, ξ₂) of each vertex (for colours).
 */
export function warpedGrid(lobe: Lobe, s: number, segments = 48): { pos: Float64Array; xi: Float64Array } {
  const verts = 2 * 2 * (GRID_LINES + 1) * segments;
  const pos = new Float64Array(3 * verts);
  const xi = new Float64Array(2 * verts);
  const d = [0, 0, 0];
  const sq = [0, 0, 0];
  let k = 0;
  const top = 1 - 2 ** -53;
  const put = (a: number, b: number) => {
    lobe.sample(Math.min(a, top), Math.min(b, top), d, 0);
    squarePoint(a, b, sq);
    morphPoint(sq, d, s, pos, 3 * k);
    xi[2 * k] = a;
    xi[2 * k + 1] = b;
    k++;
  };
  for (let l = 0; l <= GRID_LINES; l++) {
    const fixed = l / GRID_LINES;
    for (let q = 0; q < segments; q++) {
      const t0 = q / segments;
      const t1 = (q + 1) / segments;
      put(fixed, t0);
      put(fixed, t1);
      put(t0, fixed);
      put(t1, fixed);
    }
  }
  return { pos, xi };
}

// ---- variance of the Q2 estimators (warnings for infinite or huge variance) ---------------------

/** Second moments and variances of one term of each Q2 estimator, by quadrature. */
export interface VarianceCheck {
  /** Var[2π f(X)], X uniform. */
  uniformVar: number;
  /** Var[f(X)/p(X)], X ~ p (over the region p > 0); Infinity when ∫ f²/p dω diverges. */
  importanceVar: number;
  /** true when ∫ f²/p dω diverges (the importance estimator has infinite variance). */
  infinite: boolean;
  /** importanceVar / uniformVar (Infinity when infinite; NaN when both are 0). */
  ratio: number;
}

/**
 * Var of the terms of both estimators: Var_u = 2π ∫ f² dω − I², Var_p = ∫ f²/p dω − I². The
 * importance second moment is integrated over μ = cos θ (dω = dμ dφ) in decades towards the
 * horizon μ → 0 and towards the pole μ → 1, where p may vanish; when the last decades stop
 * shrinking (each contributes at least 0.9 of the one before, as for ∫ dμ/μ), the integral
 * diverges and the variance is infinite.
 */
export function varianceCheck(lobe: Lobe, f: Integrand, exact: number): VarianceCheck {
  const opts = { relTol: 1e-8, maxDepth: 5, maxEvals: 60000 };
  const g = (mu: number, phi: number) => {
    const theta = Math.acos(Math.min(1, Math.max(0, mu)));
    const fv = f(theta, phi);
    if (fv === 0) return 0;
    const st = Math.sqrt(Math.max(0, 1 - mu * mu));
    const p = lobe.pdf(st * Math.cos(phi), st * Math.sin(phi), mu);
    return p > 0 && Number.isFinite(p) ? (fv * fv) / p : 0;
  };
  const f2 = adaptiveIntegrate2D((t, p) => f(t, p) ** 2 * Math.sin(t), 0, HALF_PI, 0, TWO_PI, opts);
  const uniformVar = Math.max(0, TWO_PI * f2 - exact * exact);
  const DEC = 12;
  // decades near the horizon: [10^-(j+1), 10^-j] for j = 1…DEC, and the same towards the pole (1 − μ)
  const horizon: number[] = [];
  const pole: number[] = [];
  for (let j = 1; j <= DEC; j++) {
    horizon.push(adaptiveIntegrate2D(g, 10 ** -(j + 1), 10 ** -j, 0, TWO_PI, opts));
    pole.push(adaptiveIntegrate2D(g, 1 - 10 ** -j, 1 - 10 ** -(j + 1), 0, TWO_PI, opts));
  }
  const middle = adaptiveIntegrate2D(g, 0.1, 0.9, 0, TWO_PI, opts);
  const sum = (a: number[]) => a.reduce((x, y) => x + y, 0);
  const m2 = middle + sum(horizon) + sum(pole);
  const diverges = (a: number[]) => {
    const last = a[a.length - 1];
    const prev = a[a.length - 2];
    return !Number.isFinite(last) || (last > 1e-9 * Math.max(1e-300, Math.abs(m2)) && last >= 0.9 * prev);
  };
  const infinite = !Number.isFinite(m2) || diverges(horizon) || diverges(pole);
  const importanceVar = infinite ? Infinity : Math.max(0, m2 - exact * exact);
  const ratio = infinite
    ? Infinity
    : uniformVar > 0
      ? importanceVar / uniformVar
      : importanceVar > 0
        ? Infinity
        : NaN;
  return { uniformVar, importanceVar, infinite, ratio };
}

// ---- error of stratified / quasi-random estimates: RMSE over randomized runs ---------------------

/** RMSE of both estimators over `runs` independently randomized point sets of n points each. */
export interface RmseResult {
  runs: number;
  uniform: number;
  importance: number;
}

/**
 * s/√N assumes independent samples; for stratified, Halton and Sobol points it is not an error
 * estimate. The error is measured instead: `runs` independent randomizations (jitter, Owen
 * scrambling, seeds derived from `seed`), RMSE = √(mean (⟨I⟩ᵣ − I)²) against the quadrature value.
 */
export function rmseOverRuns(
  lobe: Lobe | null,
  f: Integrand,
  kind: SequenceKind,
  seed: number,
  n: number,
  exact: number,
  runs = 16,
): RmseResult {
  const r = repeatEstimates(lobe, f, kind, seed, runs, n);
  const rmse = (a: Float64Array) => {
    let s = 0;
    for (const x of a) s += (x - exact) ** 2;
    return Math.sqrt(s / a.length);
  };
  return { runs, uniform: rmse(r.uniform), importance: lobe ? rmse(r.importance) : NaN };
}

// ---- live checks for the written exam derivations (Q1, Q2a) --------------------------------------

/** ∫ g over [a, b] by adaptive Gauss–Legendre (the 2D routine with a dummy unit y range). */
function integrate1D(g: (x: number) => number, a: number, b: number): number {
  return adaptiveIntegrate2D((x) => g(x), a, b, 0, 1, { relTol: 1e-13, maxDepth: 8 });
}

/** Every number the exam-first derivations of Q1 and Q2(a) print, computed here (none from the key). */
export interface ExamChecks {
  e2piMinus1: number;
  k: number;
  /** ∫₀^{π/2} cos θ sin θ dθ = ½ ∫ sin 2θ dθ (quadrature). */
  thetaIntegral: number;
  /** [−½ cos 2θ] from 0 to π/2, evaluated: −½(cos π − cos 0). */
  bracket: number;
  /** ∫₀^{2π} e^φ dφ (quadrature). */
  phiIntegral: number;
  /** ∫_Ω p(ω) dω with the computed k (quadrature over θ, φ with sin θ): 1. */
  total: number;
  /** ∫ p(θ) dθ and ∫ p(φ) dφ (quadrature): both 1. */
  thetaMarginalTotal: number;
  phiMarginalTotal: number;
  /** P(π/2) and P(2π) from the CDF code: both 1. */
  thetaCdfEnd: number;
  phiCdfEnd: number;
  /** |D| = ∫_Ω dω = ∫₀^{2π} ∫₀^{π/2} sin θ dθ dφ (quadrature): 2π. */
  solidAngle: number;
}

export function examChecks(): ExamChecks {
  const k = examLobeK();
  return {
    e2piMinus1: EXAM_E2PI_M1,
    k,
    thetaIntegral: integrate1D((t) => Math.cos(t) * Math.sin(t), 0, HALF_PI),
    bracket: -0.5 * (Math.cos(Math.PI) - Math.cos(0)),
    phiIntegral: integrate1D(Math.exp, 0, TWO_PI),
    total: adaptiveIntegrate2D(
      (t, p) => examLobePdf(Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)) * Math.sin(t),
      0,
      HALF_PI,
      0,
      TWO_PI,
      { relTol: 1e-12 },
    ),
    thetaMarginalTotal: integrate1D(examThetaPdf, 0, HALF_PI),
    phiMarginalTotal: integrate1D(examPhiPdf, 0, TWO_PI * (1 - 1e-16)),
    thetaCdfEnd: examThetaCdf(HALF_PI),
    phiCdfEnd: examPhiCdf(TWO_PI),
    solidAngle: adaptiveIntegrate2D((t) => Math.sin(t), 0, HALF_PI, 0, TWO_PI, { relTol: 1e-13 }),
  };
}

let checksCache: ExamChecks | null = null;
/** examChecks(), computed once per page (it depends on nothing: quadratures of the exam's density). */
export function examChecksCached(): ExamChecks {
  return (checksCache ??= examChecks());
}

/** Q1(d) at one (ξ₁, ξ₂): both θ forms, the φ form and its log1p twin, and the CDFs at the result. */
export function examInversion(
  xi1: number,
  xi2: number,
): {
  thetaAcos: number;
  thetaAsin: number;
  phiLn: number;
  phiLog1p: number;
  cdfTheta: number;
  cdfPhi: number;
} {
  const thetaAcos = 0.5 * Math.acos(1 - 2 * xi1);
  const thetaAsin = Math.asin(Math.sqrt(xi1));
  const phiLn = Math.log(EXAM_E2PI_M1 * xi2 + 1);
  const phiLog1p = Math.log1p(EXAM_E2PI_M1 * xi2);
  return {
    thetaAcos,
    thetaAsin,
    phiLn,
    phiLog1p,
    cdfTheta: examThetaCdf(thetaAsin),
    cdfPhi: examPhiCdf(phiLog1p),
  };
}
