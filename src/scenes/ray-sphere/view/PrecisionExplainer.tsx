/**
 * Why the textbook form fails and what the robust form (Ray Tracing Gems, ch. 7) and the
 * double-double reference compute instead: static text and formulas under the precision table.
 */
import { memo } from 'react';
import { MathTex, keepTextParenthesesTogether } from '../../../ui';

const DISC_TEX =
  `{\\Delta = 4a\\left(r^2 - \\lVert \\boldsymbol\\ell \\rVert^2\\right)},\\allowbreak\\qquad ` +
  `{\\boldsymbol\\ell = \\mathbf f - \\tfrac{\\mathbf f\\cdot\\mathbf d}{a}\\,\\mathbf d}\\allowbreak\\quad` +
  `(\\text{from C to the closest point of the line})`;

const ROOTS_TEX =
  `{q = -\\left(\\tfrac b2 + \\operatorname{sign}(b)\\,\\tfrac{\\sqrt{\\Delta}}{2}\\right)},\\allowbreak\\qquad ` +
  `{t = \\frac{c}{q},\\; \\frac{q}{a}}`;

function RobustForm() {
  return (
    <div className="rs-derivation">
      <p>
        The robust form (Ray Tracing Gems, ch. 7) computes the same Δ without subtracting two huge numbers,
        and picks the root formula that never cancels:
      </p>
      <MathTex display tex={DISC_TEX} />
      <MathTex display tex={ROOTS_TEX} />
    </div>
  );
}

// plain-text formulas: the line wraps outside their parentheses, never inside
const WHY_TEXTBOOK_FAILS = keepTextParenthesesTogether(
  'Why the textbook form fails: when the sphere is far (|f| ≫ r), b² and 4ac are both about 4a|f|², and ' +
    'their difference, about 4a r², is what is left after cancelling them. Each carries a rounding error of ' +
    'about u·4a|f|² (u = 2⁻⁵³), so Δ’s relative error is about u·(|f|/r)²: a millionth at |f| ≈ 10⁵ r, ' +
    'everything at |f| ≈ 10⁸ r. The robust form first finds the point of the line closest to the centre, ' +
    'f − (f·d / a) d, whose length is comparable to r, so nothing large is subtracted.',
);

/** Static: memoised so a re-render of the scene never reaches it. */
export const PrecisionExplainer = memo(function PrecisionExplainer() {
  return (
    <div className="rs-small">
      <RobustForm />
      <p>
        The reference solves the same quadratic with the inputs taken as exact doubles, in double-double
        arithmetic (about 106 bits: Dekker’s TwoProduct and Knuth’s TwoSum), using Δ/4 = a r² − |d × f|² so
        that only the genuine cancellation is left. It is checked against 400-digit mathjs BigNumber
        arithmetic in the tests.
      </p>
      <p>{WHY_TEXTBOOK_FAILS}</p>
    </div>
  );
});
