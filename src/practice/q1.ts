/**
 * Q1 variants: a separable hemisphere density p(ω) = k cosᵐθ e^(aφ) (the exam's is m = 1, a = 1),
 * with m ∈ {0, …, 4} and a a small rational ≠ 0. Closed forms (dω = sin θ dθ dφ):
 *
 *   k = a (m + 1) / (e^(2πa) − 1)                 since ∫₀^{π/2} cos^m θ sin θ dθ = 1/(m + 1)
 *   p(θ) = (m + 1) cos^m θ sin θ,  P(θ) = 1 − cos^(m+1) θ,  θ = arccos((1 − ξ₁)^(1/(m+1)))
 *   p(φ) = a e^(aφ) / (e^(2πa) − 1),  P(φ) = (e^(aφ) − 1)/(e^(2πa) − 1),  φ = ln(1 + (e^(2πa) − 1) ξ₂)/a
 *
 * e^(2πa) − 1 is evaluated as expm1(2πa), as the core's exam lobe does (core/sampling/examLobe).
 * Classic mistakes: no sin θ in dω, the inverted Jacobian p(θ, φ) = p(ω)/sin θ, the lost factor
 * 1/a of ∫ e^(aφ) dφ, the lower limit of a CDF dropped, the root of the θ inversion dropped.
 */
import { Rng } from '../core/random';
import { formulaAnswer, numberAnswer, pick, query } from './build';
import { closeFns, integralFrom0, ownFn, ownNumber } from './follow';
import {
  assembleSolution,
  fmt,
  ratTex,
  ratText,
  ratValue,
  tn,
  type FollowRule,
  type OwnValue,
  type Part,
  type Rational,
  type SolutionStep,
  type Variant,
} from './model';

const A_CHOICES: readonly Rational[] = [
  { p: 1, q: 1 },
  { p: 1, q: 1 },
  { p: 2, q: 1 },
  { p: 1, q: 2 },
  { p: 3, q: 2 },
  { p: -1, q: 1 },
  { p: -1, q: 2 },
];

/** ∫₀^{π/2} cos^m θ dθ (Wallis): π/2, 1, then (m − 1)/m times the one two below. */
export function wallis(m: number): number {
  if (m === 0) return Math.PI / 2;
  if (m === 1) return 1;
  return ((m - 1) / m) * wallis(m - 2);
}

export interface Q1Params {
  m: number;
  a: Rational;
}

export function q1Params(seed: number): Q1Params {
  const rng = new Rng(seed, 0x5101);
  const m = pick(rng, [0, 1, 1, 1, 2, 2, 3, 4]);
  const a = pick(rng, A_CHOICES);
  return { m, a };
}

/** The closed forms of a Q1 density (pure numbers and functions). */
export function q1Closed({ m, a: ar }: Q1Params) {
  const a = ratValue(ar);
  const E = Math.expm1(2 * Math.PI * a); // e^(2πa) − 1
  const k = (a * (m + 1)) / E;
  return {
    a,
    E,
    k,
    pTheta: (t: number) => (m + 1) * Math.cos(t) ** m * Math.sin(t),
    pPhi: (f: number) => (a * Math.exp(a * f)) / E,
    cdfTheta: (t: number) => 1 - Math.cos(t) ** (m + 1),
    cdfPhi: (f: number) => Math.expm1(a * f) / E,
    thetaOfXi: (x: number) => Math.acos((1 - x) ** (1 / (m + 1))),
    phiOfXi: (x: number) => Math.log1p(E * x) / a,
  };
}

