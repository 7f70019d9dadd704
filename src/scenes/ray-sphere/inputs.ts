/**
 * The ray–sphere scene's input checks: values that do not describe a ray and a sphere are replaced
 * by safe ones, each with the parameter it concerns and a message saying why.
 */
import { dot, type Vec3 } from '../../core/vec3';
import { fail, type Failure } from '../../core/failure';
import type { ParamProblem } from '../../kit/params';
import { schema, type RaySphereParams } from './params';

export interface InputCheck {
  /** The values actually used (bad ones replaced by safe fallbacks). */
  o: Vec3;
  d: Vec3;
  c: Vec3;
  r: number;
  /**
   * What was replaced and why (kind for code, name: the parameter, message for the page); empty
   * when the inputs are fine.
   */
  failures: InputFailure[];
  /** The failures as the parameters' problems ({ name, message }), in order. */
  problems: ParamProblem[];
}

/** The parameters the checks concern. */
export type InputName = 'o' | 'd' | 'c' | 'r';

/** An input replaced by a safe value: why (kind, message) and which parameter (name). */
export type InputFailure = Failure<InputProblem> & { name: InputName };

/** Why an input was replaced by a safe value. */
export type InputProblem =
  'not-finite' | 'zero-radius' | 'negative-radius' | 'zero-direction' | 'direction-underflow';

const DEFAULT_D: Vec3 = [...schema.d.default];

/**
 * Replace inputs that do not describe a ray and a sphere by safe values, saying why:
 * non-finite numbers → defaults; d = 0 (or too short to square) → the default direction;
 * r ≤ 0 → |r| if positive, else 1.
 */
export function checkInputs(p: Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r'>): InputCheck {
  const failures: InputFailure[] = [];
  const add = (name: InputName, f: Failure<InputProblem>) => failures.push({ ...f, name });
  const fin = (name: 'o' | 'd' | 'c', what: string): Vec3 => {
    const v = p[name];
    if (v.length === 3 && v.every(Number.isFinite)) return [v[0], v[1], v[2]];
    const fallback = schema[name].default;
    add(
      name,
      fail('not-finite', `${what} has a value that is not a finite number; using ${fallback.join(', ')}.`),
    );
    return [fallback[0], fallback[1], fallback[2]];
  };
  const o = fin('o', 'The origin o');
  let d = fin('d', 'The direction d');
  const c = fin('c', 'The centre C');
  let r = p.r;
  if (!Number.isFinite(r)) {
    add('r', fail('not-finite', `The radius is not a finite number; using r = ${schema.r.default}.`));
    r = schema.r.default;
  } else if (r <= 0) {
    const fb = r < 0 ? -r : schema.r.default;
    add(
      'r',
      r === 0
        ? fail('zero-radius', `A radius of 0 is a point, not a sphere; using r = ${fb}.`)
        : fail(
            'negative-radius',
            `A negative radius (r = ${r}) does not describe a sphere; using |r| = ${fb}.`,
          ),
    );
    r = fb;
  }
  if (!(dot(d, d) > 0)) {
    const using = `using d = (${DEFAULT_D.join(', ')})`;
    add(
      'd',
      d.every((x) => x === 0)
        ? fail('zero-direction', `The direction d = (0, 0, 0) points nowhere, so the ray has no t; ${using}.`)
        : fail(
            'direction-underflow',
            `The direction d is too short to square in double precision (d·d underflows to 0); ${using}.`,
          ),
    );
    d = [...DEFAULT_D];
  }
  return { o, d, c, r, failures, problems: failures.map(({ name, message }) => ({ name, message })) };
}
