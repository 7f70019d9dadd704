import { describe, expect, it } from 'vitest';
import { defaultValues } from '../../../src/kit/params';
import {
  schema,
  EXAM_PRESET,
  PRESETS,
  presetActive,
  type AreaLightParams,
} from '../../../src/scenes/area-light/params';
import {
  buildModel,
  convergence,
  estimateAll,
  estimateOne,
  givenSamples,
  targetValue,
} from '../../../src/scenes/area-light/model';
import { drawSamples } from '../../../src/scenes/area-light/animation';
import { patchModel } from '../../../src/scenes/area-light/patch';
import { checkValues } from '../../../src/scenes/area-light/check';
import { floorJob, floorPass, imageRmse, referenceImage } from '../../../src/scenes/area-light/floor';

const base = (): AreaLightParams => defaultValues(schema);
const withP = (patch: Partial<AreaLightParams>): AreaLightParams => ({ ...base(), ...patch });

describe('area-light model', () => {
  it('the exam’s configuration: a positive reference, Ω equal to its closed form, no messages', () => {
    const m = buildModel(withP(EXAM_PRESET.params));
    expect(m.reference).toBeGreaterThan(0);
    expect(m.messages).toEqual([]);
    expect(m.solidAngleClosed).not.toBeNull();
    expect(Math.abs(m.solidAngle - m.solidAngleClosed!)).toBeLessThan(1e-14);
    // 1×1 light at height 2, centred: Ω = 4 atan(1/(2·2·√(1+1+16))).
    expect(m.solidAngle).toBeCloseTo(4 * Math.atan(1 / (4 * Math.sqrt(18))), 14);
  });

  it('defaults: the light is tilted and the patch too, so cos θ ≠ cos θₗ at every given sample and dA⊥ < dA', () => {
    const v = base();
    const m = buildModel(v);
    expect(m.messages).toEqual([]);
    expect(m.reference).toBeGreaterThan(0);
    // not parallel to the floor: no aligned closed form
    expect(m.solidAngleClosed).toBeNull();
    for (const g of givenSamples(m, v.seed, 4).samples) {
      expect(g.V).toBe(1);
      expect(Math.abs(g.cosTheta - g.cosThetaL)).toBeGreaterThan(0.05);
    }
    const pt = patchModel(m, v.pu, v.pv, v.psize, v.ptilt);
    expect(v.ptilt).not.toBe(0);
    expect(pt.cosThetaL).toBeLessThan(0.9); // dA⊥ = dA cos θₗ visibly smaller than dA
    // the defaults are the opening preset, and the exam's configuration is another
    expect(
      presetActive(
        PRESETS.find((p) => p.id === 'opening')!,
        v,
      ),
    ).toBe(true);
    expect(presetActive(EXAM_PRESET, v)).toBe(false);
    expect(presetActive(EXAM_PRESET, withP(EXAM_PRESET.params))).toBe(true);
  });

  it('the exam’s configuration: cos θ = cos θₗ at every given sample (the light is parallel to the floor)', () => {
    const v = withP(EXAM_PRESET.params);
    const m = buildModel(v);
    for (const g of givenSamples(m, v.seed, 4).samples)
      expect(Math.abs(g.cosTheta - g.cosThetaL)).toBeLessThan(1e-12);
  });

  for (const preset of PRESETS) {
    it(`preset ${preset.id}: every strategy within 3σ of the reference (n = 20000)`, () => {
      const m = buildModel(withP(preset.params));
      const ests = estimateAll(m, 20000, 3);
      for (const e of ests) {
        expect(Number.isFinite(e.estimate)).toBe(true);
        if (m.reference === 0) expect(e.estimate).toBe(0);
        else expect(Math.abs(e.estimate - m.reference)).toBeLessThan(3 * e.stderr + 1e-12);
      }
    });
  }

  it('one strategy alone (the readout at the top) gives the numbers of the three together (the table, the worker)', () => {
    const m = buildModel(withP({ tilt: 25, occluder: true }));
    for (const [n, seed] of [
      [1, 9],
      [1000, 2],
      [4097, 5],
    ] as const) {
      const all = estimateAll(m, n, seed);
      for (const e of all) expect(estimateOne(m, e.strategy, n, seed)).toEqual(e);
      // and the strategies differ (each its own stream), so the comparison above can fail
      if (n > 1) expect(new Set(all.map((e) => e.estimate)).size).toBe(3);
    }
  });

  it('zero-size light: an error message and the 1 × 1 fallback', () => {
    const m = buildModel(withP({ ls: [0, 1] }));
    expect(m.messages.some((x) => x.kind === 'error' && /no area/.test(x.text))).toBe(true);
    expect(m.w).toBe(1);
    expect(m.reference).toBeGreaterThan(0);
  });

  it('shading point on the light: an error message, and the point moves off it', () => {
    // a point on the exam's light (1 × 1, centred at 0,0,2, parallel to the floor)
    const m = buildModel(withP({ ...EXAM_PRESET.params, p: [0.1, 0.1, 2] }));
    expect(m.messages.some((x) => x.kind === 'error' && /on the light/.test(x.text))).toBe(true);
    expect(m.p).toEqual([0, 0, 0]);
    expect(Number.isFinite(m.reference)).toBe(true);
    const m2 = buildModel(withP({ p: [0, 0, 0], lc: [0, 0, 0] }));
    expect(m2.lc).toEqual([0, 0, 2]);
  });

  it('non-finite values fall back to defaults with a message', () => {
    const m = buildModel(withP({ p: [NaN, 0, 0] as [number, number, number], ls: [Infinity, 1] }));
    expect(m.messages.filter((x) => x.kind === 'error').length).toBe(2);
    expect(Number.isFinite(m.reference) && Number.isFinite(m.solidAngle)).toBe(true);
  });

  it('facing away and partly below the horizon are explained', () => {
    expect(buildModel(withP({ tilt: 180 })).messages[0].text).toMatch(/faces away/);
    const m = buildModel(withP({ lc: [0, 1, 0.2], tilt: -90 }));
    expect(m.belowHorizon).toBeCloseTo(0.3, 2);
    expect(m.messages[0].text).toMatch(/below the horizon/);
  });

  it('occluder: the estimators converge to the occluded analytic value', () => {
    const m = buildModel(withP({ occluder: true }));
    const t = targetValue(m);
    expect(t).toBeLessThan(m.reference);
    for (const e of estimateAll(m, 50000, 4)) expect(Math.abs(e.estimate - t)).toBeLessThan(3 * e.stderr);
  });

  it('drawn samples are the first samples of the estimate and lie on the light', () => {
    const m = buildModel(withP({ tilt: 30 }));
    const { points, terms } = drawSamples(m, 'solid-angle', 64, 1);
    expect(points.length).toBe(192);
    for (let i = 0; i < 64; i++) {
      const d = [points[3 * i] - m.lc[0], points[3 * i + 1] - m.lc[1], points[3 * i + 2] - m.lc[2]];
      expect(
        Math.abs(d[0] * m.light.normal[0] + d[1] * m.light.normal[1] + d[2] * m.light.normal[2]),
      ).toBeLessThan(1e-12);
    }
    const est = estimateAll(m, 64, 1).find((e) => e.strategy === 'solid-angle')!;
    expect(terms.reduce((a, b) => a + b, 0) / 64).toBeCloseTo(est.estimate, 12);
  });

  it('Q6(a): the patch formula approaches the exact solid angle as the patch shrinks', () => {
    const m = buildModel(withP({ tilt: 20 }));
    const big = patchModel(m, 0.3, 0.6, 0.5, 15);
    const small = patchModel(m, 0.3, 0.6, 0.005, 15);
    expect(Math.abs(small.relError)).toBeLessThan(Math.abs(big.relError) / 1000);
    expect(
      small.projected.every(
        (q) => Math.abs(Math.hypot(q[0] - m.p[0], q[1] - m.p[1], q[2] - m.p[2]) - 1) < 1e-12,
      ),
    ).toBe(true);
    const rs = Array.from(small.series.relError).filter(Number.isFinite);
    expect(rs[rs.length - 1]).toBeLessThan(rs[0]);
  });

  it('convergence series and a floor pass are finite, and the floor image approaches the reference', () => {
    const m = buildModel(base());
    const c = convergence(m, 4096, 1);
    for (const s of c) expect(Number.isFinite(s.estimate[s.estimate.length - 1])).toBe(true);
    const job = floorJob(m, 1, 16);
    const ref = referenceImage(job);
    const sum = new Float64Array(256);
    floorPass(job, 'solid-angle', 64, 0, sum);
    const rmse = imageRmse(sum, 64, ref);
    const mean = ref.reduce((a, b) => a + b, 0) / ref.length;
    expect(rmse).toBeLessThan(0.05 * mean);
  });
});

