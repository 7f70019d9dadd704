/**
 * Reference integrals ∫ₐᵇ f(x) dx of typed integrands to (nearly) full double precision, by globally
 * adaptive Gauss–Kronrod quadrature (the 7-point Gauss rule embedded in the 15-point Kronrod rule,
 * QUADPACK's QK15 inside a QAG-style loop): the interval with the largest error estimate is bisected
 * until the summed error estimate is below the tolerance or below the rounding floor.
 *
 * Measure: dx on [a, b] (a > b gives the negative, as usual). The rule never evaluates f at the end
 * points, so integrable end-point singularities such as 1/√x are handled, only slowly.
 * Source: Piessens, de Doncker-Kapenga, Überhuber & Kahaner, "QUADPACK" (1983), routines QK15/QAG;
 * Kronrod (1965); node and weight values from QUADPACK `dqk15.f`.
 */

/* QUADPACK publishes these constants to 33 digits; each is written here as the shortest decimal that
   reads back as the same double (the nearest double to the published value, which is the value meant). */

/** Kronrod abscissae on [0, 1) (the odd-indexed ones, 1, 3, 5, are also the 7-point Gauss nodes, with 0). */
const XGK = [
  0.9914553711208126, 0.9491079123427585, 0.8648644233597691, 0.7415311855993945, 0.5860872354676911,
  0.4058451513773972, 0.20778495500789848, 0,
];
const WGK = [
  0.022935322010529224, 0.06309209262997856, 0.10479001032225019, 0.14065325971552592, 0.1690047266392679,
  0.19035057806478542, 0.20443294007529889, 0.20948214108472782,
];
/** Gauss weights for XGK[1], XGK[3], XGK[5], XGK[7] = 0. */
const WG = [0.1294849661688697, 0.27970539148927664, 0.3818300505051189, 0.4179591836734694];

/** Name of the method, for display beside the reference value. */
export const INTEGRATION_METHOD = 'adaptive Gauss–Kronrod (7/15-point, QUADPACK QAG)';

/** Result of {@link integrate1D}. */
export interface Integral1D {
  /** The integral (NaN when f was not finite somewhere). */
  value: number;
  /** Estimated absolute error (sum of |K15 − G7| over the final intervals). */
  error: number;
  /** ∫ |f| dx, by the same rule (used for rounding floors and to detect an all-zero f). */
  absValue: number;
  /** Number of f evaluations. */
  evaluations: number;
  /** Number of final subintervals. */
  intervals: number;
  /** True when the error estimate met the tolerance. */
  converged: boolean;
  /** Where f was not finite (first such x), if anywhere. */
  nonFiniteAt?: number;
  /** The method used: {@link INTEGRATION_METHOD}. */
  method: string;
}

/** Options of {@link integrate1D}. */
export interface Integrate1DOptions {
  /** Relative tolerance (default 4e-16 ≈ 2ε: "full precision"; the rounding floor stops earlier). */
  relTol?: number;
  /** Absolute tolerance (default 0). */
  absTol?: number;
  /** Maximum number of subintervals (default 2000). */
  maxIntervals?: number;
}

interface Piece {
  a: number;
  b: number;
  k: number;
  err: number;
  abs: number;
}

const state = { nonFinite: NaN as number, evals: 0 };

function qk15(f: (x: number) => number, a: number, b: number): Piece {
  const c = 0.5 * (a + b);
  const h = 0.5 * (b - a);
  const fc = f(c);
  let bad = Number.isFinite(fc) ? NaN : c;
  let resK = fc * WGK[7];
  let resG = fc * WG[3];
  let resAbs = Math.abs(resK);
  for (let j = 0; j < 7; j++) {
    const dx = h * XGK[j];
    const f1 = f(c - dx);
    const f2 = f(c + dx);
    if (!Number.isFinite(f1) && Number.isNaN(bad)) bad = c - dx;
    if (!Number.isFinite(f2) && Number.isNaN(bad)) bad = c + dx;
    resK += WGK[j] * (f1 + f2);
    resAbs += WGK[j] * (Math.abs(f1) + Math.abs(f2));
    if (j & 1) resG += WG[j >> 1] * (f1 + f2);
  }
  state.evals += 15;
  if (!Number.isNaN(bad) && Number.isNaN(state.nonFinite)) state.nonFinite = bad;
  return { a, b, k: resK * h, err: Math.abs((resK - resG) * h), abs: resAbs * Math.abs(h) };
}

/**
 * ∫ₐᵇ f(x) dx by adaptive Gauss–Kronrod (see module doc). Domain: finite a, b; f finite on (a, b).
 * If f returns a non-finite value the result has value NaN and `nonFiniteAt` set. If the error
 * estimate does not shrink below the tolerance within `maxIntervals` (e.g. a divergent integral such
 * as ∫₀¹ dx/x), `converged` is false.
 */
export function integrate1D(
  f: (x: number) => number,
  a: number,
  b: number,
  opts: Integrate1DOptions = {},
): Integral1D {
  const relTol = opts.relTol ?? 4e-16;
  const absTol = opts.absTol ?? 0;
  const maxIntervals = opts.maxIntervals ?? 2000;
  state.nonFinite = NaN;
  state.evals = 0;
  const base = { method: INTEGRATION_METHOD };
  if (!Number.isFinite(a) || !Number.isFinite(b)) {
    return {
      ...base,
      value: NaN,
      error: Infinity,
      absValue: NaN,
      evaluations: 0,
      intervals: 0,
      converged: false,
    };
  }
  if (a === b)
    return { ...base, value: 0, error: 0, absValue: 0, evaluations: 0, intervals: 0, converged: true };
  const pieces: Piece[] = [qk15(f, a, b)];
  const done = (converged: boolean): Integral1D => {
    // Neumaier-compensated sums of the pieces
    let s = 0;
    let comp = 0;
    let e = 0;
    let av = 0;
    for (const p of pieces) {
      const t = s + p.k;
      comp += Math.abs(s) >= Math.abs(p.k) ? s - t + p.k : p.k - t + s;
      s = t;
      e += p.err;
      av += p.abs;
    }
    const nf = state.nonFinite;
    return {
      ...base,
      value: Number.isNaN(nf) ? s + comp : NaN,
      error: e,
      absValue: av,
      evaluations: state.evals,
      intervals: pieces.length,
      converged: converged && Number.isNaN(nf),
      ...(Number.isNaN(nf) ? {} : { nonFiniteAt: nf }),
    };
  };
  for (;;) {
    if (!Number.isNaN(state.nonFinite)) return done(false);
    let total = 0;
    let err = 0;
    let absTotal = 0;
    let worst = 0;
    for (let i = 0; i < pieces.length; i++) {
      const p = pieces[i];
      total += p.k;
      err += p.err;
      absTotal += p.abs;
      if (p.err > pieces[worst].err) worst = i;
    }
    const tol = Math.max(absTol, relTol * Math.abs(total));
    // rounding floor: below ~50 ε ∫|f| the K15−G7 difference is rounding noise (QUADPACK's 50·epmach)
    const floor = 50 * 2.220446049250313e-16 * absTotal;
    if (err <= tol || err <= floor) return done(true);
    if (pieces.length >= maxIntervals) return done(false);
    const p = pieces[worst];
    const m = 0.5 * (p.a + p.b);
    if (!(m > Math.min(p.a, p.b) && m < Math.max(p.a, p.b))) return done(false); // interval too small to split
    pieces[worst] = qk15(f, p.a, m);
    pieces.push(qk15(f, m, p.b));
  }
}
