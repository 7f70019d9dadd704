/**
 * The expected answers of every question agree with independent computations: closed forms and
 * mathjs BigNumber arithmetic (60 digits), numerical quadrature for the Q1 densities, brute force
 * for the nearest texel; and the exam's own configuration reproduces the core's exam-lobe values.
 */
import { describe, expect, it } from 'vitest';
import { all, create, type BigNumber } from 'mathjs';
import { q1Variant } from '../../src/practice/q1';
import { q1Closed, q1Params } from '../../src/practice/q1Density';
import { q2Params, q2Variant } from '../../src/practice/q2';
import { q3Params, q3Variant } from '../../src/practice/q3';
import { q4Params, q4Variant } from '../../src/practice/q4';
import { q5Params, q5Variant } from '../../src/practice/q5';
import { q6Params, q6Variant } from '../../src/practice/q6';
import { allAnswers, type NumberAnswer, type FormulaAnswer, type Variant } from '../../src/practice/model';
import { integrate1D } from '../../src/core/verify';
import { examLobeK, examPhiCdf, examPhiPdf, examThetaCdf, examThetaPdf } from '../../src/core/sampling';
import { formatGrid } from '../../src/core/texture';

type BN = BigNumber;
type Arg = BN | number;
/** A 60-digit BigNumber instance, typed for the few operations used here. */
const M = create(all, { number: 'BigNumber', precision: 60 }) as unknown as {
  bignumber(x: number | string): BN;
  add(a: Arg, b: Arg): BN;
  subtract(a: Arg, b: Arg): BN;
  multiply(a: Arg, b: Arg): BN;
  divide(a: Arg, b: Arg): BN;
  pow(a: Arg, b: Arg): BN;
  exp(a: Arg): BN;
  cos(a: Arg): BN;
  sqrt(a: Arg): BN;
  number(a: BN): number;
  pi: BN;
};
const B = (x: number | string) => M.bignumber(x);
const num = (v: Variant, name: string) =>
  (allAnswers(v).find((a) => a.name === name) as NumberAnswer).expected;
const formula = (v: Variant, name: string) => allAnswers(v).find((a) => a.name === name) as FormulaAnswer;
const rel = (x: number, y: number) => Math.abs(x - y) / Math.max(Math.abs(y), 1e-300);
const SEEDS = Array.from({ length: 300 }, (_, i) => i * 104729 + 7);

describe('Q1', () => {
  it('k by BigNumber; the densities integrate to 1, the CDFs are their integrals, inversion inverts them', () => {
    for (const s of SEEDS) {
      const P = q1Params(s);
      const v = q1Variant(s);
      const a = M.divide(B(P.a.p), B(P.a.q)) as BN;
      const k = M.divide(
        M.multiply(a, B(P.m + 1)),
        M.subtract(M.exp(M.multiply(M.multiply(2, M.pi), a)), 1),
      ) as BN;
      expect(rel(num(v, 'k')!, M.number(k) as number)).toBeLessThan(1e-13);
      expect(P.m).toBeGreaterThanOrEqual(0);
      expect(P.m).toBeLessThanOrEqual(4);
      const pt = formula(v, 'p-theta').expected;
      const pp = formula(v, 'p-phi').expected;
      expect(Math.abs(integrate1D((t) => pt(t), 0, Math.PI / 2).value - 1)).toBeLessThan(1e-12);
      expect(Math.abs(integrate1D((f) => pp(f), 0, 2 * Math.PI).value - 1)).toBeLessThan(1e-12);
      // k ∫∫ cos^m θ e^{aφ} sin θ dθ dφ = 1, numerically
      const kn = num(v, 'k')!;
      const aa = P.a.p / P.a.q;
      const inner = integrate1D((t) => Math.cos(t) ** P.m * Math.sin(t), 0, Math.PI / 2).value;
      const outer = integrate1D((f) => Math.exp(aa * f), 0, 2 * Math.PI).value;
      expect(Math.abs(kn * inner * outer - 1)).toBeLessThan(1e-12);
      const ct = formula(v, 'cdf-theta').expected;
      const cp = formula(v, 'cdf-phi').expected;
      const ti = formula(v, 'theta-of-xi').expected;
      const fi = formula(v, 'phi-of-xi').expected;
      for (const x of [0.1, 0.5, 1.2])
        expect(Math.abs(ct(x) - integrate1D((t) => pt(t), 0, x).value)).toBeLessThan(1e-12);
      for (const x of [0.5, 3, 6])
        expect(Math.abs(cp(x) - integrate1D((f) => pp(f), 0, x).value)).toBeLessThan(1e-12);
      for (const xi of [0.01, 0.3, 0.7, 0.99]) {
        expect(Math.abs(ct(ti(xi)) - xi)).toBeLessThan(1e-12);
        expect(Math.abs(cp(fi(xi)) - xi)).toBeLessThan(1e-12);
      }
    }
  });
  it('the exam configuration (m = 1, a = 1) reproduces the core exam lobe', () => {
    const c = q1Closed({ m: 1, a: { p: 1, q: 1 } });
    expect(rel(c.k, examLobeK())).toBeLessThan(1e-15);
    for (const t of [0.2, 0.8, 1.4]) {
      expect(rel(c.pTheta(t), examThetaPdf(t))).toBeLessThan(1e-14);
      expect(rel(c.cdfTheta(t), examThetaCdf(t))).toBeLessThan(1e-14);
    }
    for (const f of [0.5, 3, 6]) {
      expect(rel(c.pPhi(f), examPhiPdf(f))).toBeLessThan(1e-14);
      expect(rel(c.cdfPhi(f), examPhiCdf(f))).toBeLessThan(1e-13);
    }
  });
});

