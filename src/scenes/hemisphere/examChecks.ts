/**
 * Every number the exam-first derivations of Q1 and Q2(a) print, computed live (none from the
 * key): the normalization, the marginal integrals, the CDF ends, the inversion at one (ξ₁, ξ₂), and
 * the inverted-Jacobian variant's partial integrals.
 */
import {
  EXAM_E2PI_M1,
  examLobeK,
  examLobePdf,
  examPhiCdf,
  examPhiPdf,
  examThetaCdf,
  examThetaPdf,
  invertedJacobianPartialIntegral,
  HALF_PI,
  TWO_PI,
} from '../../core/sampling';
import { adaptiveIntegrate2D } from '../../core/verify';
import { integrate1D } from '../../core/verify/integrate1d';

/** ∫ g over [a, b] to full double precision (adaptive Gauss–Kronrod, core/verify). */
function integral(g: (x: number) => number, a: number, b: number): number {
  return integrate1D(g, a, b).value;
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
    thetaIntegral: integral((t) => Math.cos(t) * Math.sin(t), 0, HALF_PI),
    bracket: -0.5 * (Math.cos(Math.PI) - Math.cos(0)),
    phiIntegral: integral(Math.exp, 0, TWO_PI),
    total: adaptiveIntegrate2D(
      (t, p) => examLobePdf(Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)) * Math.sin(t),
      0,
      HALF_PI,
      0,
      TWO_PI,
      { relTol: 1e-12 },
    ),
    thetaMarginalTotal: integral(examThetaPdf, 0, HALF_PI),
    phiMarginalTotal: integral(examPhiPdf, 0, TWO_PI * (1 - 1e-16)),
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
