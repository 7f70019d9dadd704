/**
 * Q4 variants: ∫ₐᵇ f dx for an integrand of the exam's kind, (x + c)², (x + c)³ or x² + c, positive
 * on [a, b], and four given samples. Expected answers:
 *   exact       I = F(b) − F(a) (closed form; the monte-carlo scene uses the same closed form for
 *               (x + c)² and adaptive Gauss–Kronrod otherwise, which agrees to ~1e-15)
 *   uniform     ⟨I⟩ = (1/N) Σ f(xᵢ)/p with p = 1/(b − a)    (core/estimators uniformEstimate)
 *   importance  ⟨I⟩ = (1/N) Σ f(xᵢ)/p(xᵢ) with p = f/I     (core/estimators importanceEstimate):
 *               every term equals I (zero variance)
 * Classic mistakes: F(a) not subtracted; the interval length (b − a) missing or multiplied in the
 * wrong place; p = f used without normalizing; f·p instead of f/p.
 */
import { formatSignificant } from '../core/format';
import { Rng } from '../core/random';
import { importanceEstimate, uniformEstimate } from '../core/estimators';
import { intIn, numberAnswer, pick, query } from './build';
import { closeTo, ownNumber } from './follow';
import { assembleSolution, roundTo, tn, type Part, type Variant } from './model';

type Kind = 'square' | 'cube' | 'quad';

export interface Q4Params {
  kind: Kind;
  c: number;
  a: number;
  b: number;
  samples: number[];
}

export function q4Params(seed: number): Q4Params {
  const rng = new Rng(seed, 0x5104);
  const kind = pick(rng, ['square', 'square', 'cube', 'quad'] as const);
  const c = kind === 'quad' ? pick(rng, [1, 2, 4]) : pick(rng, [1, 2, 3]);
  const a = pick(rng, [0, 0, 1]);
  const b = a + intIn(rng, 1, 3);
  const samples: number[] = [];
  while (samples.length < 4) {
    const x = roundTo(a + 0.01 + (b - a - 0.02) * rng.nextFloat(), 2);
    if (!samples.includes(x)) samples.push(x);
  }
  return { kind, c, a, b, samples };
}

export function q4Functions({ kind, c }: Pick<Q4Params, 'kind' | 'c'>) {
  switch (kind) {
    case 'square':
      return {
        f: (x: number) => (x + c) ** 2,
        F: (x: number) => (x + c) ** 3 / 3,
        Fexpanded: (x: number) => x ** 3 / 3 + c * x * x + c * c * x,
        text: `(x+${c})^2`,
        tex: `(x + ${c})^2`,
        Ftex: `\\frac{(x + ${c})^3}{3}`,
      };
    case 'cube':
      return {
        f: (x: number) => (x + c) ** 3,
        F: (x: number) => (x + c) ** 4 / 4,
        Fexpanded: (x: number) => x ** 4 / 4 + c * x ** 3 + 1.5 * c * c * x * x + c ** 3 * x,
        text: `(x+${c})^3`,
        tex: `(x + ${c})^3`,
        Ftex: `\\frac{(x + ${c})^4}{4}`,
      };
    default:
      return {
        f: (x: number) => x * x + c,
        F: (x: number) => x ** 3 / 3 + c * x,
        Fexpanded: (x: number) => x ** 3 / 3 + c * x,
        text: `x^2+${c}`,
        tex: `x^2 + ${c}`,
        Ftex: `\\frac{x^3}{3} + ${c}x`,
      };
  }
}

export function q4Expected(P: Q4Params) {
  const fn = q4Functions(P);
  const I = fn.F(P.b) - fn.F(P.a);
  const fv = P.samples.map(fn.f);
  const pv = fv.map((f) => f / I);
  const uniform = uniformEstimate(fv, P.a, P.b).estimate;
  const importance = importanceEstimate(fv, pv).estimate;
  return { fn, I, fv, pv, uniform, importance };
}

