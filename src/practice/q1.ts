/**
 * Q1 variants: a separable hemisphere density p(ω) = k cosᵐθ e^(aφ) (q1Density.ts), its answers
 * (q1Answers.ts), and here the variant itself: the statement, each part's hint and worked steps in
 * the variant's numbers, and the link to the hemisphere scene.
 */
import { formatSignificant } from '../core/format';
import { query } from './build';
import { assembleSolution, ratTex, ratText, tn, type Part, type SolutionStep, type Variant } from './model';
import { q1Answers, q1Tex } from './q1Answers';
import { q1Closed, q1Params } from './q1Density';
import { argTex, coefTex, cosPowTex, cosPowText, expPlain, expTex, expText } from './q1Text';

export function q1Variant(seed: number): Variant {
  const P = q1Params(seed);
  const { m, a: ar } = P;
  const c = q1Closed(P);
  const { a, E, k } = c;
  const A = ratTex(ar);
  const cosPlain = m === 0 ? '' : m === 1 ? 'cos θ ' : `cos^${m} θ `;
  const pdfText = ['k', cosPowText(m), expText(ar)].filter(Boolean).join(' * ');
  const pdfTex = `p(\\omega) = k\\,${cosPowTex(m)}${expTex(ar)}`;
  const aIsOne = ar.p === 1 && ar.q === 1;
  const ans = q1Answers(P);
  const { mp1, E2, cosPow1Tex, kExactTex, pThetaTex, pPhiTex, cdfThetaTex, cdfPhiTex, thetaXiTex, phiXiTex } =
    q1Tex(P);
  const xi1 = 0.3;
  const xi2 = 0.7;
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
    { text: `Here e^(2πa) − 1 = ${formatSignificant(E, 6, 'e')}.` },
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
      text: `For example ξ₁ = ${xi1} gives θ = ${formatSignificant(c.thetaOfXi(xi1), 5, 'e')} rad and ξ₂ = ${xi2} gives φ = ${formatSignificant(c.phiOfXi(xi2), 5, 'e')} rad. Using 1 − ξ for ξ gives the same distribution.`,
    },
  ];
  const parts: Part[] = [
    {
      id: 'a',
      prompt: '(a) The normalization constant k (a number).',
      answers: [ans.k],
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
      answers: [ans.pTheta, ans.pPhi],
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
      answers: [ans.cdfTheta, ans.cdfPhi],
      hint: [
        {
          text: 'Integrate each marginal from 0 (the marginals of (b)), so that P(0) = 0; for θ substitute u = cos θ′:',
        },
        {
          tex: `P(\\theta) = \\int_0^{\\theta} p(\\theta')\\,d\\theta', \\qquad P(\\phi) = \\int_0^{\\phi} p(\\phi')\\,d\\phi'`,
        },
      ],
      steps: stepsC,
    },
    {
      id: 'd',
      prompt: '(d) θ and φ from uniform numbers (write ξ₁, ξ₂ as xi).',
      paperPrompt: '(d) The inversion formulas θ(ξ₁) and φ(ξ₂).',
      answers: [ans.thetaXi, ans.phiXi],
      hint: [
        { text: 'Set ξ₁ equal to P(θ) and solve for θ (and likewise ξ₂ = P(φ)):' },
        { tex: `\\xi_1 = P(\\theta) \\;\\Rightarrow\\; \\theta = P^{-1}(\\xi_1)` },
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