function gcd(a: number, b: number): number {
  return b === 0 ? Math.abs(a) : gcd(b, a % b);
}
function reduce(p: number, q: number): Rational {
  const g = (gcd(p, q) || 1) * (q < 0 ? -1 : 1); // denominator positive
  return { p: p / g + 0, q: q / g };
}
/** A rational as a coefficient in mathjs text: '' for 1, '-' for −1, '3*', '(1/2)*'. */
function coefText(r: Rational): string {
  if (r.q === 1) return r.p === 1 ? '' : r.p === -1 ? '-' : `${r.p}*`;
  return `(${r.p}/${r.q})*`;
}
/** A rational as a coefficient in TeX: '' for 1, '-' for −1, '3', '\tfrac{1}{2}'. */
function coefTex(r: Rational): string {
  if (r.q === 1) return r.p === 1 ? '' : r.p === -1 ? '-' : String(r.p);
  return ratTex(r);
}
/** aφ as mathjs text: phi, -phi, 2*phi, phi/2, 3*phi/2, -phi/2. */
export function argText(a: Rational): string {
  const head = a.p === 1 ? 'phi' : a.p === -1 ? '-phi' : `${a.p}*phi`;
  return a.q === 1 ? head : `${head}/${a.q}`;
}
export function argTex(a: Rational): string {
  const head = a.p === 1 ? '\\phi' : a.p === -1 ? '-\\phi' : `${a.p}\\phi`;
  return a.q === 1 ? head : `${head}/${a.q}`;
}
/** e^(aφ) for people: e^φ, e^(−φ), e^(φ/2), … */
export function expPlain(a: Rational): string {
  const t = argText(a).replace('phi', 'φ').replace('*', '').replace('-', '−');
  return a.p === 1 && a.q === 1 ? 'e^φ' : `e^(${t})`;
}
/** 2πa = cπ with c = 2a an integer for every a drawn here. */
function twoPiA(a: Rational): { text: string; tex: string } {
  const c = (2 * a.p) / a.q;
  const head = c === 1 ? '' : c === -1 ? '-' : `${c}*`;
  return { text: `(e^(${head}pi) - 1)`, tex: `e^{${head.replace('*', '')}\\pi}-1` };
}

function cosPowTex(m: number): string {
  return m === 0 ? '' : m === 1 ? '\\cos\\theta\\,' : `\\cos^{${m}}\\theta\\,`;
}
function cosPowText(m: number): string {
  return m === 0 ? '' : m === 1 ? 'cos(theta)' : `cos(theta)^${m}`;
}
function expTex(a: Rational): string {
  return `e^{${argTex(a)}}`;
}
function expText(a: Rational): string {
  return `exp(${argText(a)})`;
}

