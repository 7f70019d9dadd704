/**
 * Q2 variants: the two Monte Carlo estimators of ∫ f dω over the upper hemisphere, evaluated on four
 * given directions (θᵢ, φᵢ), with the density p(ω) = k cosᵐθ e^(aφ) of Q1's family:
 *
 *   uniform     ⟨I⟩ = (2π/N) Σ f(θᵢ, φᵢ)          (|D| = 2π, p = 1/2π)
 *   importance  ⟨I⟩ = (1/N) Σ f(θᵢ, φᵢ) / p(ωᵢ)    (p per steradian, not p(θ, φ))
 *
 * The terms are summed by the core's estimator (core/estimators estimateFromTerms, as the
 * hemisphere scene does). Which estimator has zero variance: importance when f ∝ p, uniform when f
 * is constant, else neither.
 * Classic mistakes: no |D| = 2π (or 4π, the whole sphere); f·p instead of f/p; dividing by
 * p(θ, φ) = p(ω) sin θ (the measure of θ, φ) instead of p(ω); p without its k.
 */
import { formatSignificant } from '../core/format';
import { Rng } from '../core/random';
import { estimateFromTerms } from '../core/estimators';
import { choiceAnswer, numberAnswer, pick, query } from './build';
import { argTex, argText, expPlain } from './q1Text';
import {
  assembleSolution,
  ratValue,
  roundTo,
  tn,
  tp,
  type Part,
  type Rational,
  type SolutionStep,
  type Variant,
} from './model';

type FKind = 'const' | 'prop' | 'cos' | 'cos2';

export interface Q2Params {
  m: number;
  a: Rational;
  fKind: FKind;
  /** Coefficient of f (constant value, or the multiple of cosᵐθ e^(aφ)). */
  C: number;
  dirs: [number, number][];
}

export function q2Params(seed: number): Q2Params {
  const rng = new Rng(seed, 0x5102);
  const m = pick(rng, [1, 1, 2]);
  const a = pick(rng, [
    { p: 1, q: 1 },
    { p: 1, q: 2 },
    { p: -1, q: 2 },
    { p: -1, q: 1 },
  ] as Rational[]);
  const fKind = pick(rng, ['const', 'prop', 'cos', 'cos2'] as const);
  const C = pick(rng, [1, 2, 3]);
  const dirs: [number, number][] = [];
  while (dirs.length < 4) {
    const t = roundTo(0.1 + 1.35 * rng.nextFloat(), 2);
    const f = roundTo(0.05 + 6.15 * rng.nextFloat(), 2);
    if (dirs.some(([tt, ff]) => tt === t && ff === f)) continue;
    dirs.push([t, f]);
  }
  return { m, a, fKind, C, dirs };
}

export function q2Functions({ m, a: ar, fKind, C }: Q2Params) {
  const a = ratValue(ar);
  const k = (a * (m + 1)) / Math.expm1(2 * Math.PI * a);
  const shape = (t: number, f: number) => Math.cos(t) ** m * Math.exp(a * f);
  const p = (t: number, f: number) => k * shape(t, f);
  let f: (t: number, ph: number) => number;
  let fText: string;
  let fTex: string;
  const cosT = m === 1 ? 'cos(theta)' : `cos(theta)^${m}`;
  const cosX = m === 1 ? '\\cos\\theta' : `\\cos^{${m}}\\theta`;
  const expT = `exp(${argText(ar)})`;
  const expX = `e^{${argTex(ar)}}`;
  const cosPlain = m === 1 ? 'cos θ' : `cos^${m} θ`;
  switch (fKind) {
    case 'const':
      f = () => C;
      fText = String(C);
      fTex = String(C);
      break;
    case 'prop':
      f = (t, ph) => C * shape(t, ph);
      fText = `${C === 1 ? '' : `${C} * `}${cosT} * ${expT}`;
      fTex = `${C === 1 ? '' : C}${cosX}\\,${expX}`;
      break;
    case 'cos':
      f = (t) => C * Math.cos(t);
      fText = `${C === 1 ? '' : `${C} * `}cos(theta)`;
      fTex = `${C === 1 ? '' : C}\\cos\\theta`;
      break;
    default:
      f = (t) => C * Math.cos(t) ** 2;
      fText = `${C === 1 ? '' : `${C} * `}cos(theta)^2`;
      fTex = `${C === 1 ? '' : C}\\cos^2\\theta`;
  }
  const fPlain = fText
    .replace(/cos\(theta\)\^(\d)/g, 'cos^$1 θ')
    .replace(/cos\(theta\)/g, 'cos θ')
    .replace(/ \* /g, ' ')
    .replace(/exp\([^)]*\)/, expPlain(ar));
  return {
    a,
    k,
    p,
    f,
    fText,
    fTex,
    fPlain,
    pText: `${cosT} * ${expT}`,
    pPlain: `k ${cosPlain} ${expPlain(ar)}`,
    pTex: `k\\,${cosX}\\,${expX}`,
  };
}

