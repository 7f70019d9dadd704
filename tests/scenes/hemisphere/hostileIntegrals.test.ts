/** ∫ f dω must not show finite numbers for divergent integrals or non-finite f. */
import { describe, expect, it } from 'vitest';
import { compileExpression } from '../../../src/core/expr';
import { checkedIntegral } from '../../../src/scenes/hemisphere/integral';
import { q2Estimates } from '../../../src/scenes/hemisphere/q2Estimates';
import { makeLobe } from '../../../src/scenes/hemisphere/lobe';

async function fnOf(src: string) {
  const r = await compileExpression(src, ['theta', 'phi']);
  if (!r.ok) throw new Error(r.message);
  return r.fn as (t: number, p: number) => number;
}

describe('checkedIntegral (hemisphere ∫ f dω)', () => {
  it.each(['tan(theta)', '1/cos(theta)', 'theta^-2', '1/(theta-0.5)'])(
    'calls %s divergent, with no value',
    async (src) => {
      const r = checkedIntegral(await fnOf(src));
      expect(r.value).toBeNaN();
      expect(r.problem).toMatch(/does not converge/);
    },
  );

  it.each(['sqrt(cos(phi))', '1e308', 'exp(1000*theta)'])('says f is not finite for %s', async (src) => {
    const r = checkedIntegral(await fnOf(src));
    expect(r.value).toBeNaN();
    expect(r.problem).toMatch(/not finite/);
  });

  it('keeps convergent integrals, the sharp cos^10000 lobe and integrable singularities', async () => {
    expect(checkedIntegral(await fnOf('cos(theta)')).value).toBeCloseTo(Math.PI, 10);
    // ∫ cosⁿθ dω = 2π/(n+1)
    expect(checkedIntegral(await fnOf('cos(theta)^10000')).value / ((2 * Math.PI) / 10001)).toBeCloseTo(1, 6);
    // ∫ θ^-1/2 sin θ dθ dφ converges; the quadrature resolves it
    const s = checkedIntegral(await fnOf('theta^-0.5'));
    expect(s.problem).toBeNull();
    expect(Number.isFinite(s.value)).toBe(true);
  });
});

describe('q2Estimates blames the right thing', () => {
  it('counts samples where f is not finite, not "p = 0"', async () => {
    const f = await fnOf('sqrt(cos(phi))');
    const lobe = makeLobe('uniform', 1, null)!;
    const n = 512;
    const u = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      u[2 * i] = (i + 0.5) / n;
      u[2 * i + 1] = (((i * 0.618034) % 1) + 1) % 1;
    }
    const dirs = new Float64Array(3 * n);
    lobe.sampleBatch(u, dirs, n);
    const q = q2Estimates(lobe, f, u, dirs, n);
    expect(q.fNonFinite).toBeGreaterThan(0);
    expect(q.pZero).toBe(0);
  });
});

describe('tabulated typed density', () => {
  it('cos(theta)^10000 is integrable: at most a warning that the table cannot resolve the peak', async () => {
    const { tabulateHemisphereDensity } = await import('../../../src/core/sampling');
    const r = tabulateHemisphereDensity(await fnOf('cos(theta)^10000'));
    expect(r.ok).toBe(true);
    if (r.ok && r.warning) expect(r.warning).toMatch(/resolve/);
    const d = tabulateHemisphereDensity(await fnOf('cos(theta)/sin(theta)^2'));
    expect(d.ok).toBe(false);
  });
});
