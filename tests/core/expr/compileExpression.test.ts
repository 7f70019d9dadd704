import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  compileExpression,
  loadExpressionEngine,
  toTex,
  MAX_EXPRESSION_LENGTH,
} from '../../../src/core/expr';

const TP = ['theta', 'phi'] as const;

async function ok(src: string, vars: readonly string[] = TP) {
  const r = await compileExpression(src, vars);
  if (!r.ok) throw new Error(`expected '${src}' to compile, got: ${r.message}`);
  return r;
}
async function err(src: string, vars: readonly string[] = TP): Promise<string> {
  const r = await compileExpression(src, vars);
  if (r.ok) throw new Error(`expected '${src}' to be rejected`);
  return r.message;
}

describe('compileExpression: whitelist rejections with clear messages', () => {
  it.each([
    ['import(1)', /function 'import' is not allowed/],
    ['import("fs")', /function 'import' is not allowed|text strings/],
    ['x = 2', /assignments/],
    ['theta = 2', /assignments/],
    ['f(x) = x', /defining functions/],
    ['[1,2]', /matrices/],
    ['"a"', /text strings/],
    ['evaluate("1")', /function 'evaluate' is not allowed/],
    ['x.y', /property access/],
    ['theta[1]', /indexing/],
    ['foo(theta)', /function 'foo' is not allowed/],
    ['theta(2)', /function 'theta' is not allowed/],
    ['1:3', /ranges/],
    ['theta > 1 ? 1 : 0', /conditionals/],
    ['theta < 1', /operator '<' is not allowed/],
    ['theta!', /operator '!' is not allowed/],
    ['1; 2', /only one expression/],
    ['{a: 1}', /objects/],
    ['true', /not a number/],
    ['1e400', /too large/],
    ['sin(theta, phi)', /takes 1 argument, got 2/],
    ['atan2(theta)', /takes 2 arguments, got 1/],
    ['cos(y)', /unknown symbol 'y' — use theta, phi/],
    ['5 cm', /unknown symbol 'cm'/],
    ['Infinity', /infinite or too large/],
    ['NaN', /NaN/],
  ])('rejects %s', async (src, re) => {
    expect(await err(src)).toMatch(re);
  });

  it('reports syntax errors with their position', async () => {
    expect(await err('2 +')).toMatch(/syntax error at character 4/);
    expect(await err('sin(theta')).toMatch(/syntax error at character \d+/);
    expect(await err('   ')).toMatch(/empty/);
  });

  it('enforces the length and depth limits', async () => {
    expect(await err('theta+'.repeat(80) + '1')).toMatch(/too long/);
    const deep = '('.repeat(150) + 'theta' + ')'.repeat(150);
    expect(deep.length).toBeLessThanOrEqual(MAX_EXPRESSION_LENGTH);
    expect(await err(deep)).toMatch(/nested too deeply/);
  });

  it('only knows the variables it is given', async () => {
    expect(await err('theta', ['x'])).toMatch(/unknown symbol 'theta' — use x/);
    expect((await ok('(x + 2)^2', ['x'])).fn(1)).toBe(9);
  });
});

