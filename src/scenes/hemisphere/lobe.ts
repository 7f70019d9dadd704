/**
 * The sampling densities of the hemisphere scene (lobes): each a sampler, its pdf and its
 * marginals, built-in ones from the core's closed forms and a typed one from its tabulation.
 */
import {
  TabulatedHemisphere,
  cosineHemispherePdf,
  examLobeK,
  examLobePdf,
  examPhiPdf,
  examThetaPdf,
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
  TWO_PI,
  tabulateHemisphereDensity,
  uniformHemispherePdf,
  type TabulateResult,
} from '../../core/sampling';
import { superscript } from '../../core/format';
import type { ParamProblem } from '../../kit/params';
import { checkedIntegral, type Integrand } from './integral';
import type { LobeId } from './params';

/** A sampling density on the hemisphere, as the scene uses it: sampler, pdf and marginals. */
export interface Lobe {
  id: LobeId;
  /** Short name for legends. */
  label: string;
  /** Normalization constant of p(ω) as the derivation defines it (k of k·(shape)). */
  k: number;
  /**
   * Significant digits of k that are right: 8 (the readout's) for the closed forms and for a typed
   * density whose adaptive quadrature met its tolerance, fewer when its error estimate is larger.
   */
  kDigits: number;
  /** How k was obtained, in a few words (for the readout's note). */
  kSource: string;
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
 * not compile), with the tabulation's verdict in `tab` (null when nothing was tabulated) and, when
 * the typed density is not one, the problem the shell reports for `pdf`.
 */
export function lobeFromParams(
  id: LobeId,
  exponent: number,
  density?: Integrand | null,
): { lobe: Lobe | null; tab: TabulateResult | null; problem: ParamProblem | null } {
  if (id !== 'custom') return { lobe: makeLobe(id, exponent), tab: null, problem: null };
  if (!density) return { lobe: null, tab: null, problem: null };
  const tab = tabulateHemisphereDensity(density);
  if (!tab.ok)
    return { lobe: null, tab, problem: { name: 'pdf', message: `is not a valid density: ${tab.message}` } };
  const lobe = makeLobe('custom', exponent, tab.lobe);
  return { lobe: lobe && { ...lobe, ...typedK(density) }, tab, problem: null };
}

/** Digits of k the readouts print when k is exact (a closed form) or resolved to full tolerance. */
export const K_DIGITS = 8;

/**
 * k = 1/∫ p dω of a typed density by adaptive quadrature (the table's own sum is off in the 4th
 * digit for a peaked density), with as many significant digits as its error estimate vouches for.
 * Null when the quadrature has no value: the lobe then keeps the table's k, to 3 digits.
 */
export function typedK(density: Integrand): Pick<Lobe, 'k' | 'kDigits' | 'kSource'> | null {
  const q = checkedIntegral(density);
  if (!(q.value > 0) || q.problem) return null;
  const rel = q.error / q.value;
  const digits = rel > 0 ? Math.floor(-Math.log10(2 * rel)) : K_DIGITS;
  return {
    k: 1 / q.value,
    kDigits: Math.max(1, Math.min(K_DIGITS, digits)),
    kSource: 'by adaptive quadrature of ∫ p dω',
  };
}

/** A built-in lobe for the exponent n (only Phong reads it): every column is a core function. */
type LobeRow = (n: number) => Omit<Lobe, 'id' | 'kDigits' | 'kSource'>;

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
  if (id !== 'custom') return { id, kDigits: K_DIGITS, kSource: 'closed form', ...LOBES[id](exponent) };
  if (!custom) return null;
  return {
    id,
    label: 'typed p(θ, φ), tabulated',
    k: custom.k,
    kDigits: 3,
    kSource: 'from the 64 × 128 table',
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