describe('Q2', () => {
  it('both estimates by BigNumber from the given directions; the zero-variance answer', () => {
    for (const s of SEEDS) {
      const P = q2Params(s);
      const v = q2Variant(s);
      const a = M.divide(B(P.a.p), B(P.a.q)) as BN;
      const k = M.divide(
        M.multiply(a, B(P.m + 1)),
        M.subtract(M.exp(M.multiply(M.multiply(2, M.pi), a)), 1),
      ) as BN;
      let su = B(0);
      let si = B(0);
      for (const [t, f] of P.dirs) {
        expect(t).toBeGreaterThan(0);
        expect(t).toBeLessThan(Math.PI / 2);
        expect(f).toBeGreaterThanOrEqual(0);
        expect(f).toBeLessThan(2 * Math.PI);
        const shape = M.multiply(M.pow(M.cos(B(t)), P.m), M.exp(M.multiply(a, B(f)))) as BN;
        const fv =
          P.fKind === 'const'
            ? B(P.C)
            : P.fKind === 'prop'
              ? (M.multiply(B(P.C), shape) as BN)
              : P.fKind === 'cos'
                ? (M.multiply(B(P.C), M.cos(B(t))) as BN)
                : (M.multiply(B(P.C), M.pow(M.cos(B(t)), 2)) as BN);
        su = M.add(su, fv) as BN;
        si = M.add(si, M.divide(fv, M.multiply(k, shape))) as BN;
      }
      const n = P.dirs.length;
      expect(
        rel(num(v, 'mc-uniform')!, M.number(M.multiply(M.divide(M.multiply(2, M.pi), n), su)) as number),
      ).toBeLessThan(1e-13);
      expect(rel(num(v, 'mc-importance')!, M.number(M.divide(si, n)) as number)).toBeLessThan(1e-12);
      const z = allAnswers(v).find((x) => x.name === 'zero-variance')!;
      expect(z.kind === 'choice' && z.expected).toBe(
        P.fKind === 'prop' ? 'importance' : P.fKind === 'const' ? 'uniform' : 'neither',
      );
    }
  });
});

