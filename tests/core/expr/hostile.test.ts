/**
 * Hostile expressions: no input the whitelist accepts may cost more than linear work,
 * and prototype names are never mistaken for functions, symbols or aliases.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  compileExpression,
  MAX_EXPRESSION_DEPTH,
  MAX_EXPRESSION_LENGTH,
  EXPRESSION_FUNCTIONS,
} from '../../../src/core/expr';

const PROTO_NAMES = Object.getOwnPropertyNames(Object.prototype);
const UNARY = Object.entries(EXPRESSION_FUNCTIONS)
  .filter(([, [, lo]]) => lo === 1)
  .map(([name]) => name);

function nest(fns: readonly string[], inner: string): string {
  let s = inner;
  for (const f of fns) s = `${f}(${s})`;
  return s;
}

/** Compile in θ and φ. The work is bounded by construction (the TeX stays linear in the input; a
 * runaway would hit the test's timeout); its speed is measured by bench/expr.bench.ts, not here. */
const compileThetaPhi = (src: string) => compileExpression(src, ['theta', 'phi']);

describe('expression work is bounded (no exponential TeX)', () => {
  it('60 nested exp() compile, with TeX linear in the input (mathjs toTex grew exponentially)', async () => {
    await compileExpression('x', ['x']); // load the engine outside the timing
    const src = nest(Array(60).fill('exp'), 'theta');
    expect(src.length).toBeLessThanOrEqual(MAX_EXPRESSION_LENGTH);
    const r = await compileThetaPhi(src);
    expect(r.ok).toBe(true);
    if (r.ok) {
      expect(r.tex.split('\\exp').length - 1).toBe(60);
      expect(r.tex.length).toBeLessThan(60 * 30);
    }
  });

  it('property: any nesting of whitelisted unary functions up to the depth limit compiles, refused only past the length limit', async () => {
    await compileExpression('x', ['x']);
    await fc.assert(
      fc.asyncProperty(
        fc.array(fc.constantFrom(...UNARY), { minLength: 1, maxLength: MAX_EXPRESSION_DEPTH - 1 }),
        fc.constantFrom('theta', 'phi', '0.5'),
        async (fns, inner) => {
          const src = nest(fns, inner);
          const r = await compileThetaPhi(src);
          if (src.length <= MAX_EXPRESSION_LENGTH) expect(r.ok).toBe(true);
          else expect(r.ok).toBe(false);
          if (r.ok) expect(r.tex.length).toBeLessThan(40 * src.length + 40);
        },
      ),
      { numRuns: 60, seed: 17 },
    );
  });

  it('property: arbitrary operator/paren/function mixes never throw and give a number or a message', async () => {
    await compileExpression('x', ['x']);
    const leaf = fc.constantFrom('theta', 'phi', '2', '1e308', 'pi', 'e', 'x', '0');
    const tree: fc.Arbitrary<string> = fc.letrec<{ t: string }>((tie) => ({
      t: fc.oneof(
        { depthSize: 'small', withCrossShrink: true },
        leaf,
        fc
          .tuple(
            fc.constantFrom(...UNARY, 'max', 'min', 'atan2', 'pow', 'log'),
            fc.array(tie('t'), { minLength: 1, maxLength: 3 }),
          )
          .map(([f, a]) => `${f}(${a.join(',')})`),
        fc
          .tuple(tie('t'), fc.constantFrom('+', '-', '*', '/', '^', ' '), tie('t'))
          .map(([a, o, b]) => `(${a}${o}${b})`),
        tie('t').map((a) => `-${a}`),
      ),
    })).t;
    await fc.assert(
      fc.asyncProperty(tree, async (src) => {
        const r = await compileThetaPhi(src.slice(0, MAX_EXPRESSION_LENGTH));
        if (r.ok) {
          expect(typeof r.fn(0.3, 1.1)).toBe('number');
          expect(typeof r.tex).toBe('string');
        } else expect(r.message.length).toBeGreaterThan(0);
      }),
      { numRuns: 200, seed: 4242 },
    );
  });

  it('a flat sum of many terms is not "nested too deeply"; real nesting past the limit is', async () => {
    const sum = Array(150).fill('1').join('+');
    const r = await compileExpression(sum, []);
    expect(r.ok).toBe(true);
    if (r.ok) expect(r.fn()).toBe(150);
    const mixed = Array(40).fill('x').join('-1+'); // 80 alternating levels as mathjs parses it
    const m = await compileExpression(mixed, ['x']);
    expect(m.ok).toBe(true);
    const deep = '('.repeat(MAX_EXPRESSION_DEPTH + 2) + 'x' + ')'.repeat(MAX_EXPRESSION_DEPTH + 2);
    const d = await compileExpression(deep, ['x']);
    expect(d.ok).toBe(false);
    if (!d.ok) expect(d.message).toMatch(/nested too deeply/);
  });

  it('"#" alone is called empty, not "the constant undefined"', async () => {
    const r = await compileExpression('#', ['x']);
    expect(r.ok).toBe(false);
    if (!r.ok) {
      expect(r.message).toMatch(/empty/);
      expect(r.message).not.toMatch(/undefined/);
    }
  });
});

describe('prototype names are ordinary unknown names', () => {
  it('property: every Object.prototype name as symbol, function, or alias is rejected with a message', async () => {
    await fc.assert(
      fc.asyncProperty(
        fc.constantFrom(...PROTO_NAMES),
        fc.constantFrom('%s', '%s(x)', '%s + x', 'x * %s(1, 2)'),
        async (name, shape) => {
          const src = shape.replace('%s', name);
          const r = await compileExpression(src, ['x']);
          expect(r.ok).toBe(false);
          if (!r.ok) {
            expect(r.message).not.toMatch(/native code|\[object|is not a function|Cannot read/);
          }
        },
      ),
      { numRuns: 120, seed: 3 },
    );
  });

  it('property: arbitrary identifiers never crash the compiler', async () => {
    await fc.assert(
      fc.asyncProperty(
        fc.oneof(fc.string({ maxLength: 30 }), fc.constantFrom(...PROTO_NAMES)),
        async (name) => {
          const r = await compileExpression(name, ['x']);
          if (!r.ok) expect(typeof r.message).toBe('string');
          else expect(typeof r.fn(1)).toBe('number');
        },
      ),
      { numRuns: 200, seed: 11 },
    );
  });
});
