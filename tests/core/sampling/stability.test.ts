import { describe, expect, it } from 'vitest';
import { all, create } from 'mathjs';
import {
  STABILITY_XIS,
  computeStabilityReference,
  exactDecimal,
  measureError,
  phiFromXiLog,
  phiFromXiLog1p,
  stabilityTable,
  thetaFromXiAcos,
  thetaFromXiAsin,
  thetaFromXiStable,
  ulp,
} from '../../../src/core/sampling/stability';

// mathjs' typings do not follow BigNumber through generic calls; the instance is used untyped here.
const m: any = create(all, { number: 'BigNumber', precision: 60 });
type BN = ReturnType<typeof m.bignumber>;
const big = (x: number) => m.bignumber(exactDecimal(x));
const num = (b: unknown) => Number((b as BN).toString());
const cB = m.subtract(m.exp(m.multiply(2, m.pi) as BN), 1) as BN;
const thetaRef = (xi: number) => num(m.asin(m.sqrt(big(xi))));
/** ln(1 + cξ) at 60 digits; by series when cξ is tiny (1 + cξ would round even at 60 digits). */
const phiRef = (xi: number) => {
  const y = m.multiply(cB, big(xi)) as BN;
  return num(
    m.smaller(y, m.bignumber('1e-12'))
      ? m.add(m.subtract(y, m.divide(m.pow(y, 2), 2)), m.divide(m.pow(y, 3), 3))
      : m.log(m.add(y, 1)),
  );
};
const rel = (a: number, b: number) => Math.abs(a - b) / Math.abs(b);

describe('numerical stability of the inversion forms', () => {
  it('exactDecimal reproduces the double exactly', () => {
    for (const x of [0.1, 2 ** -53, 1 - 2 ** -53, 1e-300, 5e-324, 0.5, 3]) {
      const s = exactDecimal(x);
      expect(Number(s)).toBe(x);
      // 0.1 is not 1/10: its exact expansion is long
      if (x === 0.1) expect(s.length).toBeGreaterThan(50);
    }
  });

  it('ulp is the spacing of doubles', () => {
    expect(ulp(1)).toBe(2 ** -52);
    expect(ulp(1.5)).toBe(2 ** -52);
    expect(ulp(0.5)).toBe(2 ** -53);
    expect(ulp(2)).toBe(2 ** -51);
    expect(ulp(0)).toBe(2 ** -1074);
  });

  it('θ: ½acos(1−2ξ) fails for tiny ξ; arcsin √ξ and atan2 do not', () => {
    for (const xi of [1e-20, 1e-300]) {
      const r = thetaRef(xi);
      expect(thetaFromXiAcos(xi)).toBe(0); // 1 − 2ξ rounded to 1
      expect(rel(thetaFromXiAsin(xi), r)).toBeLessThan(3e-16);
      expect(rel(thetaFromXiStable(xi), r)).toBeLessThan(3e-16);
    }
    // ξ = 1e-12: acos form keeps only about half of the digits
    const r = thetaRef(1e-12);
    expect(rel(thetaFromXiAcos(1e-12), r)).toBeGreaterThan(1e-9);
    expect(rel(thetaFromXiStable(1e-12), r)).toBeLessThan(3e-16);
  });

  it('θ near ξ → 1: arcsin √ξ amplifies the rounding of √ξ; acos and atan2 forms are accurate', () => {
    // arcsin is ill-conditioned at 1 (derivative 1/√(1−x²)): the ≤ ½-ulp rounding of √ξ is
    // amplified unless √ξ happens to be exact (e.g. ξ = 1 − 2⁻⁵⁰ gives √ξ ≈ 1 − 2⁻⁵¹ almost exactly)
    for (const xi of [1 - 1e-12, 1 - 2 ** -53]) {
      const r = thetaRef(xi);
      expect(rel(thetaFromXiAcos(xi), r)).toBeLessThan(3e-16);
      expect(rel(thetaFromXiStable(xi), r)).toBeLessThan(3e-16);
      expect(rel(thetaFromXiAsin(xi), r)).toBeGreaterThan(1e-11);
    }
  });

  it('φ: ln(cξ+1) loses relative precision at tiny ξ; log1p(expm1(2π)ξ) does not', () => {
    for (const xi of [1e-12, 2 ** -53, 1e-300]) {
      const r = phiRef(xi);
      expect(rel(phiFromXiLog1p(xi), r)).toBeLessThan(5e-16);
      expect(rel(phiFromXiLog(xi), r)).toBeGreaterThan(1e-7);
    }
    for (const xi of [0.5, 1 - 2 ** -53]) expect(rel(phiFromXiLog1p(xi), phiRef(xi))).toBeLessThan(5e-16);
  });

  it('computeStabilityReference (lazy mathjs) agrees with independent 60-digit references', async () => {
    const ref = await computeStabilityReference(STABILITY_XIS);
    ref.xi.forEach((xi, i) => {
      expect(ref.theta[i]).toBe(thetaRef(xi));
      expect(ref.phi[i]).toBe(phiRef(xi));
    });
    // and with series expansions at tiny ξ: θ ≈ √ξ (1 + ξ/6), φ ≈ cξ
    const i0 = ref.xi.indexOf(1e-300);
    expect(ref.theta[i0]).toBe(Math.sqrt(1e-300));
    expect(rel(ref.phi[i0], Math.expm1(2 * Math.PI) * 1e-300)).toBeLessThan(3e-16);
  });

  it('table: every stable form within 2 ulps at every ξ; the unstable ones fail somewhere', async () => {
    const rows = stabilityTable(await computeStabilityReference(STABILITY_XIS));
    expect(rows.length).toBe(2 * STABILITY_XIS.length);
    let acosWorst = 0;
    let asinWorst = 0;
    let logWorst = 0;
    for (const row of rows) {
      for (const f of row.forms) {
        expect(Number.isFinite(f.value)).toBe(true);
        if (f.id === 'theta-atan2' || f.id === 'phi-log1p') expect(f.ulps).toBeLessThanOrEqual(2);
        if (f.id === 'theta-acos') acosWorst = Math.max(acosWorst, f.relError);
        if (f.id === 'theta-asin') asinWorst = Math.max(asinWorst, f.relError);
        if (f.id === 'phi-log') logWorst = Math.max(logWorst, f.relError);
      }
    }
    expect(acosWorst).toBe(1); // θ = 0 instead of √ξ
    expect(asinWorst).toBeGreaterThan(1e-12);
    expect(logWorst).toBeGreaterThan(1e-3);
  });

  it('measureError reports relative error and ulps', () => {
    const e = measureError(1 + 2 ** -52, 1);
    expect(e.relError).toBe(2 ** -52);
    expect(e.ulps).toBe(1);
  });
});