/** Both estimates from the given directions, by the core's estimator over per-direction terms. */
export function q2Estimates(P: Q2Params) {
  const F = q2Functions(P);
  const n = P.dirs.length;
  const uni = new Float64Array(n);
  const imp = new Float64Array(n);
  const fv: number[] = [];
  const pv: number[] = [];
  P.dirs.forEach(([t, ph], i) => {
    const f = F.f(t, ph);
    const p = F.p(t, ph);
    fv.push(f);
    pv.push(p);
    uni[i] = 2 * Math.PI * f;
    imp[i] = f / p;
  });
  return { F, fv, pv, uniform: estimateFromTerms(uni).estimate, importance: estimateFromTerms(imp).estimate };
}

/** ∫ f dω over the upper hemisphere, in closed form: 2πC, πC, 2πC/3, or C/k for f ∝ p. */
export function q2TrueValue(P: Q2Params, k: number): { value: number; tex: string; how: string } {
  const C = P.C;
  const c = C === 1 ? '' : String(C);
  switch (P.fKind) {
    case 'const':
      return { value: 2 * Math.PI * C, tex: `${2 * C}\\pi`, how: `${C} · 2π` };
    case 'cos':
      return { value: Math.PI * C, tex: `${c}\\pi`, how: `${c ? `${C} · ` : ''}∫ cos θ dω = ${c}π` };
    case 'cos2':
      return {
        value: (2 * Math.PI * C) / 3,
        tex: `\\frac{${2 * C}\\pi}{3}`,
        how: `${c ? `${C} · ` : ''}∫ cos² θ dω = ${2 * C}π/3`,
      };
    default:
      return {
        value: C / k,
        tex: `\\frac{${C}}{k}`,
        how: `${C}/k (p integrates to 1, so ∫ cosᵐθ e^(aφ) dω = 1/k)`,
      };
  }
}

