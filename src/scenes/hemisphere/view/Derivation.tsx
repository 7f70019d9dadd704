/**
 * The derivation of a lobe other than the exam's (whose derivation is the exam section, exam/Q1.tsx),
 * with the live numbers from the core.
 * For a typed density the steps are numerical (tabulated) and say so.
 */
import { useRef, type ReactNode } from 'react';
import { MathTex, formatNumber } from '../../../ui';
import { unsuperscript } from '../../../ui/axis';
import type { TabulatedHemisphere } from '../../../core/sampling';
import type { LobeId } from '../params';
import { useScrollBoxFocus } from './scrollFocus';

const n6 = (x: number) =>
  formatNumber(x, 6)
    .replace('×10', '\\times 10^{')
    .replace(/([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)/, (m) => `${unsuperscript(m)}}`);

/** One numbered step: its title, its formulas (each in a scroll box) and a line of prose. */
interface StepData {
  title: string;
  tex: string | string[];
  note?: ReactNode;
}

function Step({ n, title, tex, note }: StepData & { n: number }) {
  return (
    <li className="deriv-step">
      <h3>
        {n}. {title}
      </h3>
      {(Array.isArray(tex) ? tex : [tex]).map((t, i) => (
        // a scroll box: a wide formula scrolls sideways on a phone, then also from the keyboard
        <div key={i} className="deriv-formula" role="group" aria-label={`${title}, formula ${i + 1}`}>
          <MathTex tex={t} display />
        </div>
      ))}
      {note ? <p>{note}</p> : null}
    </li>
  );
}

const UNIFORM_STEPS: StepData[] = [
  {
    title: 'Normalize',
    tex: `\\int_\\Omega k\\,d\\omega = 2\\pi k = 1 \\Rightarrow k = \\frac{1}{2\\pi} = ${n6(1 / (2 * Math.PI))}`,
  },
  {
    title: 'Change of variables and marginals',
    tex: [
      `p(\\theta,\\phi) = \\frac{\\sin\\theta}{2\\pi}`,
      `p(\\theta) = \\sin\\theta,\\quad p(\\phi) = \\frac{1}{2\\pi}`,
    ],
  },
  {
    title: 'CDFs and inversion',
    tex: [
      `P(\\theta) = 1-\\cos\\theta \\;\\Rightarrow\\; \\cos\\theta = 1-\\xi_1 \\sim \\xi_1`,
      `\\phi = 2\\pi\\xi_2`,
    ],
    note: '1 − ξ₁ has the same distribution as ξ₁, so the code uses cos θ = ξ₁ (pbrt-v4 A.5.2).',
  },
];

const COSINE_STEPS: StepData[] = [
  {
    title: 'Normalize',
    tex: [`k\\int_\\Omega \\cos\\theta\\,d\\omega = k\\pi = 1`, `k = \\frac1\\pi = ${n6(1 / Math.PI)}`],
  },
  {
    title: 'Marginals',
    tex: `p(\\theta) = \\sin 2\\theta,\\quad p(\\phi) = \\frac{1}{2\\pi}`,
    note: (
      <>
        The same θ-marginal as the exam lobe: the exam lobe is the cosine lobe with φ reweighted by e
        <sup>φ</sup>.
      </>
    ),
  },
  {
    title: "Malley's method",
    tex: [`(x, y) \\sim \\text{uniform on the unit disk}`, `z = \\sqrt{1-x^2-y^2}`],
    note:
      'Projecting a uniform disk point up onto the hemisphere gives density cos θ/π. The disk is sampled ' +
      "with Shirley and Chiu's concentric map, which keeps the warped grid well shaped (pbrt-v4 A.5.3).",
  },
];

const phongSteps = (exponent: number): StepData[] => [
  {
    title: 'Normalize',
    tex: [
      `k\\int_\\Omega \\cos^{n}\\theta\\,d\\omega = \\frac{2\\pi k}{n+1} = 1`,
      `k = \\frac{n+1}{2\\pi} = ${n6((exponent + 1) / (2 * Math.PI))}\\quad (n = ${exponent})`,
    ],
  },
  {
    title: 'Marginal and CDF',
    tex: [`p(\\theta) = (n+1)\\cos^{n}\\theta\\sin\\theta`, `P(\\theta) = 1-\\cos^{n+1}\\theta`],
  },
  {
    title: 'Inversion',
    tex: [
      `\\cos\\theta = \\xi_1^{1/(n+1)} = \\exp\\!\\Big(\\frac{\\ln\\xi_1}{n+1}\\Big)`,
      `\\sin\\theta = \\sqrt{-\\operatorname{expm1}\\!\\Big(\\frac{2\\ln\\xi_1}{n+1}\\Big)},\\quad \\phi = 2\\pi\\xi_2`,
    ],
    note: 'Computed in log space so a large exponent does not lose sin θ to cancellation.',
  },
];

const customSteps = (custom: TabulatedHemisphere | null, customTex: string | null): StepData[] => [
  {
    title: 'Normalize (numerically)',
    tex: custom
      ? [
          `p(\\theta,\\phi) = ${customTex ?? '\\text{(typed)}'}`,
          `\\int_\\Omega p\\,d\\omega \\approx ${n6(custom.integral)} \\;\\Rightarrow\\; k \\approx ${n6(custom.k)}`,
        ]
      : `\\int_\\Omega p\\,d\\omega = \\;?`,
    note:
      `The hemisphere is cut into ${custom ? `${custom.nz} × ${custom.nphi}` : '64 × 128'} cells of equal ` +
      'solid angle (equal steps in cos θ and φ, since dω = d(cos θ) dφ); p is taken at each cell centre.',
  },
  {
    title: 'Marginal of cos θ, conditional of φ',
    tex: [
      `p(\\cos\\theta) = \\int_0^{2\\pi} p\\,d\\phi`,
      `p(\\phi\\mid\\theta) = \\frac{p(\\theta,\\phi)}{p(\\cos\\theta)}`,
    ],
    note:
      'The density need not be separable, so φ is drawn from the conditional of the row that θ fell in ' +
      '(pbrt-v4 PiecewiseConstant2D).',
  },
  {
    title: 'Invert the tabulated CDFs',
    tex: [`\\cos\\theta = P_{\\cos\\theta}^{-1}(\\xi_1)`, `\\phi = P_{\\phi\\mid\\theta}^{-1}(\\xi_2)`],
    note:
      'Each CDF is a running sum over the table, inverted by binary search and linear interpolation ' +
      'within the cell.',
  },
];

export function Derivation({
  lobe,
  exponent,
  custom,
  customTex,
}: {
  lobe: LobeId;
  exponent: number;
  custom: TabulatedHemisphere | null;
  customTex: string | null;
}) {
  const list = useRef<HTMLOListElement>(null);
  useScrollBoxFocus(list, `${lobe} ${exponent} ${customTex ?? ''}`);
  // the exam lobe's derivation is written out part by part in the exam section (exam/Q1.tsx)
  if (lobe === 'exam') return null;
  const steps =
    lobe === 'uniform'
      ? UNIFORM_STEPS
      : lobe === 'cosine'
        ? COSINE_STEPS
        : lobe === 'phong'
          ? phongSteps(exponent)
          : customSteps(custom, customTex);
  return (
    <ol className="derivation" data-testid="derivation" ref={list}>
      {lobe === 'custom' ? (
        <li className="deriv-step">
          <p>
            <strong>Numerical steps.</strong> A typed density has no closed-form integral in general, so each
            step below is done on a table.
          </p>
        </li>
      ) : null}
      {steps.map((s, i) => (
        <Step key={s.title} n={i + 1} {...s} />
      ))}
    </ol>
  );
}
