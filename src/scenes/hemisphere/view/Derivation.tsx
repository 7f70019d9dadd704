/**
 * The derivation panel: Q1 step by step for the chosen lobe, with the live numbers from the core.
 * For a typed density the steps are numerical (tabulated) and say so.
 */
import { MathTex, formatNumber } from '../../../ui';
import type { TabulatedHemisphere } from '../../../core/sampling';
import { examNumbers } from '../model';
import type { LobeId } from '../params';

const n6 = (x: number) => formatNumber(x, 6).replace('×10', '\\times 10^{').replace(/([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)/, (m) => `${fromSup(m)}}`);
function fromSup(s: string): string {
  const map: Record<string, string> = { '⁻': '-', '⁰': '0', '¹': '1', '²': '2', '³': '3', '⁴': '4', '⁵': '5', '⁶': '6', '⁷': '7', '⁸': '8', '⁹': '9' };
  return [...s].map((c) => map[c] ?? c).join('');
}

function Step({ n, title, tex, children }: { n: number; title: string; tex: string | string[]; children?: React.ReactNode }) {
  return (
    <li className="deriv-step">
      <h3>
        {n}. {title}
      </h3>
      {(Array.isArray(tex) ? tex : [tex]).map((t, i) => (
        // a focusable scroll box: a wide formula scrolls sideways on a phone, also from the keyboard
        <div key={i} className="deriv-formula" tabIndex={0} role="group" aria-label={`${title}, formula ${i + 1}`}>
          <MathTex tex={t} display />
        </div>
      ))}
      {children ? <p>{children}</p> : null}
    </li>
  );
}

export function Derivation({ lobe, exponent, custom, customTex, inverted }: { lobe: LobeId; exponent: number; custom: TabulatedHemisphere | null; customTex: string | null; inverted: boolean }) {
  if (lobe === 'exam') {
    const e = examNumbers();
    const ex = e.example;
    return (
      <ol className="derivation" data-testid="derivation">
        <Step
          n={1}
          title="Normalize over solid angle (Q1a)"
          tex={[
            `\\begin{aligned}\\int_\\Omega p(\\omega)\\,d\\omega &= k\\int_0^{\\pi/2}\\!\\cos\\theta\\sin\\theta\\,d\\theta\\int_0^{2\\pi}\\!e^{\\phi}\\,d\\phi \\\\ &= k\\cdot\\tfrac12\\cdot(e^{2\\pi}-1) = 1\\end{aligned}`,
            `k = \\frac{2}{e^{2\\pi}-1} = \\frac{2}{${n6(e.e2piMinus1)}} = ${n6(e.k)}`,
          ]}
        >
          dω = sin θ dθ dφ: the extra sin θ is the area of a thin ring of directions. k is computed as 2/expm1(2π).
        </Step>
        <Step
          n={2}
          title="Change of variables (Q1b)"
          tex={
            inverted
              ? [`p(\\theta,\\phi) = \\sin\\theta\\,p(\\omega) = k\\sin\\theta\\cos\\theta\\,e^{\\phi}`, `\\cancel{p(\\theta,\\phi) = p(\\omega)/\\sin\\theta = k\\cot\\theta\\,e^{\\phi}}\\quad\\text{(the key's upside-down variant: see below)}`]
              : `p(\\theta,\\phi) = \\sin\\theta\\,p(\\omega) = k\\sin\\theta\\cos\\theta\\,e^{\\phi}`
          }
        >
          Probability is conserved: p(θ, φ) dθ dφ = p(ω) dω, and dω = sin θ dθ dφ.
        </Step>
        <Step
          n={3}
          title="Marginals"
          tex={[
            `\\begin{aligned}p(\\theta) &= \\int_0^{2\\pi} p(\\theta,\\phi)\\,d\\phi \\\\ &= k\\sin\\theta\\cos\\theta\\,(e^{2\\pi}-1) = \\sin 2\\theta\\end{aligned}`,
            `\\begin{aligned}p(\\phi) &= \\int_0^{\\pi/2} p(\\theta,\\phi)\\,d\\theta = \\frac{k}{2}e^{\\phi} \\\\ &= \\frac{e^{\\phi}}{e^{2\\pi}-1}, \\qquad \\tfrac{k}{2} = ${n6(e.halfK)}\\end{aligned}`,
          ]}
        >
          The density is separable, p(θ, φ) = p(θ) p(φ), so θ and φ can be sampled independently. (The key's intermediate line for p(θ)
          keeps a stray e^φ inside the integral over φ; its result, sin 2θ, is right.)
        </Step>
        <Step n={4} title="CDFs (Q1c)" tex={[`P(\\theta) = \\int_0^{\\theta}\\sin 2t\\,dt = \\frac{1-\\cos 2\\theta}{2} = \\sin^2\\theta`, `P(\\phi) = \\frac{e^{\\phi}-1}{e^{2\\pi}-1}`]} />
        <Step
          n={5}
          title="Invert (Q1d)"
          tex={[
            `\\theta = \\tfrac12\\arccos(1-2\\xi_1) = \\arcsin\\sqrt{\\xi_1}`,
            `\\phi = \\ln\\big((e^{2\\pi}-1)\\xi_2+1\\big)`,
            `\\sin\\theta = \\sqrt{\\xi_1},\\quad \\cos\\theta = \\sqrt{1-\\xi_1}`,
            `\\phi = \\operatorname{log1p}\\big(\\operatorname{expm1}(2\\pi)\\,\\xi_2\\big)`,
          ]}
        >
          The second line is what the code runs: from cos 2θ = 1 − 2ξ₁ the half-angle identities give sin²θ = ξ₁ and cos²θ = 1 − ξ₁, so no
          arccos is needed and both stay accurate for tiny and near-1 ξ (see the stability panel).
        </Step>
        <Step
          n={6}
          title="Worked example"
          tex={[
            `\\xi = (${ex.xi1}, ${ex.xi2})\\;\\mapsto\\; \\theta = ${n6(ex.theta)},\\ \\phi = ${n6(ex.phi)}`,
            `\\omega = (${n6(ex.sinTheta * Math.cos(ex.phi))},\\ ${n6(ex.sinTheta * Math.sin(ex.phi))},\\ ${n6(ex.cosTheta)})`,
          ]}
        />
      </ol>
    );
  }
  if (lobe === 'uniform')
    return (
      <ol className="derivation" data-testid="derivation">
        <Step n={1} title="Normalize" tex={`\\int_\\Omega k\\,d\\omega = 2\\pi k = 1 \\Rightarrow k = \\frac{1}{2\\pi} = ${n6(1 / (2 * Math.PI))}`} />
        <Step n={2} title="Change of variables and marginals" tex={[`p(\\theta,\\phi) = \\frac{\\sin\\theta}{2\\pi}`, `p(\\theta) = \\sin\\theta,\\quad p(\\phi) = \\frac{1}{2\\pi}`]} />
        <Step n={3} title="CDFs and inversion" tex={[`P(\\theta) = 1-\\cos\\theta \\;\\Rightarrow\\; \\cos\\theta = 1-\\xi_1 \\sim \\xi_1`, `\\phi = 2\\pi\\xi_2`]}>
          1 − ξ₁ has the same distribution as ξ₁, so the code uses cos θ = ξ₁ (pbrt-v4 A.5.2).
        </Step>
      </ol>
    );
  if (lobe === 'cosine')
    return (
      <ol className="derivation" data-testid="derivation">
        <Step n={1} title="Normalize" tex={[`k\\int_\\Omega \\cos\\theta\\,d\\omega = k\\pi = 1`, `k = \\frac1\\pi = ${n6(1 / Math.PI)}`]} />
        <Step n={2} title="Marginals" tex={`p(\\theta) = \\sin 2\\theta,\\quad p(\\phi) = \\frac{1}{2\\pi}`}>
          The same θ-marginal as the exam lobe: the exam lobe is the cosine lobe with φ reweighted by e^φ.
        </Step>
        <Step n={3} title="Malley's method" tex={[`(x, y) \\sim \\text{uniform on the unit disk}`, `z = \\sqrt{1-x^2-y^2}`]}>
          Projecting a uniform disk point up onto the hemisphere gives density cos θ/π. The disk is sampled with Shirley and Chiu&apos;s
          concentric map, which keeps the warped grid well shaped (pbrt-v4 A.5.3).
        </Step>
      </ol>
    );
  if (lobe === 'phong')
    return (
      <ol className="derivation" data-testid="derivation">
        <Step n={1} title="Normalize" tex={[`k\\int_\\Omega \\cos^{n}\\theta\\,d\\omega = \\frac{2\\pi k}{n+1} = 1`, `k = \\frac{n+1}{2\\pi} = ${n6((exponent + 1) / (2 * Math.PI))}\\quad (n = ${exponent})`]} />
        <Step n={2} title="Marginal and CDF" tex={[`p(\\theta) = (n+1)\\cos^{n}\\theta\\sin\\theta`, `P(\\theta) = 1-\\cos^{n+1}\\theta`]} />
        <Step n={3} title="Inversion" tex={[`\\cos\\theta = \\xi_1^{1/(n+1)} = \\exp\\!\\Big(\\frac{\\ln\\xi_1}{n+1}\\Big)`, `\\sin\\theta = \\sqrt{-\\operatorname{expm1}\\!\\Big(\\frac{2\\ln\\xi_1}{n+1}\\Big)},\\quad \\phi = 2\\pi\\xi_2`]}>
          Computed in log space so a large exponent does not lose sin θ to cancellation.
        </Step>
      </ol>
    );
  // custom
  return (
    <ol className="derivation" data-testid="derivation">
      <li className="deriv-step">
        <p>
          <strong>Numerical steps.</strong> A typed density has no closed-form integral in general, so each step below is done on a table.
        </p>
      </li>
      <Step
        n={1}
        title="Normalize (numerically)"
        tex={
          custom
            ? [`p(\\theta,\\phi) = ${customTex ?? '\\text{(typed)}'}`, `\\int_\\Omega p\\,d\\omega \\approx ${n6(custom.integral)} \\;\\Rightarrow\\; k \\approx ${n6(custom.k)}`]
            : `\\int_\\Omega p\\,d\\omega = \\;?`
        }
      >
        The hemisphere is cut into {custom ? `${custom.nz} × ${custom.nphi}` : '64 × 128'} cells of equal solid angle (equal steps in cos θ and φ, since dω = d(cos θ) dφ);
        p is taken at each cell centre.
      </Step>
      <Step n={2} title="Marginal of cos θ, conditional of φ" tex={[`p(\\cos\\theta) = \\int_0^{2\\pi} p\\,d\\phi`, `p(\\phi\\mid\\theta) = \\frac{p(\\theta,\\phi)}{p(\\cos\\theta)}`]}>
        The density need not be separable, so φ is drawn from the conditional of the row that θ fell in (pbrt-v4 PiecewiseConstant2D).
      </Step>
      <Step n={3} title="Invert the tabulated CDFs" tex={[`\\cos\\theta = P_{\\cos\\theta}^{-1}(\\xi_1)`, `\\phi = P_{\\phi\\mid\\theta}^{-1}(\\xi_2)`]}>
        Each CDF is a running sum over the table, inverted by binary search and linear interpolation within the cell.
      </Step>
    </ol>
  );
}