describe('Q3', () => {
  it('nearest by brute force, bilinear by the weighted sum, (u, v) of the sphere point by closed form', () => {
    for (const s of SEEDS) {
      const P = q3Params(s);
      const v = q3Variant(s);
      const g = P.grid;
      const n = g.width;
      expect([3, 4, 5]).toContain(n);
      expect(P.u).toBeGreaterThan(0);
      expect(P.u).toBeLessThan(1);
      expect(P.v).toBeGreaterThan(0);
      expect(P.v).toBeLessThan(1);
      const at = (i: number, j: number) => g.values[j * n + i];
      let best = Infinity;
      let bestVal = NaN;
      for (let j = 0; j < n; j++)
        for (let i = 0; i < n; i++) {
          const d = (i / (n - 1) - P.u) ** 2 + (j / (n - 1) - P.v) ** 2;
          if (d < best) {
            best = d;
            bestVal = at(i, j);
          }
        }
      expect(num(v, 'nearest')).toBe(bestVal);
      const su = P.u * (n - 1);
      const sv = P.v * (n - 1);
      const i0 = Math.floor(su);
      const j0 = Math.floor(sv);
      const fu = su - i0;
      const fv = sv - j0;
      const want =
        (1 - fu) * (1 - fv) * at(i0, j0) +
        fu * (1 - fv) * at(i0 + 1, j0) +
        (1 - fu) * fv * at(i0, j0 + 1) +
        fu * fv * at(i0 + 1, j0 + 1);
      expect(Math.abs(num(v, 'bilinear')! - want)).toBeLessThan(1e-12);
      const r = Math.hypot(P.x, P.y, P.z);
      let phi = Math.atan2(P.y, P.x);
      if (phi < 0) phi += 2 * Math.PI;
      expect(Math.abs(num(v, 'sphere-u')! - phi / (2 * Math.PI))).toBeLessThan(1e-14);
      expect(Math.abs(num(v, 'sphere-v')! - Math.acos(P.z / r) / Math.PI)).toBeLessThan(1e-12);
      expect(v.givens.find((x) => x.name === 'grid')!.value).toBe(formatGrid(g));
    }
  });
});

describe('Q4', () => {
  it('exact integral and both estimates by BigNumber', () => {
    for (const s of SEEDS) {
      const P = q4Params(s);
      const v = q4Variant(s);
      expect(P.a).toBeLessThan(P.b);
      for (const x of P.samples) {
        expect(x).toBeGreaterThan(P.a);
        expect(x).toBeLessThan(P.b);
      }
      const c = B(P.c);
      const f = (x: BN): BN =>
        P.kind === 'square'
          ? (M.pow(M.add(x, c), 2) as BN)
          : P.kind === 'cube'
            ? (M.pow(M.add(x, c), 3) as BN)
            : (M.add(M.pow(x, 2), c) as BN);
      const F = (x: BN): BN =>
        P.kind === 'square'
          ? (M.divide(M.pow(M.add(x, c), 3), 3) as BN)
          : P.kind === 'cube'
            ? (M.divide(M.pow(M.add(x, c), 4), 4) as BN)
            : (M.add(M.divide(M.pow(x, 3), 3), M.multiply(c, x)) as BN);
      const I = M.subtract(F(B(P.b)), F(B(P.a))) as BN;
      expect(rel(num(v, 'exact')!, M.number(I) as number)).toBeLessThan(1e-14);
      let sum = B(0);
      for (const x of P.samples) sum = M.add(sum, f(B(x))) as BN;
      const uni = M.divide(M.multiply(sum, P.b - P.a), P.samples.length) as BN;
      expect(rel(num(v, 'uniform')!, M.number(uni) as number)).toBeLessThan(1e-14);
      expect(rel(num(v, 'importance')!, M.number(I) as number)).toBeLessThan(1e-13);
    }
  });
});

