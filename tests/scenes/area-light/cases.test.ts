/**
 * The area light's numbers for several placements of the light, checked against formulas computed
 * here: the solid angle Ω by the corner formula (inclusion–exclusion in the light's own frame,
 * independent of the model's Van Oosterom–Strackee code), the small-patch limit A cos θₗ / r² for a
 * distant light, and every strategy's estimate within 3σ of the analytic reference.
 */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/area-light/params';
import { buildModel, estimateAll, targetValue } from '../../../src/scenes/area-light/model';
import type { Vec3 } from '../../../src/core/vec3';

/**
 * Ω of a w × h rectangle (centre c, tilt t degrees about its x axis: ex = (1, 0, 0),
 * ey = (0, cos t, sin t), n = (0, sin t, −cos t)) seen from p:
 * Ω = |F(x1, y1) − F(x0, y1) − F(x1, y0) + F(x0, y0)|, F(a, b) = atan(ab / (d √(a² + b² + d²))).
 */
function cornerOmega(p: Vec3, c: Vec3, w: number, h: number, tiltDeg: number): number {
  const t = (tiltDeg * Math.PI) / 180;
  const ey: Vec3 = [0, Math.cos(t), Math.sin(t)];
  const n: Vec3 = [0, Math.sin(t), -Math.cos(t)];
  const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const rel: Vec3 = [c[0] - p[0], c[1] - p[1], c[2] - p[2]];
  const d = Math.abs(dot(rel, n));
  const cx = rel[0];
  const cy = dot(rel, ey);
  const F = (a: number, b: number) => Math.atan((a * b) / (d * Math.sqrt(a * a + b * b + d * d)));
  const [x0, x1, y0, y1] = [cx - w / 2, cx + w / 2, cy - h / 2, cy + h / 2];
  return Math.abs(F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0));
}

const modelOf = (query: string) => {
  const values = parseParams(schema, query).values;
  return { values, m: buildModel(values) };
};

interface Placement {
  name: string;
  p: Vec3;
  lc: Vec3;
  ls: [number, number];
  tilt: number;
  zero?: boolean;
}

const PLACEMENTS: Placement[] = [
  { name: 'overhead', p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 0 },
  { name: 'off-axis', p: [0.2, -0.4, 0], lc: [0.9, 0.3, 1.5], ls: [1.2, 0.8], tilt: 0 },
  { name: 'tilted', p: [0, 0, 0], lc: [0, 1, 1.5], ls: [1.5, 1], tilt: -45 },
  { name: 'partly below the horizon', p: [0, 0, 0], lc: [0, 1, 0.2], ls: [1, 1], tilt: -90 },
  { name: 'near', p: [0.1, 0, 0], lc: [0, 0, 0.25], ls: [2, 2], tilt: 0 },
  { name: 'facing away', p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 180, zero: true },
];

const queryOf = (pl: Placement) =>
  `p=${pl.p.join(',')}&lc=${pl.lc.join(',')}&ls=${pl.ls.join(',')}&tilt=${pl.tilt}`;

describe('placements of the light', () => {
  for (const pl of PLACEMENTS) {
    it(`${pl.name}: Ω equals the corner formula; every strategy is within 3σ of the reference`, () => {
      const { m } = modelOf(queryOf(pl));
      expect(m.refusals).toEqual([]);
      const omega = cornerOmega(pl.p, pl.lc, pl.ls[0], pl.ls[1], pl.tilt);
      expect(Math.abs(m.solidAngle - omega) / omega).toBeLessThan(1e-12);
      const all = estimateAll(m, 4096, 7);
      if (pl.zero) {
        expect(m.facing).toBe(false);
        expect(m.reference).toBe(0);
        for (const e of all) expect(e.estimate, e.strategy).toBe(0);
        return;
      }
      expect(m.reference).toBeGreaterThan(0);
      for (const e of all) {
        expect(e.stderr, e.strategy).toBeGreaterThan(0);
        expect(Math.abs(e.estimate - m.reference), e.strategy).toBeLessThanOrEqual(3 * e.stderr);
      }
    });
  }

  it('a light parallel to the floor: the aligned closed form equals Ω; no occluder, no occluded reference', () => {
    const { m } = modelOf('lc=0.7,-0.3,1.5&ls=1.2,0.8&tilt=0');
    expect(m.solidAngleClosed).not.toBeNull();
    expect(Math.abs(m.solidAngle - m.solidAngleClosed!) / m.solidAngle).toBeLessThan(1e-13);
    expect(m.referenceOccluded).toBeNull();
  });

  it('a tiny light 10⁶ away: Ω is A cos θₗ / r² to O((size/d)²); the solid-angle estimate is exact', () => {
    const { m } = modelOf('lc=3,-2,1000000&ls=1,0.5&tilt=0');
    // the corner formula's four terms cancel at this distance: the small-patch limit is the check
    const d = 1e6;
    const r = Math.hypot(3, -2, d);
    const approx = (1 * 0.5 * (d / r)) / (r * r);
    expect(Math.abs(m.solidAngle - approx) / approx).toBeLessThan(1e-11);
    const sa = estimateAll(m, 512, 1).find((e) => e.strategy === 'solid-angle')!;
    expect(Math.abs(sa.estimate - m.reference) / m.reference).toBeLessThan(1e-9);
  });

  it('the occluder lowers the target; the solid-angle estimate matches the occluded reference within 3σ', () => {
    const { m } = modelOf('occluder=1');
    expect(m.referenceOccluded).not.toBeNull();
    expect(m.referenceOccluded!).toBeLessThan(m.reference);
    expect(targetValue(m)).toBe(m.referenceOccluded);
    const sa = estimateAll(m, 20000, 3).find((e) => e.strategy === 'solid-angle')!;
    expect(Math.abs(sa.estimate - m.referenceOccluded!)).toBeLessThanOrEqual(3 * sa.stderr);
  });

  it('a zero-size light is refused and the 1 × 1 fallback is used where the default light is', () => {
    const { m } = modelOf('ls=0,0');
    expect(m.refusals.map((r) => r.kind)).toContain('no-area');
    expect(m.messages.some((x) => x.text.includes('no area'))).toBe(true);
    const omega = cornerOmega(
      [...schema.p.default] as Vec3,
      [...schema.lc.default] as Vec3,
      1,
      1,
      schema.tilt.default,
    );
    expect(m.solidAngle).toBeCloseTo(omega, 12);
  });
});
