/**
 * The pixel inspector against independent closed forms. The light's irradiance is recomputed here
 * from first principles, E = ∫_A L cos θ cos θ_l / r² dA by a 64 × 64 Gauss–Legendre rule over the
 * rectangle (not Lambert's formula, which the inspector's own reference uses); the camera ray,
 * the sphere's quadratic (the textbook form, well conditioned at these pixels), the spherical
 * (u, v) and the bilinear lookup of the exam's grid (value 21 − 20v + 4u, linear, so bilinear
 * filtering reproduces it exactly) are all written out again.
 */
import { describe, expect, it } from 'vitest';
import { inspectPixel, type PixelInspection } from '../../../src/core/render/inspector';
import { STRATEGIES } from '../../../src/core/render/directLight';
import { EXAM_DEFAULTS, defaultView, examScene } from '../../../src/core/render/scene';

const W = 48;
const VIEW = defaultView('exam');
const SCENE = examScene();

/** Gauss–Legendre nodes and weights on [0, 1] (Newton's method on P_n). */
function gaussLegendre(n: number): { x: number[]; w: number[] } {
  const x: number[] = [];
  const w: number[] = [];
  for (let i = 1; i <= n; i++) {
    let z = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    let dp = 0;
    for (let it = 0; it < 100; it++) {
      let p0 = 1,
        p1 = z;
      for (let k = 2; k <= n; k++) {
        const p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = (n * (z * p1 - p0)) / (z * z - 1);
      const dz = p1 / dp;
      z -= dz;
      if (Math.abs(dz) < 1e-16) break;
    }
    x.push((1 - z) / 2);
    w.push(1 / ((1 - z * z) * dp * dp));
  }
  return { x, w };
}
const GL = gaussLegendre(64);

/** The exam light from its parameters: centre, 1 × 1, tilted −30° about x, emitting towards −z. */
const tilt = (EXAM_DEFAULTS.tilt * Math.PI) / 180;
const EY = [0, Math.cos(tilt), Math.sin(tilt)];
const NL = [0, Math.sin(tilt), -Math.cos(tilt)];
const C0 = [EXAM_DEFAULTS.lc[0] - 0.5, EXAM_DEFAULTS.lc[1] - 0.5 * EY[1], EXAM_DEFAULTS.lc[2] - 0.5 * EY[2]];

/** L ∫ max(0, cos θ) max(0, cos θ_l)/r² dA over the light, seen from p with normal n. */
function irradiance(p: readonly number[], n: readonly number[]): number {
  let e = 0;
  for (let a = 0; a < 64; a++)
    for (let b = 0; b < 64; b++) {
      const x = [C0[0] + GL.x[a], C0[1] + GL.x[b] * EY[1], C0[2] + GL.x[b] * EY[2]];
      const r = [x[0] - p[0], x[1] - p[1], x[2] - p[2]];
      const r2 = r[0] ** 2 + r[1] ** 2 + r[2] ** 2;
      const len = Math.sqrt(r2);
      const cos = Math.max(0, (n[0] * r[0] + n[1] * r[1] + n[2] * r[2]) / len);
      const cosL = Math.max(0, -(NL[0] * r[0] + NL[1] * r[1] + NL[2] * r[2]) / len);
      e += (GL.w[a] * GL.w[b] * cos * cosL) / r2;
    }
  return EXAM_DEFAULTS.L * e;
}

/** The primary ray through pixel (i, j)'s centre, from the camera's definition. */
function primary(i: number, j: number): number[] {
  const { eye, look, fov } = VIEW;
  const f = [look[0] - eye[0], look[1] - eye[1], look[2] - eye[2]];
  const fl = Math.hypot(f[0], f[1], f[2]);
  const fw = f.map((c) => c / fl);
  const rl = Math.hypot(fw[1], fw[0]);
  const right = [fw[1] / rl, -fw[0] / rl, 0];
  const up = [
    right[1] * fw[2] - right[2] * fw[1],
    right[2] * fw[0] - right[0] * fw[2],
    right[0] * fw[1] - right[1] * fw[0],
  ];
  const t = Math.tan((fov * Math.PI) / 360);
  const x = ((2 * (i + 0.5)) / W - 1) * t;
  const y = (1 - (2 * (j + 0.5)) / W) * t;
  const d = [0, 1, 2].map((k) => fw[k] + x * right[k] + y * up[k]);
  const dl = Math.hypot(d[0], d[1], d[2]);
  return d.map((c) => c / dl);
}

const inspect = (
  i: number,
  j: number,
  strategy: (typeof STRATEGIES)[number],
  seed = 11,
  pn = 4096,
): PixelInspection =>
  inspectPixel(SCENE, VIEW, i, j, { width: W, height: W, seed, strategy, bounces: 1, pn });

const FLOOR_PIXELS = [
  [6, 38],
  [45, 30],
  [33, 45],
];
/** Sphere pixels whose point sees the whole light above its horizon (a smooth integrand for the rule). */
const SPHERE_PIXELS = [
  [22, 27],
  [28, 25],
];

describe('the pixel inspector on the exam scene', () => {
  it('finds the primary ray, the sphere quadratic and the hit as written out independently', () => {
    for (const [i, j] of [...FLOOR_PIXELS, ...SPHERE_PIXELS]) {
      const ins = inspect(i, j, 'cosine', 1, 16);
      const d = primary(i, j);
      for (let k = 0; k < 3; k++) expect(ins.d[k]).toBeCloseTo(d[k], 14);
      expect(ins.o).toEqual(VIEW.eye);
      // textbook quadratic (a = |d|² = 1): f = o − c, b = 2 f·d, c′ = |f|² − r²
      const f = [0, 1, 2].map((k) => VIEW.eye[k] - EXAM_DEFAULTS.c[k]);
      const b = 2 * (f[0] * d[0] + f[1] * d[1] + f[2] * d[2]);
      const cc = f[0] ** 2 + f[1] ** 2 + f[2] ** 2 - EXAM_DEFAULTS.r ** 2;
      const disc = b * b - 4 * cc;
      expect(ins.discriminant).not.toBeNull();
      expect(Math.abs((ins.discriminant ?? 0) - disc)).toBeLessThan(1e-12 * (b * b));
      if (disc >= 0) {
        const t = (-b - Math.sqrt(disc)) / 2;
        expect(ins.t).toBeCloseTo(t, 12);
        expect(ins.hit).toBe('sphere');
      } else {
        expect(ins.t).toBeNull();
        // the floor z = 0
        const t = -VIEW.eye[2] / d[2];
        expect(ins.hit).toBe('floor');
        expect(ins.p?.[0]).toBeCloseTo(VIEW.eye[0] + t * d[0], 12);
        expect(ins.p?.[1]).toBeCloseTo(VIEW.eye[1] + t * d[1], 12);
        expect(ins.p?.[2]).toBe(0);
      }
    }
  });

  it('reads the sphere’s (u, v) and texel as the exam’s spherical mapping and bilinear lookup', () => {
    for (const [i, j] of SPHERE_PIXELS) {
      const ins = inspect(i, j, 'cosine', 1, 16);
      const p = ins.p ?? [NaN, NaN, NaN];
      const q = [0, 1, 2].map((k) => p[k] - EXAM_DEFAULTS.c[k]);
      let phi = Math.atan2(q[1], q[0]);
      if (phi < 0) phi += 2 * Math.PI;
      const u = phi / (2 * Math.PI);
      const v = Math.acos(q[2] / Math.hypot(q[0], q[1], q[2])) / Math.PI;
      expect(ins.u).toBeCloseTo(u, 12);
      expect(ins.v).toBeCloseTo(v, 12);
      expect(ins.texel).toBeCloseTo(21 - 20 * v + 4 * u, 11);
      expect(ins.albedo).toBeCloseTo(0.2 + (0.6 * (21 - 20 * v + 4 * u - 1)) / 24, 11);
    }
  });

  it('reads the nearest texel with filter=nearest', () => {
    const scene = examScene({ ...EXAM_DEFAULTS, filter: 'nearest' });
    const [i, j] = SPHERE_PIXELS[0];
    const ins = inspectPixel(scene, VIEW, i, j, {
      width: W,
      height: W,
      seed: 1,
      strategy: 'cosine',
      bounces: 1,
      pn: 8,
    });
    const u = ins.u ?? NaN,
      v = ins.v ?? NaN;
    const col = Math.round(4 * u),
      row = Math.round(4 * v);
    expect(ins.texel).toBe(21 - 5 * row + col);
  });

  for (const strategy of STRATEGIES) {
    it(`${strategy}: the estimate is within 4 standard errors of (ρ/π) E, E by quadrature`, () => {
      for (const [i, j] of [...FLOOR_PIXELS, ...SPHERE_PIXELS]) {
        const ins = inspect(i, j, strategy);
        expect(ins.referenceKind).toBe('exact');
        const p = ins.p ?? [NaN, NaN, NaN];
        const onSphere = ins.hit === 'sphere';
        const n = onSphere ? p.map((c, k) => (c - EXAM_DEFAULTS.c[k]) / EXAM_DEFAULTS.r) : [0, 0, 1];
        const albedo = onSphere ? (ins.albedo ?? NaN) : EXAM_DEFAULTS.rho;
        const lo = (albedo / Math.PI) * irradiance(p, n);
        expect(lo).toBeGreaterThan(0);
        expect(Math.abs(ins.reference - lo)).toBeLessThan(1e-9 * lo);
        expect(ins.n).toBe(4096);
        expect(ins.stderr).toBeGreaterThan(0);
        expect(Math.abs(ins.estimate - lo)).toBeLessThan(4 * ins.stderr);
      }
    });
  }

  it('shows the first samples in full: each term is f L cos θ / p (times 2w under MIS)', () => {
    for (const strategy of STRATEGIES) {
      const ins = inspect(FLOOR_PIXELS[0][0], FLOOR_PIXELS[0][1], strategy, 3, 16);
      expect(ins.rows).toHaveLength(8);
      for (const r of ins.rows) {
        const mis = strategy.startsWith('mis');
        const expected =
          r.pdfSolidAngle > 0 ? ((mis ? 2 * r.weight : 1) * r.f * r.L * r.cosTheta) / r.pdfSolidAngle : 0;
        expect(r.term).toBeCloseTo(expected, 14);
        if (r.measure === 'area' && r.r2 !== null && r.cosThetaL !== null && r.cosThetaL > 0)
          expect(r.pdfSolidAngle).toBeCloseTo((r.pdf * r.r2) / r.cosThetaL, 12);
        if (mis) expect(r.technique).toBe(ins.rows.indexOf(r) % 2 === 0 ? 'bsdf' : 'solid-angle');
      }
    }
  });

  it('falls back to a converged reference in the sphere’s shadow and with more bounces', () => {
    // a floor point just behind the dome, as the light sees it: partly shadowed
    const shadowed = inspect(24, 33, 'mis-power');
    expect(shadowed.hit).toBe('floor');
    expect(shadowed.referenceKind).toBe('converged');
    const bounced = inspectPixel(SCENE, VIEW, 6, 38, {
      width: W,
      height: W,
      seed: 5,
      strategy: 'solid-angle',
      bounces: 3,
    });
    expect(bounced.referenceKind).toBe('converged');
    for (const ins of [shadowed, bounced]) {
      expect(ins.referenceStderr).toBeGreaterThan(0);
      const s = Math.hypot(ins.stderr, ins.referenceStderr);
      expect(Math.abs(ins.estimate - ins.reference)).toBeLessThan(4 * s);
    }
    // light reflected off the floor and the dome adds to the direct light
    expect(bounced.estimate).toBeGreaterThan(inspect(6, 38, 'solid-angle').estimate);
  });

  it('reads a miss and the light itself exactly, with no samples', () => {
    const up = { ...VIEW, look: [0, 0, 10] as const };
    const sky = inspectPixel(SCENE, up, 2, 1, {
      width: W,
      height: W,
      seed: 1,
      strategy: 'cosine',
      bounces: 1,
    });
    expect(sky.hit).toBe('none');
    expect([sky.estimate, sky.stderr, sky.reference, sky.referenceKind]).toEqual([0, 0, 0, 'exact']);
    let light: PixelInspection | null = null;
    for (let j = 0; j < W && !light; j++) {
      const ins = inspect(24, j, 'cosine', 1, 16);
      if (ins.hit === 'light') light = ins;
    }
    expect(light?.estimate).toBe(EXAM_DEFAULTS.L);
    expect(light?.rows).toEqual([]);
  });
});
