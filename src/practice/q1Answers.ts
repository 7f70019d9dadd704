/**
 * Q1's answers as the key grades them: k, the marginals p(θ), p(φ), their CDFs and the inversion
 * formulas, each with the conventions the key accepts, the classic mistakes it deducts for (no
 * sin θ in dω, the inverted Jacobian p(θ, φ) = p(ω)/sin θ, the lost factor 1/a of ∫ e^(aφ) dφ, the
 * lower limit of a CDF dropped, the root of the θ inversion dropped), the follow-through from the
 * student's own earlier answers, and the key's TeX.
 */
import { formulaAnswer, numberAnswer } from './build';
import { closeFns, integralFrom0, ownFn, ownNumber } from './follow';
import { q1Closed, wallis, type Q1Params } from './q1Density';
import { coefTex, coefText, cosPowTex, cosPowText, expTex, expText, reduce, twoPiA } from './q1Text';
import {
  ratTex,
  ratText,
  tn,
  type FollowRule,
  type FormulaAnswer,
  type NumberAnswer,
  type OwnValue,
} from './model';

/** The TeX of each Q1 answer's right-hand side (the key's form), shared by the answers and the steps. */
export function q1Tex({ m, a: ar }: Q1Params) {
  const E2 = twoPiA(ar).tex;
  const inv = reduce(ar.q, ar.p); // 1/a
  const num = reduce(ar.p * (m + 1), ar.q); // a (m + 1)
  const mp1 = m + 1;
  const cosPow1Tex = m === 0 ? '\\cos\\theta' : `\\cos^{${mp1}}\\theta`;
  const kExactTex = `\\frac{${ratTex(num)}}{${E2}}`;
  const pThetaTex = `${m === 0 ? '' : `${mp1}\\,`}${cosPowTex(m)}\\sin\\theta`;
  const pPhiTex = `\\frac{${coefTex(ar)}${expTex(ar)}}{${E2}}`;
  const cdfThetaTex = `1 - ${cosPow1Tex}`;
  const cdfPhiTex = `\\frac{${expTex(ar)} - 1}{${E2}}`;
  const thetaXiTex =
    m === 0
      ? `\\arccos(1 - \\xi_1)`
      : m === 1
        ? `\\tfrac12\\arccos(1 - 2\\xi_1)`
        : `\\arccos\\!\\big((1 - \\xi_1)^{1/${mp1}}\\big)`;
  const phiXiTex = `${coefTex(inv)}\\ln\\!\\big(1 + (${E2})\\,\\xi_2\\big)`;
  return {
    mp1,
    E2,
    cosPow1Tex,
    kExactTex,
    pThetaTex,
    pPhiTex,
    cdfThetaTex,
    cdfPhiTex,
    thetaXiTex,
    phiXiTex,
  };
}

/** The sampling intervals of θ, φ and ξ, where formulas are compared. */
export const Q1_DOMAINS = {
  th: [0, Math.PI / 2] as [number, number],
  ph: [0, 2 * Math.PI] as [number, number],
  xi: [0, 1] as [number, number],
};

export interface Q1Answers {
  k: NumberAnswer;
  pTheta: FormulaAnswer;
  pPhi: FormulaAnswer;
  cdfTheta: FormulaAnswer;
  cdfPhi: FormulaAnswer;
  thetaXi: FormulaAnswer;
  phiXi: FormulaAnswer;
}

