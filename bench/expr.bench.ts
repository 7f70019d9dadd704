/**
 * Evaluations per second of a user expression (the exam lobe's pdf typed as text) three ways:
 * the closure tree from compileExpression (what the app uses), the same formula written in JS
 * (the ceiling), and mathjs's own compile().evaluate(scope) (what we avoid per sample).
 * 100000 evaluations per iteration. Run with `npx vitest bench bench/expr.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { create, all } from 'mathjs';
import { compileExpression } from '../src/core/expr';
import { Rng } from '../src/core/random';

const SRC = '2/(e^(2 pi) - 1) * cos(theta) * e^phi';
const N = 100000;
const u = new Rng(3).fill(new Float64Array(2 * N));
for (let i = 0; i < N; i++) {
  u[2 * i] = u[2 * i] * (Math.PI / 2);
  u[2 * i + 1] = u[2 * i + 1] * 2 * Math.PI;
}
const compiled = await compileExpression(SRC, ['theta', 'phi']);
if (!compiled.ok) throw new Error(compiled.message);
const fn = compiled.fn;
const K = 2 / Math.expm1(2 * Math.PI);
const native = (t: number, p: number) => K * Math.cos(t) * Math.exp(p);
const math = create(all);
const mj = math.compile(SRC);
let sink = 0;

describe(`expression evaluation, ${N} evaluations per iteration`, () => {
  bench('compileExpression closure tree', () => {
    let s = 0;
    for (let i = 0; i < N; i++) s += fn(u[2 * i], u[2 * i + 1]);
    sink += s;
  });
  bench('hand-written JS (ceiling)', () => {
    let s = 0;
    for (let i = 0; i < N; i++) s += native(u[2 * i], u[2 * i + 1]);
    sink += s;
  });
  bench('mathjs compile().evaluate(scope) per sample', () => {
    let s = 0;
    const scope = { theta: 0, phi: 0 };
    for (let i = 0; i < N; i++) {
      scope.theta = u[2 * i];
      scope.phi = u[2 * i + 1];
      s += mj.evaluate(scope) as number;
    }
    sink += s;
  });
});

export { sink };