describe('Q5', () => {
  it('coefficients, discriminant and roots by BigNumber; the case by its definition; every case occurs', () => {
    const cases = new Set<string>();
    for (const s of SEEDS) {
      const P = q5Params(s);
      const v = q5Variant(s);
      const f = P.o.map((x, i) => x - P.c[i]);
      const a = P.d.reduce((t, x) => t + x * x, 0);
      const b = 2 * P.d.reduce((t, x, i) => t + x * f[i], 0);
      const c = f.reduce((t, x) => t + x * x, 0) - P.r * P.r;
      expect(num(v, 'a')).toBe(a);
      expect(num(v, 'b')).toBe(b);
      expect(num(v, 'c')).toBe(c);
      const D = b * b - 4 * a * c;
      expect(num(v, 'discriminant')).toBe(D);
      const kase = allAnswers(v).find((x) => x.name === 'case')!;
      const got = kase.kind === 'choice' ? kase.expected : '';
      cases.add(got);
      if (D < 0) {
        expect(got).toBe('miss');
        expect(num(v, 't0')).toBeNull();
        expect(num(v, 't-hit')).toBeNull();
        continue;
      }
      const sq = M.sqrt(B(D)) as BN;
      const t0 = M.number(M.divide(M.subtract(B(-b), sq), 2 * a)) as number;
      const t1 = M.number(M.divide(M.add(B(-b), sq), 2 * a)) as number;
      expect(Math.abs(num(v, 't0')! - t0)).toBeLessThan(1e-13 * Math.max(1, Math.abs(t0)));
      expect(Math.abs(num(v, 't1')! - t1)).toBeLessThan(1e-13 * Math.max(1, Math.abs(t1)));
      const want =
        D === 0 ? (t0 >= 0 ? 'tangent' : 'behind') : t1 < 0 ? 'behind' : t0 >= 0 ? 'two-hits' : 'inside';
      expect(got).toBe(want);
      const hit = t0 >= 0 ? t0 : t1 >= 0 ? t1 : null;
      if (hit === null) expect(num(v, 't-hit')).toBeNull();
      else expect(Math.abs(num(v, 't-hit')! - hit)).toBeLessThan(1e-13 * Math.max(1, hit));
    }
    expect([...cases].sort()).toEqual(['behind', 'inside', 'miss', 'tangent', 'two-hits']);
  });
});

describe('Q6', () => {
  it('r, cos θ_l, dω and the area estimate from first principles', () => {
    for (const s of SEEDS) {
      const P = q6Params(s);
      const v = q6Variant(s);
      const [w, h] = P.ls;
      const t = (P.tilt * Math.PI) / 180;
      const ex = [1, 0, 0];
      const ey = [0, Math.cos(t), Math.sin(t)];
      const nl = [0, Math.sin(t), -Math.cos(t)];
      const corner = P.lc.map((c, k) => c - (w / 2) * ex[k] - (h / 2) * ey[k]);
      const pc = corner.map((c, k) => c + P.pu * w * ex[k] + P.pv * h * ey[k]);
      const tp = ((P.tilt + P.ptilt) * Math.PI) / 180;
      const pn = [0, Math.sin(tp), -Math.cos(tp)];
      const d = pc.map((c, k) => c - P.p[k]);
      const r = Math.hypot(d[0], d[1], d[2]);
      const cosL = -(d[0] * pn[0] + d[1] * pn[1] + d[2] * pn[2]) / r;
      expect(rel(num(v, 'r')!, r)).toBeLessThan(1e-13);
      expect(rel(num(v, 'cos-theta-l')!, cosL)).toBeLessThan(1e-12);
      expect(rel(num(v, 'd-omega')!, (P.psize * P.psize * cosL) / (r * r))).toBeLessThan(1e-12);
      let sum = 0;
      for (const [a, b] of P.uv) {
        const x = corner.map((c, k) => c + a * w * ex[k] + b * h * ey[k]);
        const q = x.map((c, k) => c - P.p[k]);
        const r2 = q[0] ** 2 + q[1] ** 2 + q[2] ** 2;
        const rr = Math.sqrt(r2);
        const cosT = q[2] / rr;
        const cl = -(q[0] * nl[0] + q[1] * nl[1] + q[2] * nl[2]) / rr;
        expect(cosT).toBeGreaterThan(0);
        expect(cl).toBeGreaterThan(0);
        sum += ((P.rho / Math.PI) * P.L * cosT * cl) / r2;
      }
      expect(rel(num(v, 'estimate')!, (w * h * sum) / P.uv.length)).toBeLessThan(1e-12);
    }
  });
});