/** Every answer of a Q1 variant with its mistakes, follow-through and TeX. */
export function q1Answers(P: Q1Params): Q1Answers {
  const { m, a: ar } = P;
  const c = q1Closed(P);
  const { a, E, k } = c;
  const ET = twoPiA(ar).text;
  const inv = reduce(ar.q, ar.p); // 1/a
  const W = wallis(m);
  const { th, ph, xi } = Q1_DOMAINS;
  const kAns = numberAnswer(
    'k',
    'k',
    k,
    [],
    [
      {
        id: 'no-sin-jacobian',
        value: a / (E * W),
        message:
          'This k comes from dω = dθ dφ: the solid-angle element is dω = sin θ dθ dφ (the sin θ is missing).',
      },
      {
        id: 'missing-1-over-a',
        value: (m + 1) / E,
        message: `∫₀^2π e^(aφ) dφ = (e^(2πa) − 1)/a: the factor 1/a (a = ${ratText(ar)}) is missing.`,
      },
      {
        id: 'forgot-e0',
        value: (a * (m + 1)) / Math.exp(2 * Math.PI * a),
        message:
          'The lower limit of ∫ e^(aφ) dφ is missing: it gives e^(2πa) − e^0 = e^(2πa) − 1, not e^(2πa).',
      },
    ],
  );
  const pTheta = formulaAnswer(
    'p-theta',
    'p(θ)',
    'theta',
    th,
    c.pTheta,
    m === 0 ? 'sin(theta)' : `${m + 1}*${cosPowText(m)}*sin(theta)`,
    [],
    [
      {
        id: 'inverted-jacobian',
        fns: [(t) => ((m + 1) * Math.cos(t) ** m) / Math.sin(t)],
        message:
          'This is the inverted Jacobian p(θ, φ) = p(ω)/sin θ (the key’s first version): the correct change of variables multiplies, p(θ, φ) = sin θ · p(ω). Divided, the θ-integral diverges at θ → 0.',
      },
      {
        id: 'no-sin-jacobian',
        fns: [(t) => Math.cos(t) ** m / W, (t) => (m + 1) * Math.cos(t) ** m],
        message: 'The sin θ of dω = sin θ dθ dφ is missing from p(θ, φ) = sin θ · p(ω).',
      },
    ],
  );
  const pPhi = formulaAnswer(
    'p-phi',
    'p(φ)',
    'phi',
    ph,
    c.pPhi,
    `${coefText(ar)}${expText(ar)} / ${ET}`,
    [],
    [
      {
        id: 'missing-1-over-a',
        fns: [(f) => Math.exp(a * f) / E],
        message: `The factor a = ${ratText(ar)} is missing: ∫₀^2π e^(aφ) dφ = (e^(2πa) − 1)/a, so p(φ) = a e^(aφ)/(e^(2πa) − 1).`,
      },
      {
        id: 'forgot-e0',
        fns: [(f) => (a * Math.exp(a * f)) / Math.exp(2 * Math.PI * a)],
        message: 'The normalization lost the e^0 term: it is e^(2πa) − 1, not e^(2πa).',
      },
    ],
  );
  const cdfTheta = formulaAnswer(
    'cdf-theta',
    'P(θ)',
    'theta',
    th,
    c.cdfTheta,
    m === 0 ? '1 - cos(theta)' : `1 - cos(theta)^${m + 1}`,
    [],
    [
      {
        id: 'no-lower-limit',
        fns: [(t) => -(Math.cos(t) ** (m + 1)), (t) => -Math.cos(2 * t) / 2],
        message: 'The lower limit θ′ = 0 was not subtracted: P(0) must be 0.',
      },
    ],
  );
  const cdfPhi = formulaAnswer(
    'cdf-phi',
    'P(φ)',
    'phi',
    ph,
    c.cdfPhi,
    `(${expText(ar)} - 1) / ${ET}`,
    [],
    [
      {
        id: 'no-lower-limit',
        fns: [(f) => Math.exp(a * f) / E],
        message: 'The lower limit φ′ = 0 was not subtracted: P(0) must be 0, so the numerator is e^(aφ) − 1.',
      },
    ],
  );
  const thetaXi = formulaAnswer(
    'theta-of-xi',
    'θ(ξ₁)',
    'xi',
    xi,
    c.thetaOfXi,
    m === 0 ? 'acos(1 - xi)' : m === 1 ? 'acos(1 - 2*xi) / 2' : `acos((1 - xi)^(1/${m + 1}))`,
    [
      {
        fn: (x) => Math.acos(x ** (1 / (m + 1))),
        message:
          'you used ξ in place of 1 − ξ, which has the same distribution (a valid sampler; the literal inverse of P is with 1 − ξ₁).',
      },
    ],
    [
      {
        id: 'missing-root',
        fns: [(x) => Math.acos(1 - x), (x) => Math.acos(x)],
        message: `The root is missing: cos^(m+1) θ = 1 − ξ₁ gives cos θ = (1 − ξ₁)^(1/(m+1)) (here m + 1 = ${m + 1}).`,
      },
      ...(m === 1
        ? [
            {
              id: 'missing-half',
              fns: [(x: number) => Math.acos(1 - 2 * x)],
              message: 'cos 2θ = 1 − 2ξ₁ gives 2θ = arccos(1 − 2ξ₁): divide by 2.',
            },
          ]
        : []),
    ],
  );
  const phiXi = formulaAnswer(
    'phi-of-xi',
    'φ(ξ₂)',
    'xi',
    xi,
    c.phiOfXi,
    `${coefText(inv)}log(1 + ${ET}*xi)`,
    [
      {
        fn: (x) => Math.log1p(E * (1 - x)) / a,
        message: 'you used 1 − ξ in place of ξ, which has the same distribution (a valid sampler).',
      },
    ],
    [
      {
        id: 'missing-1-over-a',
        fns: [(x) => Math.log1p(E * x)],
        message: `e^(aφ) = 1 + (e^(2πa) − 1)ξ₂ gives φ = ln(…)/a: divide by a = ${ratText(ar)}.`,
      },
      {
        id: 'no-plus-one',
        fns: [(x) => Math.log(E * x) / a],
        message:
          'The "+ 1" from P(φ) = (e^(aφ) − 1)/(e^(2πa) − 1) is missing: φ = ln(1 + (e^(2πa) − 1)ξ₂)/a.',
      },
    ],
  );

  // follow-through: each later answer from the student's own earlier one
  pPhi.follow = [
    {
      from: ['k'],
      matches: (own, g) => {
        const ks = ownNumber(own, 'k');
        return typeof ks === 'number' && closeFns((f) => (ks / (m + 1)) * Math.exp(a * f), g, ph);
      },
    },
  ];
  const cdfFrom = (pdf: string, dom: [number, number]) => [
    {
      from: [pdf],
      matches: (own: Parameters<FollowRule['matches']>[0], g: OwnValue) => {
        const p = ownFn(own, pdf);
        return !!p && closeFns(integralFrom0(p), g, dom);
      },
    },
  ];
  cdfTheta.follow = cdfFrom('p-theta', th);
  cdfPhi.follow = cdfFrom('p-phi', ph);
  const inverseOf = (cdf: string) => [
    {
      from: [cdf],
      matches: (own: Parameters<FollowRule['matches']>[0], h: OwnValue) => {
        const P = ownFn(own, cdf);
        if (!P || typeof h !== 'function') return false;
        const back = (x: number) => P(h(x));
        return closeFns((x) => x, back, xi) || closeFns((x) => 1 - x, back, xi);
      },
    },
  ];
  thetaXi.follow = inverseOf('cdf-theta');
  phiXi.follow = inverseOf('cdf-phi');
  const T = q1Tex(P);
  kAns.tex = `k = ${T.kExactTex} \\approx ${tn(k)}`;
  pTheta.tex = `p(\\theta) = ${T.pThetaTex}`;
  pPhi.tex = `p(\\phi) = ${T.pPhiTex}`;
  cdfTheta.tex = `P(\\theta) = ${T.cdfThetaTex}`;
  cdfPhi.tex = `P(\\phi) = ${T.cdfPhiTex}`;
  thetaXi.tex = `\\theta = ${T.thetaXiTex}`;
  phiXi.tex = `\\phi = ${T.phiXiTex}`;
  return { k: kAns, pTheta, pPhi, cdfTheta, cdfPhi, thetaXi, phiXi };
}