export function q1Variant(seed: number): Variant {
  const P = q1Params(seed);
  const { m, a: ar } = P;
  const c = q1Closed(P);
  const { a, E, k } = c;
  const ET = twoPiA(ar).text;
  const A = ratTex(ar);
  const E2 = twoPiA(ar).tex;
  const inv = reduce(ar.q, ar.p); // 1/a
  const num = reduce(ar.p * (m + 1), ar.q); // a (m + 1)
  const cosPlain = m === 0 ? '' : m === 1 ? 'cos θ ' : `cos^${m} θ `;
  const W = wallis(m);
  const pdfText = ['k', cosPowText(m), expText(ar)].filter(Boolean).join(' * ');
  const pdfTex = `p(\\omega) = k\\,${cosPowTex(m)}${expTex(ar)}`;
  const aIsOne = ar.p === 1 && ar.q === 1;

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
  const th: [number, number] = [0, Math.PI / 2];
  const ph: [number, number] = [0, 2 * Math.PI];
  const xi: [number, number] = [0, 1];
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
  const xi1 = 0.3;
  const xi2 = 0.7;
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
  kAns.tex = `k = ${kExactTex} \\approx ${tn(k)}`;
  pTheta.tex = `p(\\theta) = ${pThetaTex}`;
  pPhi.tex = `p(\\phi) = ${pPhiTex}`;
  cdfTheta.tex = `P(\\theta) = ${cdfThetaTex}`;
  cdfPhi.tex = `P(\\phi) = ${cdfPhiTex}`;
  thetaXi.tex = `\\theta = ${thetaXiTex}`;
  phiXi.tex = `\\phi = ${phiXiTex}`;
  const thetaIntegral = `\\int_0^{\\pi/2} ${cosPowTex(m)}\\sin\\theta\\,d\\theta = \\Big[-\\frac{${cosPow1Tex}}{${mp1}}\\Big]_0^{\\pi/2} = ${m === 0 ? '1' : `\\frac{1}{${mp1}}`}`;
  const phiIntegral = `\\int_0^{2\\pi} ${expTex(ar)}\\,d\\phi = \\Big[\\frac{${expTex(ar)}}{${A}}\\Big]_0^{2\\pi} = \\frac{${E2}}{${A}}`;
  const normTex = `\\int_0^{2\\pi}\\!\\!\\int_0^{\\pi/2} k\\,${cosPowTex(m)}${expTex(ar)}\\sin\\theta\\,d\\theta\\,d\\phi = 1`;
  const stepsA: SolutionStep[] = [
    { text: '(a) Normalize over the upper hemisphere with dω = sin θ dθ dφ; the integral separates:' },
    { tex: normTex },
    { text: 'The θ integral (substitute u = cos θ, du = −sin θ dθ):' },
    { tex: thetaIntegral },
    { text: 'The φ integral (both limits: e^0 = 1 is subtracted):' },
    { tex: phiIntegral },
    {
      tex: `k\\cdot${m === 0 ? '1' : `\\frac{1}{${mp1}}`}\\cdot\\frac{${E2}}{${A}} = 1 \\;\\Rightarrow\\; k = ${kExactTex} = ${tn(k)}`,
    },
    { text: `Here e^(2πa) − 1 = ${fmt(E, 6)}.` },
  ];
  const stepsB: SolutionStep[] = [
    { text: '(b) Change of variables p(θ, φ) = sin θ · p(ω), then integrate out the other variable:' },
    { tex: `p(\\theta,\\phi) = k\\,${cosPowTex(m)}\\sin\\theta\\,${expTex(ar)}` },
    {
      tex: `p(\\theta) = \\int_0^{2\\pi} p(\\theta,\\phi)\\,d\\phi = k\\,${cosPowTex(m)}\\sin\\theta\\cdot\\frac{${E2}}{${A}} = ${pThetaTex}${m === 1 ? ' = \\sin 2\\theta' : ''}`,
    },
    {
      tex: `p(\\phi) = \\int_0^{\\pi/2} p(\\theta,\\phi)\\,d\\theta = k\\,${expTex(ar)}\\cdot${m === 0 ? '1' : `\\frac{1}{${mp1}}`} = ${pPhiTex}`,
    },
    {
      text: `Each marginal integrates to 1. The inverted Jacobian p(θ, φ) = p(ω)/sin θ ∝ ${cosPlain}${expPlain(ar)} / sin θ cannot be normalized: ∫ dθ/sin θ diverges at θ → 0.`,
    },
  ];
  const stepsC: SolutionStep[] = [
    { text: '(c) CDFs, integrating each marginal from 0 (so that P(0) = 0):' },
    {
      tex: `P(\\theta) = \\int_0^{\\theta} ${pThetaTex.replace(/\\theta/g, "\\theta'")}\\,d\\theta' = \\Big[-${cosPow1Tex.replace(/\\theta/g, "\\theta'")}\\Big]_0^{\\theta} = ${cdfThetaTex}${m === 1 ? ' = \\frac{1-\\cos 2\\theta}{2}' : ''}`,
    },
    {
      tex: `P(\\phi) = \\int_0^{\\phi} \\frac{${coefTex(ar)}e^{${argTex(ar).replace(/\\phi/g, "\\phi'")}}}{${E2}}\\,d\\phi' = ${cdfPhiTex}`,
    },
  ];
  const stepsD: SolutionStep[] = [
    { text: '(d) Set ξ = P and solve for the angle:' },
    { tex: `\\xi_1 = ${cdfThetaTex} \\;\\Rightarrow\\; \\cos\\theta = (1 - \\xi_1)^{1/${mp1}}` },
    {
      tex:
        m === 0
          ? `\\theta = \\arccos(1 - \\xi_1)`
          : m === 1
            ? `\\theta = \\tfrac12\\arccos(1 - 2\\xi_1) = \\arccos\\sqrt{1-\\xi_1}`
            : `\\theta = ${thetaXiTex}`,
    },
    { tex: `\\xi_2 = ${cdfPhiTex} \\;\\Rightarrow\\; ${expTex(ar)} = 1 + (${E2})\\,\\xi_2` },
    { tex: `\\phi = ${phiXiTex}` },
    {
      text: `For example ξ₁ = ${xi1} gives θ = ${fmt(c.thetaOfXi(xi1), 5)} rad and ξ₂ = ${xi2} gives φ = ${fmt(c.phiOfXi(xi2), 5)} rad. Using 1 − ξ for ξ gives the same distribution.`,
    },
  ];
  const parts: Part[] = [
    {
      id: 'a',
      prompt: '(a) The normalization constant k (a number).',
      answers: [kAns],
      hint: [
        { text: 'Integrate p(ω) over the hemisphere with dω = sin θ dθ dφ and set the result to 1:' },
        { tex: normTex },
      ],
      steps: stepsA,
    },
    {
      id: 'b',
      prompt: '(b) The marginal densities, as formulas in theta and phi.',
      paperPrompt: '(b) The marginal densities p(θ) and p(φ).',
      answers: [pTheta, pPhi],
      hint: [
        { text: 'First change variables (the Jacobian multiplies), then integrate out the other angle:' },
        {
          tex: `p(\\theta,\\phi) = \\sin\\theta\\cdot p(\\omega) = k\\,${cosPowTex(m)}\\sin\\theta\\,${expTex(ar)}`,
        },
      ],
      steps: stepsB,
    },
    {
      id: 'c',
      prompt: '(c) The CDFs P(θ) and P(φ).',
      answers: [cdfTheta, cdfPhi],
      hint: [
        { text: 'Integrate each marginal from 0; for θ substitute u = cos θ′:' },
        { tex: `P(\\theta) = \\int_0^{\\theta} ${pThetaTex.replace(/\\theta/g, "\\theta'")}\\,d\\theta'` },
      ],
      steps: stepsC,
    },
    {
      id: 'd',
      prompt: '(d) θ and φ from uniform numbers (write ξ₁, ξ₂ as xi).',
      paperPrompt: '(d) The inversion formulas θ(ξ₁) and φ(ξ₂).',
      answers: [thetaXi, phiXi],
      hint: [
        { text: 'Set ξ₁ equal to P(θ) and solve for θ (and likewise ξ₂ = P(φ)):' },
        { tex: `\\xi_1 = ${cdfThetaTex}` },
      ],
      steps: stepsD,
    },
  ];
  const sceneQuery =
    m === 1 && aIsOne
      ? 'lobe=exam'
      : query({ lobe: 'custom', pdf: [cosPowText(m), expText(ar)].filter(Boolean).join('*') });
  return {
    question: 'q1',
    seed,
    title: 'Sampling a hemisphere PDF by inversion',
    statement: `A density over directions of the upper hemisphere (θ ∈ [0, π/2] polar, φ ∈ [0, 2π)) is p(ω) = k ${cosPlain}${expPlain(ar)}. With dω = sin θ dθ dφ: (a) find k; (b) find the marginal densities p(θ) and p(φ) of p(θ, φ) = sin θ · p(ω); (c) their CDFs; (d) the inversion formulas that turn uniform ξ₁, ξ₂ into θ, φ.`,
    givens: [
      { name: 'pdf', label: 'p(ω)', value: pdfText, display: pdfText, tex: pdfTex },
      { name: 'm', label: 'exponent m of cos θ', value: String(m), display: String(m) },
      { name: 'a', label: 'a (in e^(aφ))', value: String(a), display: ratText(ar) },
    ],
    parts,
    intro: [],
    solution: assembleSolution([], parts),
    sceneHref: `#/hemisphere?${sceneQuery}`,
    sceneLabel: 'Open this density in the hemisphere scene',
    notes: [],
  };
}