export function q2Variant(seed: number): Variant {
  const P = q2Params(seed);
  const { F, fv, pv, uniform, importance } = q2Estimates(P);
  const n = P.dirs.length;
  const sumF = fv.reduce((s, x) => s + x, 0);
  const mean = (xs: number[]) => xs.reduce((s, x) => s + x, 0) / xs.length;
  const sinT = P.dirs.map(([t]) => Math.sin(t));
  const zero = P.fKind === 'prop' ? 'importance' : P.fKind === 'const' ? 'uniform' : 'neither';
  const why =
    zero === 'importance'
      ? 'Here f ∝ p, so every term f/p equals the same constant ∫ f dω: zero variance. The uniform terms 2π f vary with the direction.'
      : zero === 'uniform'
        ? 'Here f is constant, so every uniform term 2π f is the same: zero variance. The importance terms f/p vary because p does.'
        : 'Here f is neither constant nor proportional to p, so both estimators’ terms vary from direction to direction.';
  const uniAns = numberAnswer(
    'mc-uniform',
    'uniform ⟨I⟩',
    uniform,
    [],
    [
      {
        id: 'no-2pi',
        value: sumF / n,
        message:
          'The factor |D| = 2π is missing: uniform sampling of the hemisphere has p = 1/(2π), so ⟨I⟩ = (2π/N) Σ f.',
      },
      {
        id: 'sphere-4pi',
        value: (4 * Math.PI * sumF) / n,
        message: 'That is 4π, the solid angle of the whole sphere; the hemisphere has |D| = 2π.',
      },
    ],
  );
  const impAns = numberAnswer(
    'mc-importance',
    'importance ⟨I⟩',
    importance,
    [],
    [
      {
        id: 'f-times-p',
        value: mean(fv.map((f, i) => f * pv[i])),
        message: 'The estimator divides by the density: (1/N) Σ f/p, not f·p.',
      },
      {
        id: 'theta-phi-density',
        value: mean(fv.map((f, i) => f / (pv[i] * sinT[i]))),
        message:
          'You divided by p(θ, φ) = p(ω) sin θ. The integral is over solid angle (dω), so divide by p(ω), the density per steradian.',
      },
      {
        id: 'pdf-without-k',
        value: mean(fv.map((f, i) => f / (pv[i] / F.k))),
        message: 'The density lost its normalization constant k: divide by the full p(ω) = k cosᵐθ e^(aφ).',
      },
    ],
  );
  const zeroAns = choiceAnswer(
    'zero-variance',
    'zero variance',
    ['uniform', 'importance', 'neither'],
    zero,
    [],
    why,
  );
  const rows = P.dirs.map(
    ([t, ph], i) =>
      `(${formatSignificant(t, 6, 'e')}, ${formatSignificant(ph, 6, 'e')}) & ${tn(fv[i])} & ${tn(pv[i])} & ${tn(fv[i] / pv[i])}`,
  );
  const { value: trueI, tex: trueTex, how: trueHow } = q2TrueValue(P, F.k);
  const intro: SolutionStep[] = [
    {
      text: `Per direction (θᵢ, φᵢ): f(ωᵢ), p(ωᵢ) = ${F.pPlain} with k = ${formatSignificant(F.k, 6, 'e')}, and f/p:`,
    },
    {
      tex: `\\begin{array}{cccc} (\\theta_i,\\phi_i) & f & p & f/p \\\\ \\hline ${rows.join(' \\\\ ')} \\end{array}`,
    },
  ];
  const uniformSum = `\\frac{2\\pi}{${n}}\\,(${fv.map((x) => tn(x)).join(' + ')})`;
  const impSum = `\\frac{1}{${n}}\\,(${fv.map((x, i) => tp(x / pv[i])).join(' + ')})`;
  const trueStep = (est: number): SolutionStep => ({
    text: `The true value is ∫ f dω = ${trueHow} = ${formatSignificant(trueI, 6, 'e')}; this estimate from ${n} directions is ${formatSignificant(est, 6, 'e')} (${Math.abs(est - trueI) <= 1e-9 * Math.abs(trueI) ? 'exact: every term is the same' : `off by ${formatSignificant(Math.abs(est - trueI), 3, 'e')}`}).`,
    tex: `\\int f\\,d\\omega = ${trueTex} = ${tn(trueI)}`,
  });
  const parts: Part[] = [
    {
      id: 'a',
      prompt: '(a) The uniform estimate (2π/N) Σ f.',
      answers: [uniAns],
      hint: [
        { text: 'Uniform over the hemisphere means p = 1/|D| = 1/(2π); sum f over the directions:' },
        { tex: `\\langle I\\rangle = \\frac{1}{N}\\sum \\frac{f(X_i)}{1/(2\\pi)} = ${uniformSum}` },
      ],
      steps: [
        { text: '(a) Uniform sampling of the hemisphere, p = 1/|D| = 1/(2π):' },
        {
          tex: `\\begin{aligned} \\langle I\\rangle &= \\frac{2\\pi}{N}\\sum f(X_i) \\\\ &= ${uniformSum} \\\\ &= ${tn(uniform)} \\end{aligned}`,
        },
        trueStep(uniform),
      ],
    },
    {
      id: 'b',
      prompt: '(b) The importance-sampled estimate (1/N) Σ f/p.',
      answers: [impAns],
      hint: [
        {
          text: 'Divide each f(ωᵢ) by the density per steradian p(ωᵢ) of the same direction, then average the N terms:',
        },
        { tex: `\\langle I\\rangle = \\frac{1}{N}\\sum_{i=1}^{N} \\frac{f(X_i)}{p(X_i)}` },
      ],
      steps: [
        { text: '(b) Importance sampling with p(ω), the density per steradian:' },
        {
          tex: `\\begin{aligned} \\langle I\\rangle &= \\frac{1}{N}\\sum \\frac{f(X_i)}{p(X_i)} \\\\ &= ${impSum} \\\\ &= ${tn(importance)} \\end{aligned}`,
        },
        trueStep(importance),
      ],
    },
    {
      id: 'c',
      prompt: '(c) Which has zero variance for this f: uniform, importance or neither?',
      paperPrompt: '(c) Which estimator has zero variance for this f: uniform, importance or neither? Why?',
      answers: [zeroAns],
      hint: [
        {
          text: 'An estimator has zero variance when all its terms are the same number: compare the terms 2π f and f/p from direction to direction.',
        },
      ],
      steps: [
        { text: `(c) ${why}` },
        {
          text: 'Both estimators are unbiased (the key’s proof: linearity of E, then E[g(X)] = ∫ g p dω), for any p > 0 where f ≠ 0:',
        },
        {
          tex: `\\begin{aligned} E[\\langle I\\rangle] &= E\\Big[\\frac{1}{N}\\sum_{i=1}^N \\frac{f(X_i)}{p(X_i)}\\Big] = \\frac{1}{N}\\sum_{i=1}^N E\\Big[\\frac{f(X_i)}{p(X_i)}\\Big] \\\\ &= \\frac{1}{N}\\sum_{i=1}^N \\int \\frac{f(\\omega)}{p(\\omega)}\\,p(\\omega)\\,d\\omega = \\int f\\,d\\omega = ${trueTex} \\end{aligned}`,
        },
      ],
    },
  ];
  uniAns.tex = `\\langle I\\rangle_{\\text{uniform}} = ${tn(uniform)}`;
  impAns.tex = `\\langle I\\rangle_{\\text{importance}} = ${tn(importance)}`;
  zeroAns.tex = `\\text{${zero}}`;
  const dirValue = P.dirs.map(([t, ph]) => `${t},${ph}`).join(';');
  return {
    question: 'q2',
    seed,
    title: 'Monte Carlo estimators on the hemisphere',
    statement: `Estimate ∫ f dω over the upper hemisphere with f(θ, φ) = ${F.fPlain}, from the ${n} directions (θᵢ, φᵢ) below (radians). (a) Treat them as drawn uniformly over the hemisphere: the uniform estimate. (b) Treat them as drawn from p(ω) = ${F.pPlain} with k = ${formatSignificant(F.k, 6, 'e')}: the importance-sampled estimate. (c) Which estimator has zero variance for this f?`,
    givens: [
      { name: 'f', label: 'f(θ, φ)', value: F.fText, display: F.fText, tex: `f(\\theta,\\phi) = ${F.fTex}` },
      {
        name: 'pdf',
        label: 'p(ω) per steradian',
        value: `k * ${F.pText}`,
        display: `k · ${F.pText}`,
        tex: `p(\\omega) = ${F.pTex}`,
      },
      { name: 'k', label: 'k', value: String(F.k), display: formatSignificant(F.k, 6, 'e') },
      {
        name: 'directions',
        label: 'directions (θ, φ), radians',
        value: dirValue,
        display: P.dirs.map(([t, ph]) => `(${t}, ${ph})`).join('  '),
      },
    ],
    parts,
    intro,
    solution: assembleSolution(intro, parts),
    sceneHref: `#/hemisphere?${query({ lobe: 'custom', pdf: F.pText.replace(/ /g, ''), f: F.fText.replace(/ /g, '') })}`,
    sceneLabel: 'Open this density and integrand in the hemisphere scene',
    notes: [
      'The scene draws its own directions (many of them); its estimates converge to ∫ f dω rather than reproduce these four.',
    ],
  };
}