describe('Q6(c) given samples and the animation (pure functions of params, seed, t)', () => {
  it('givenSamples: the first four area terms equal the estimator kernel’s, and their mean is (|A|/4) Σ …', async () => {
    const { givenSamples } = await import('../../../src/scenes/area-light/model');
    const { drawSamples: draw } = await import('../../../src/scenes/area-light/animation');
    for (const preset of PRESETS) {
      const m = buildModel(withP({ ...preset.params, occluder: preset.id === 'overhead' }));
      const g = givenSamples(m, 11, 4);
      const d = draw(m, 'area', 4, 11);
      let sum = 0;
      g.samples.forEach((s, i) => {
        expect(s.term).toBeCloseTo(d.terms[i], 12);
        expect(s.pA).toBeCloseTo(1 / m.light.area, 12);
        for (let c = 0; c < 3; c++) expect(s.x[c]).toBeCloseTo(d.points[3 * i + c], 12);
        // the key's form of the term, recomputed from the printed factors
        const keyTerm = s.V
          ? (m.light.area * (m.rho / Math.PI) * m.L * s.cosTheta * s.cosThetaL) / (s.r * s.r)
          : 0;
        expect(s.term).toBeCloseTo(keyTerm, 12);
        sum += s.term;
      });
      expect(g.estimate).toBeCloseTo(sum / 4, 14);
      // the first four samples are the first four of the n-sample estimate (same stream)
      expect(g.estimate).toBeCloseTo(estimateAll(m, 4, 11)[0].estimate, 14);
    }
  });

  it('animationFrame at t = n reproduces the estimate readout; at t = k the mean of the first k terms', async () => {
    const { sampleRun, animationFrame, animationLength } =
      await import('../../../src/scenes/area-light/animation');
    const m = buildModel(withP({ occluder: true }));
    for (const s of ['area', 'solid-angle', 'cosine'] as const) {
      const n = 300;
      const run = sampleRun(m, s, animationLength(n), 5);
      const full = estimateAll(m, n, 5).find((e) => e.strategy === s)!;
      const f = animationFrame(run, n);
      expect(f.k).toBe(n);
      expect(f.estimate).toBeCloseTo(full.estimate, 13);
      expect(f.stderr).toBeCloseTo(full.stderr, 13);
      const k = 37;
      let mean = 0;
      for (let i = 0; i < k; i++) mean += run.terms[i];
      expect(animationFrame(run, k + 0.6).estimate).toBeCloseTo(mean / k, 13);
      expect(animationFrame(run, 0).k).toBe(0);
      expect(Number.isNaN(animationFrame(run, 1).stderr)).toBe(true);
      expect(animationFrame(run, 1e9).k).toBe(n);
    }
    expect(animationLength(5)).toBe(5);
    expect(animationLength(1e6)).toBe(1024);
  });

  it('floorPassAt: pass grows with t, 0 at the start, the last pass (64 spp) at the end', async () => {
    const { floorPassAt, PASS_TOTAL } = await import('../../../src/scenes/area-light/floor');
    expect(floorPassAt(0, 1024)).toBe(0);
    expect(PASS_TOTAL[floorPassAt(1024, 1024)]).toBe(64);
    expect(PASS_TOTAL[floorPassAt(512, 1024)]).toBe(32);
    let prev = 0;
    for (let t = 0; t <= 1024; t += 7) {
      const k = floorPassAt(t, 1024);
      expect(k).toBeGreaterThanOrEqual(prev);
      prev = k;
    }
  });
});