describe('compileExpression: values', () => {
  const cases: [string, (t: number, p: number) => number][] = [
    ['cos(theta) * exp(phi)', (t, p) => Math.cos(t) * Math.exp(p)],
    [
      '2/(e^(2 pi) - 1) * cos(θ) * e^φ',
      (t, p) => (2 / (Math.exp(2 * Math.PI) - 1)) * Math.cos(t) * Math.exp(p),
    ],
    ['-theta^2', (t) => -(t * t)],
    ['2^-1 + +phi', (_t, p) => 0.5 + p],
    ['sqrt(abs(sin(theta))) / (1 + phi^2)', (t, p) => Math.sqrt(Math.abs(Math.sin(t))) / (1 + p * p)],
    [
      'atan2(phi, theta) + log1p(theta^2) - expm1(-phi) + cbrt(theta)',
      (t, p) => Math.atan2(p, t) + Math.log1p(t * t) - Math.expm1(-p) + Math.cbrt(t),
    ],
    [
      'min(theta, phi, 0.5) + max(theta, phi) + pow(theta, 3) + floor(phi) + ceil(theta) + sign(theta - phi)',
      (t, p) =>
        Math.min(t, p, 0.5) +
        Math.max(t, p) +
        Math.pow(t, 3) +
        Math.floor(p) +
        Math.ceil(t) +
        Math.sign(t - p),
    ],
    [
      'log(phi + 1, 2) + log(theta + 1) + tanh(theta) + sinh(phi) / cosh(phi)',
      (t, p) => Math.log(p + 1) / Math.log(2) + Math.log(t + 1) + Math.tanh(t) + Math.sinh(p) / Math.cosh(p),
    ],
    ['tau * theta + π * phi + τ', (t, p) => 2 * Math.PI * t + Math.PI * p + 2 * Math.PI],
    ['2theta phi', (t, p) => 2 * t * p],
    // specialized closures: constant operands, squares, e^x, functions of a bare variable, 1-argument min
    [
      'e^theta + 3^phi - theta^2 + phi^0.5 - 2 - theta / 4 + 1 / (1 + phi)',
      (t, p) => Math.exp(t) + Math.pow(3, p) - t * t + Math.pow(p, 0.5) - 2 - t / 4 + 1 / (1 + p),
    ],
    [
      'min(theta) + max(phi, 1, 2, theta) + sin(phi) + cos(phi) + exp(theta) + sqrt(phi) + log(1 + theta) + tan(theta / 4) + abs(phi)',
      (t, p) =>
        t +
        Math.max(p, 1, 2, t) +
        Math.sin(p) +
        Math.cos(p) +
        Math.exp(t) +
        Math.sqrt(p) +
        Math.log(1 + t) +
        Math.tan(t / 4) +
        Math.abs(p),
    ],
    [
      'sign(phi - 3) * floor(theta * 3) * ceil(phi) + sinh(theta) - cosh(phi / 4) + tanh(phi) + asin(theta / 2) + acos(phi / 7) + atan(phi) + log1p(phi) + expm1(theta) + cbrt(phi)',
      (t, p) =>
        Math.sign(p - 3) * Math.floor(t * 3) * Math.ceil(p) +
        Math.sinh(t) -
        Math.cosh(p / 4) +
        Math.tanh(p) +
        Math.asin(t / 2) +
        Math.acos(p / 7) +
        Math.atan(p) +
        Math.log1p(p) +
        Math.expm1(t) +
        Math.cbrt(p),
    ],
    [
      'asin(theta / 4) + acos(phi / 8) + atan(theta) + tan(phi / 8)',
      (t, p) => Math.asin(t / 4) + Math.acos(p / 8) + Math.atan(t) + Math.tan(p / 8),
    ],
  ];

  it.each(cases)('%s matches Math', async (src, ref) => {
    const { fn } = await ok(src);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: Math.PI / 2, noNaN: true }),
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        (t, p) => {
          const a = fn(t, p);
          const b = ref(t, p);
          return Object.is(a, b) || Math.abs(a - b) <= 1e-14 * Math.max(1, Math.abs(b));
        },
      ),
    );
  });

  it('accepts Unicode θ and φ and normalizes them in text and tex', async () => {
    const r = await ok('cos(θ) e^φ');
    expect(r.fn(0, 0)).toBe(1);
    expect(r.text).toContain('theta');
    expect(r.text).toContain('phi');
    expect(r.text).not.toMatch(/[θφ]/);
    expect(r.tex).toContain('\\theta');
    expect(r.tex).toContain('\\phi');
  });

  it('is real-valued: outside a function’s domain the value is NaN, not complex', async () => {
    const { fn } = await ok('sqrt(theta - 2)');
    expect(fn(1, 0)).toBeNaN();
    expect(fn(6, 0)).toBe(2);
  });

  it('folds constants and the engine loads once', async () => {
    const a = loadExpressionEngine();
    const b = loadExpressionEngine();
    expect(a).toBe(b);
    const r = await ok('2 * pi + e^0');
    expect(r.fn(0, 0)).toBe(2 * Math.PI + 1);
  });

  it('toTex renders accepted expressions and falls back to \\text for rejected ones', async () => {
    expect(await toTex('sqrt(theta)')).toContain('\\sqrt');
    expect(await toTex('x = 2', ['x'])).toMatch(/^\\text\{/);
  });
});

describe('compileExpression cache', () => {
  it('returns the same promise for the same source and variables, a different one otherwise', async () => {
    const a = compileExpression('sin(theta) + phi', ['theta', 'phi']);
    const b = compileExpression('sin(theta) + phi', ['theta', 'phi']);
    const c = compileExpression('sin(theta) + phi', ['phi', 'theta']);
    expect(a).toBe(b);
    expect(c).not.toBe(a);
    const [ra, rc] = await Promise.all([a, c]);
    expect(ra.ok && rc.ok).toBe(true);
    if (ra.ok && rc.ok) expect(ra.fn(1, 2)).not.toBe(rc.fn(1, 2));
  });
});

describe('secant, cosecant and cotangent', () => {
  it('parse and evaluate as 1/cos, 1/sin, 1/tan (the key writes 2·cot θ)', async () => {
    const r = await ok('2*cot(theta) + sec(phi) - csc(theta / 2)');
    for (const [t, p] of [
      [0.3, 1.1],
      [1.2, -0.4],
    ])
      expect(r.fn(t, p)).toBeCloseTo(2 / Math.tan(t) + 1 / Math.cos(p) - 1 / Math.sin(t / 2), 12);
    expect((await ok('cot(0.5)')).fn(0, 0)).toBe(1 / Math.tan(0.5));
  });

  it('typeset as the upright operators \\sec, \\csc, \\cot, which KaTeX speaks by name', async () => {
    const tex = await toTex('2*cot(theta) + sec(theta) * csc(theta)');
    for (const op of ['\\cot', '\\sec', '\\csc']) expect(tex).toContain(op);
    const { default: katex } = await import('katex');
    const mathml = katex.renderToString(tex, { output: 'mathml' });
    for (const name of ['cot', 'sec', 'csc']) expect(mathml).toContain(`<mi>${name}</mi>`);
  });
});
