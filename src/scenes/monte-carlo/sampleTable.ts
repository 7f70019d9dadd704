/** The worked Q4 table for given samples: f, p and the terms of each row, and the three estimates. */
import { importanceEstimate, uniformEstimate, type McEstimate } from '../../core/estimators';
import { fail, type Failure } from '../../core/failure';
import { formatPlain } from '../../core/format';
import type { Fn1 } from './integral';

/** One row of the worked table. */
export interface SampleRow {
  x: number;
  f: number;
  p: number;
  /** f/p (NaN when p = 0 and f ≠ 0). */
  ratio: number;
  /** Uniform term (b − a) f(x). */
  uniformTerm: number;
  /** Importance term f/p with p ∝ |f| (exact density); NaN when there is none. */
  propRatio: number;
  /** Outside [a, b]? */
  outside: boolean;
}

/** The worked Q4 table for given samples: rows and the three estimates. */
export interface SampleTable {
  rows: SampleRow[];
  /** Estimator with the chosen pdf (importance; for the uniform pdf it is the uniform estimator). */
  chosen: McEstimate | null;
  /** Uniform estimator (b − a)/N Σ f(xᵢ). */
  uniform: McEstimate;
  /** Importance estimator with p ∝ |f| (exact density). */
  proportional: McEstimate | null;
  /** Problems with the given samples: kind 'outside' ([a, b]) or 'zero-pdf' (p = 0 where f ≠ 0). */
  problems: Failure[];
}

/** Build the worked table for the samples xs (given, or the exam's four). */
export function sampleTable(
  xs: readonly number[],
  f: Fn1,
  a: number,
  b: number,
  density: Fn1 | null,
  propDensity: Fn1 | null,
): SampleTable {
  const problems: Failure[] = [];
  const rows: SampleRow[] = xs.map((x) => {
    const fx = f(x);
    const outside = !(x >= a && x <= b);
    const p = density ? density(x) : NaN;
    const pp = propDensity && !outside ? propDensity(x) : NaN;
    return {
      x,
      f: fx,
      p,
      ratio: fx === 0 ? 0 : p > 0 ? fx / p : NaN,
      uniformTerm: (b - a) * fx,
      propRatio: fx === 0 ? 0 : pp > 0 ? fx / pp : NaN,
      outside,
    };
  });
  const outside = rows.filter((r) => r.outside).map((r) => formatPlain(r.x));
  if (outside.length) {
    problems.push(
      fail(
        'outside',
        `Sample${outside.length > 1 ? 's' : ''} ${outside.join(', ')} lie${outside.length > 1 ? '' : 's'} outside [${formatPlain(a)}, ${formatPlain(b)}]: p = 0 there, so f/p is undefined and the estimate leaves ${outside.length > 1 ? 'them' : 'it'} out.`,
      ),
    );
  }
  const fv = Float64Array.from(rows, (r) => (r.outside ? NaN : r.f));
  const uniform = uniformEstimate(fv, a, b);
  let chosen: McEstimate | null = null;
  if (density) {
    const pv = Float64Array.from(rows, (r) => r.p);
    chosen = importanceEstimate(fv, pv);
    const zero = rows.filter((r) => !r.outside && r.p === 0 && r.f !== 0).map((r) => formatPlain(r.x));
    if (zero.length)
      problems.push(
        fail(
          'zero-pdf',
          `p = 0 at x = ${zero.join(', ')} where f ≠ 0: such a sample could never be drawn from p.`,
        ),
      );
  }
  let proportional: McEstimate | null = null;
  if (propDensity) {
    proportional = importanceEstimate(
      fv,
      Float64Array.from(rows, (r) => propDensity(r.x)),
    );
  }
  return { rows, chosen, uniform, proportional, problems };
}