describe('problems: the parameters the model replaces, named', () => {
  it('checkValues is the model’s problems, one per parameter, in schema order', () => {
    const bad = { ...defaultValues(schema), p: [NaN, 0, 0], ls: [0, 1], L: -1, rho: 2, tilt: NaN };
    const m = buildModel(bad as AreaLightParams);
    expect(m.problems.map((x) => x.name)).toEqual(['p', 'ls', 'tilt', 'L', 'rho']);
    expect(m.problems[0].message).toBe(m.refusals[0].message);
    expect(checkValues(bad as AreaLightParams)).toEqual(m.problems);
    expect(checkValues(defaultValues(schema))).toEqual([]);
  });
  it('a point on the light names the point, and the light when it had to move', () => {
    const onIt = { ...defaultValues(schema), p: [0, 0, 2], lc: [0, 0, 2], tilt: 0 };
    const m = buildModel(onIt as AreaLightParams);
    expect(m.problems.map((x) => x.name)).toEqual(['p']);
    expect(m.problems[0].message).toMatch(/lies on the light/);
    const atOrigin = { ...defaultValues(schema), p: [0, 0, 0], lc: [0, 0, 0], tilt: 30 };
    const moved = buildModel(atOrigin as AreaLightParams);
    expect([moved.lc, moved.tilt]).toEqual([[0, 0, 2], 0]);
    expect(moved.problems.map((x) => x.name)).toEqual(['lc', 'tilt']);
  });
});