export function q4Variant(seed: number): Variant {
  const P = q4Params(seed);
  const { fn, I, fv, pv, uniform, importance } = q4Expected(P);
  const { a, b } = P;
  const L = b - a;
  const n = fv.length;
  const mean = (xs: number[]) => xs.reduce((s, x) => s + x, 0) / xs.length;
  const exact = numberAnswer(
    'exact',
    'exact I',
    I,
    [],
    [
      {
        id: 'no-lower-limit',
        value: fn.F(b),
        message: `F(a) was not subtracted: I = F(b) − F(a) with a = ${a}.`,
      },
      {
        id: 'no-lower-limit',
        value: fn.Fexpanded(b),
        message: `F(a) was not subtracted: I = F(b) − F(a) with a = ${a}.`,
      },
    ],
  );
  const uni = numberAnswer(
    'uniform',
    'uniform ⟨I⟩',
    uniform,
    [],
    [
      {
        id: 'no-interval-length',
        value: mean(fv),
        message: `Dividing by p = 1/(b − a) multiplies by b − a = ${L}: ⟨I⟩ = ((b − a)/N) Σ f(xᵢ).`,
      },
      {
        id: 'times-p',
        value: mean(fv) / L,
        message: `That multiplies by p = 1/(b − a) instead of dividing by it: ⟨I⟩ = (1/N) Σ f(xᵢ)/p.`,
      },
    ],
  );
  const imp = numberAnswer(
    'importance',
    'importance ⟨I⟩',
    importance,
    [],
    [
      {
        id: 'unnormalized-pdf',
        value: 1,
        message: 'p = f is not a density: it must integrate to 1, so p = f/I. Then every term f/p equals I.',
      },
      {
        id: 'f-times-p',
        value: mean(fv.map((f, i) => f * pv[i])),
        message: 'The estimator divides by the density: (1/N) Σ f/p, not f·p.',
      },
    ],
  );
  const den = P.kind === 'cube' ? 4 : 3;
  const numI = Math.round(I * den);
  const iTex =
    Math.abs(numI / den - I) < 1e-9 && numI % den !== 0 ? `\\frac{${numI}}{${den}} = ${tn(I)}` : tn(I);
  const fTable = `\\begin{array}{l} ${P.samples.map((x, i) => `f(${x}) = ${tn(fv[i])}`).join(' \\\\ ')} \\end{array}`;
  const parts: Part[] = [
    {
      id: 'a',
      prompt: `(a) I = ∫ f dx over [${a}, ${b}].`,
      answers: [exact],
      hint: [
        { text: 'Find an antiderivative F of f and evaluate it at both limits:' },
        { tex: `F(x) = ${fn.Ftex}, \\qquad I = F(${b}) - F(${a})` },
      ],
      steps: [
        { text: '(a) Exact integral by the antiderivative:' },
        {
          tex: `I = \\int_{${a}}^{${b}} ${fn.tex}\\,dx = \\Big[${fn.Ftex}\\Big]_{${a}}^{${b}} = ${tn(fn.F(b))} - ${tn(fn.F(a))} = ${iTex}`,
        },
      ],
    },
    {
      id: 'b',
      prompt: '(b) The uniform estimate.',
      answers: [uni],
      hint: [
        {
          text: `The uniform density on [${a}, ${b}] is p = 1/(b − a) = ${formatSignificant(1 / L, 6, 'e')}; evaluate f at each sample:`,
        },
        { tex: fTable },
      ],
      steps: [
        {
          text: `(b) Uniform density p = 1/(b − a) = ${formatSignificant(1 / L, 6, 'e')}; the samples give f(xᵢ):`,
        },
        { tex: fTable },
        {
          tex: `\\begin{aligned} \\langle I\\rangle &= \\frac{1}{${n}}\\sum \\frac{f(x_i)}{p} = \\frac{${L}}{${n}}\\sum f(x_i) \\\\ &= \\frac{${L}}{${n}}\\,(${fv.map((x) => tn(x)).join(' + ')}) \\\\ &= ${tn(uniform)} \\end{aligned}`,
        },
        {
          text: `The exact value is I = ${formatSignificant(I, 6, 'e')}: this estimate is off by ${formatSignificant(Math.abs(uniform - I), 3, 'e')}.`,
        },
      ],
    },
    {
      id: 'c',
      prompt: '(c) The importance-sampled estimate with p ∝ f.',
      answers: [imp],
      hint: [
        {
          text: 'A density must integrate to 1 over the interval: p(x) = f(x) / ∫ f dx. Write each term f(xᵢ)/p(xᵢ) with it.',
        },
      ],
      steps: [
        {
          text: `(c) Importance sampling with p(x) = f(x)/I = ${fn.text}/${formatSignificant(I, 6, 'e')}, proportional to f:`,
        },
        { tex: `\\frac{f(x_i)}{p(x_i)} = \\frac{f(x_i)}{f(x_i)/I} = I = ${tn(I)}\\ \\text{for every } i` },
        { tex: `\\langle I\\rangle = ${tn(importance)}\\ \\text{(zero variance)}` },
      ],
    },
  ];
  imp.follow = [
    {
      from: ['exact'],
      matches: (own, val) => {
        const Is = ownNumber(own, 'exact');
        return typeof Is === 'number' && Is !== 0 && closeTo(val, Is);
      },
    },
  ];
  exact.tex = `I = ${iTex}`;
  uni.tex = `\\langle I\\rangle_{\\text{uniform}} = ${tn(uniform)}`;
  imp.tex = `\\langle I\\rangle_{\\text{importance}} = I = ${tn(importance)}`;
  return {
    question: 'q4',
    seed,
    title: 'Monte Carlo integration in 1D',
    statement: `Let f(x) = ${fn.text} on [${a}, ${b}], and the samples x = ${P.samples.join(', ')}. (a) The exact integral I. (b) The uniform Monte Carlo estimate with these samples. (c) The importance-sampled estimate with p(x) ∝ f(x), with the same samples.`,
    givens: [
      { name: 'f', label: 'f(x)', value: fn.text, display: fn.text, tex: `f(x) = ${fn.tex}` },
      { name: 'a', label: 'a', value: String(a), display: String(a) },
      { name: 'b', label: 'b', value: String(b), display: String(b) },
      { name: 'samples', label: 'samples xᵢ', value: P.samples.join(','), display: P.samples.join(', ') },
    ],
    parts,
    intro: [],
    solution: assembleSolution([], parts),
    sceneHref: `#/monte-carlo?${query({ f: fn.text, a, b, samples: P.samples.join(','), pdf: 'proportional' })}`,
    sceneLabel: 'Open this integral and these samples in the Monte Carlo scene',
    notes: [],
  };
}
