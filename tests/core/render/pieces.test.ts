/**
 * The render lab's building blocks, each against what it must be: the frame is orthonormal, the
 * camera's corner rays span the field of view, intersection finds the nearest object, the MIS
 * weights of two techniques sum to 1, the light technique's density integrates to 1 over its
 * samples' support, relMSE is the mean relative squared error, the scenes are built as described.
 */
import { describe, expect, it } from 'vitest';
import { frameAround, newFrame, toWorld } from '../../../src/core/render/frame';
import { cameraRay, makeCamera } from '../../../src/core/render/camera';
import { closestHit, newHit, offsetOrigin } from '../../../src/core/render/intersect';
import { misWeight } from '../../../src/core/render/mis';
import { relMse } from '../../../src/core/render/relMse';
import { emitterCount, lightFramesAt, lightPdf, sampleEmitter } from '../../../src/core/render/lightSampling';
import { sphereClearOfPyramid } from '../../../src/core/render/reference';
import {
  EXAM_DEFAULTS,
  VEACH_LIGHT_POWER,
  defaultView,
  examScene,
  furnaceScene,
  texelAlbedo,
  veachScene,
} from '../../../src/core/render/scene';
import { bsdfEval, bsdfPdf, bsdfSample, newVertex, shadeVertex } from '../../../src/core/render/material';
import { Rng } from '../../../src/core/random/rng';

const dot = (a: ArrayLike<number>, b: ArrayLike<number>) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('frame', () => {
  it('completes any unit vector to a right-handed orthonormal basis', () => {
    const rng = new Rng(4);
    for (let k = 0; k < 200; k++) {
      const z = k === 0 ? -1 : k === 1 ? 1 : 2 * rng.nextFloat() - 1;
      const phi = 2 * Math.PI * rng.nextFloat();
      const s = Math.sqrt(1 - z * z);
      const f = frameAround(s * Math.cos(phi), s * Math.sin(phi), z, newFrame());
      const t = [f.tx, f.ty, f.tz],
        b = [f.bx, f.by, f.bz],
        n = [f.nx, f.ny, f.nz];
      expect(dot(t, t)).toBeCloseTo(1, 12);
      expect(dot(b, b)).toBeCloseTo(1, 12);
      expect(dot(t, b)).toBeCloseTo(0, 12);
      expect(dot(t, n)).toBeCloseTo(0, 12);
      expect(dot(b, n)).toBeCloseTo(0, 12);
      // t × b = n
      expect(t[1] * b[2] - t[2] * b[1]).toBeCloseTo(n[0], 12);
      const out = [0, 0, 0];
      toWorld(f, 0, 0, 1, out);
      for (let i = 0; i < 3; i++) expect(out[i]).toBeCloseTo(n[i], 15);
    }
  });
});

describe('camera', () => {
  it('shoots the centre ray at the look point and the corner rays at the field of view', () => {
    const view = { eye: [1, -5, 2] as const, look: [1, 0, 2] as const, fov: 60 };
    const cam = makeCamera(view, 4, 2);
    const d = [0, 0, 0];
    cameraRay(cam, 2, 1, 0, 0, d); // the image centre
    expect(d[0]).toBeCloseTo(0, 15);
    expect(d[1]).toBeCloseTo(1, 15);
    cameraRay(cam, 0, 0, 0, 0, d); // top left corner: left (−x) and up (+z)
    const t = Math.tan(Math.PI / 6);
    expect(d[2] / d[1]).toBeCloseTo(t, 12);
    expect(-d[0] / d[1]).toBeCloseTo(2 * t, 12);
    // row j grows downwards, column i to the right
    cameraRay(cam, 3, 1, 0.5, 0.5, d);
    expect(d[0]).toBeGreaterThan(0);
    expect(d[2]).toBeLessThan(0);
  });

  it('looks straight down, and survives eye = look and a silly fov', () => {
    const down = makeCamera({ eye: [0, 0, 5], look: [0, 0, 0], fov: 40 }, 8, 8);
    const d = [0, 0, 0];
    cameraRay(down, 4, 4, 0, 0, d);
    expect(d[2]).toBeCloseTo(-1, 15);
    const same = makeCamera({ eye: [0, 0, 0], look: [0, 0, 0], fov: NaN }, 8, 8);
    cameraRay(same, 4, 4, 0, 0, d);
    expect(d[1]).toBeCloseTo(1, 15);
  });
});

describe('intersection', () => {
  it('takes the nearest of floor, sphere, light and plate', () => {
    const exam = examScene();
    const h = newHit();
    expect(closestHit(exam, 0, -6, 3.5, 0, 0, -1, Infinity, h)).toBe('floor');
    expect(h.t).toBeCloseTo(3.5, 15);
    expect(closestHit(exam, 0, 0, 5, 0, 0, -1, Infinity, h)).toBe('sphere');
    expect(h.t).toBeCloseTo(4, 14);
    expect([h.nx, h.ny, h.nz]).toEqual([0, 0, 1]);
    expect(closestHit(exam, 0, -0.5, 1.5, 0, 0, 1, Infinity, h)).toBe('light');
    expect(closestHit(exam, 0, -6, 3.5, 0, 0, -1, 3, h)).toBe('none');
    expect(h.t).toBe(Infinity);
    const veach = veachScene();
    const p = veach.plates[2].rect.center;
    expect(closestHit(veach, p[0], p[1], p[2] + 1, 0, 0, -1, Infinity, h)).toBe('plate');
    expect(h.index).toBe(2);
  });

  it('starts secondary rays just off the surface', () => {
    const o = [0, 0, 0];
    offsetOrigin(1e6, 0, 0, 0, 0, 1, o);
    expect(o[2]).toBeCloseTo(1e-3, 12);
    offsetOrigin(0.5, 0, 0, 0, 0, 1, o);
    expect(o[2]).toBe(1e-9);
  });
});

describe('MIS weights', () => {
  it('sum to 1 over the two techniques, and favour the larger density', () => {
    for (const h of ['balance', 'power'] as const) {
      for (const [a, b] of [
        [1, 1],
        [0.3, 7],
        [1e-300, 1e300],
        [5, 0],
      ]) {
        expect(misWeight(h, a, b) + misWeight(h, b, a)).toBeCloseTo(1, 15);
      }
      expect(misWeight(h, 0, 3)).toBe(0);
      expect(misWeight(h, 4, 1)).toBeGreaterThan(0.5);
    }
    expect(misWeight('balance', 3, 1)).toBe(0.75);
    expect(misWeight('power', 3, 1)).toBeCloseTo(0.9, 15);
  });
});

describe('relMSE', () => {
  it('is the mean of (I − R)²/(R² + ε), skipping non-finite references', () => {
    expect(relMse([1, 2, 3], [1, 1, NaN], 0)).toBe(0.5);
    expect(relMse([0.1], [0], 0.01)).toBeCloseTo(1, 15);
    expect(relMse([1], [NaN])).toBeNaN();
  });
});

describe('the scenes', () => {
  it('maps texels onto albedos in [0.2, 0.8]', () => {
    expect(texelAlbedo(1, 1, 25)).toBe(0.2);
    expect(texelAlbedo(25, 1, 25)).toBe(0.8);
    expect(texelAlbedo(13, 1, 25)).toBeCloseTo(0.5, 15);
    expect(texelAlbedo(99, 1, 25)).toBe(0.8);
    expect(texelAlbedo(-9, 1, 25)).toBe(0.2);
    expect(texelAlbedo(3, 3, 3)).toBe(0.5);
  });

  it('builds the exam scene from the area-light, ray–sphere and texture scenes’ defaults', () => {
    const s = examScene();
    expect(s.floorAlbedo).toBe(EXAM_DEFAULTS.rho);
    expect(s.lights[0].rect.center).toEqual([0, -0.5, 2]);
    expect(s.lights[0].rect.tiltDeg).toBe(-30);
    expect(s.sphere?.center).toEqual([0, 0, 0]);
    expect([s.sphere?.texMin, s.sphere?.texMax]).toEqual([1, 25]);
    expect(emitterCount(s)).toBe(1);
    expect(emitterCount(furnaceScene())).toBe(1);
  });

  it('gives the veach lights equal power and the plates rising roughness', () => {
    const s = veachScene();
    expect(s.lights).toHaveLength(4);
    for (const l of s.lights) expect(l.L * l.rect.area).toBeCloseTo(VEACH_LIGHT_POWER, 12);
    const e = s.plates.map((p) => p.exponent);
    expect([...e].sort((a, b) => b - a)).toEqual(e);
    // every plate mirrors the camera towards the row of lights: its normal bisects the two
    const eye = defaultView('veach').eye;
    for (const p of s.plates) {
      const c = p.rect.center;
      const toEye = [eye[0] - c[0], eye[1] - c[1], eye[2] - c[2]];
      const le = Math.hypot(toEye[0], toEye[1], toEye[2]);
      expect(dot(toEye, p.rect.normal) / le).toBeGreaterThan(0.3);
    }
  });
});

describe('light sampling', () => {
  it('agrees with lightPdf, and its solid-angle density integrates to 1 (Monte Carlo over the sphere)', () => {
    const scene = veachScene();
    const p = [0.3, -0.4, 0.1] as const;
    const frames = lightFramesAt(scene, p[0], p[1], p[2]);
    const e = { light: 0, x: 0, y: 0, z: 0, pdf: 0 };
    const buf = new Float64Array(3);
    const rng = new Rng(8);
    for (let k = 0; k < 50; k++) {
      expect(
        sampleEmitter(
          scene,
          frames,
          'solid-angle',
          rng.nextFloat(),
          rng.nextFloat(),
          rng.nextFloat(),
          e,
          buf,
        ),
      ).toBe(true);
      expect(lightPdf(scene, frames, e.light, e.x, e.y, e.z)).toBeCloseTo(e.pdf, 9);
    }
    // ∫ pdf dω over uniform directions, for the exam's one light (1/Ω over its solid angle Ω)
    const exam = { ...examScene(), sphere: null, floorAlbedo: null };
    const examFrames = lightFramesAt(exam, p[0], p[1], p[2]);
    const h = newHit();
    let sum = 0;
    const n = 400000;
    for (let k = 0; k < n; k++) {
      const z = 2 * rng.nextFloat() - 1,
        phi = 2 * Math.PI * rng.nextFloat(),
        s = Math.sqrt(1 - z * z);
      const d = [s * Math.cos(phi), s * Math.sin(phi), z];
      if (closestHit(exam, p[0], p[1], p[2], d[0], d[1], d[2], Infinity, h) === 'light')
        sum += lightPdf(exam, examFrames, h.index, h.px, h.py, h.pz) * 4 * Math.PI;
    }
    expect(Math.abs(sum / n - 1)).toBeLessThan(0.04);
  });

  it('samples the environment uniformly, and finds nothing in a scene without emitters', () => {
    const f = furnaceScene();
    const e = { light: 0, x: 0, y: 0, z: 0, pdf: 0 };
    expect(sampleEmitter(f, null, 'area', 0, 0.25, 0.5, e, new Float64Array(3))).toBe(true);
    expect(e.light).toBe(-1);
    expect(e.pdf).toBeCloseTo(1 / (4 * Math.PI), 15);
    expect(Math.hypot(e.x, e.y, e.z)).toBeCloseTo(1, 15);
    expect(lightPdf(f, lightFramesAt(f, 0, 0, 0), -1, 0, 0, 1)).toBeCloseTo(1 / (4 * Math.PI), 15);
    const dark = { ...f, environment: 0 };
    expect(emitterCount(dark)).toBe(0);
    expect(sampleEmitter(dark, null, 'area', 0, 0, 0, e, new Float64Array(3))).toBe(false);
    expect(lightPdf(dark, lightFramesAt(dark, 0, 0, 0), -1, 0, 0, 1)).toBe(0);
  });
});

describe('materials', () => {
  it('samples the Phong lobe about the mirror direction, with the pdf it evaluates', () => {
    const scene = veachScene();
    const h = newHit();
    const c = scene.plates[1].rect.center;
    const eye = defaultView('veach').eye;
    const d = [c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]];
    const l = Math.hypot(d[0], d[1], d[2]);
    expect(closestHit(scene, eye[0], eye[1], eye[2], d[0] / l, d[1] / l, d[2] / l, Infinity, h)).toBe(
      'plate',
    );
    const v = newVertex();
    shadeVertex(scene, h, d[0] / l, d[1] / l, d[2] / l, v);
    expect(v.glossy).toBe(true);
    const out = new Float64Array(3);
    const rng = new Rng(2);
    for (let k = 0; k < 20; k++) {
      const lz = bsdfSample(v, rng.nextFloat(), rng.nextFloat(), out);
      const n = v.exponent;
      expect(bsdfPdf(v, out[0], out[1], out[2])).toBeCloseTo(((n + 1) / (2 * Math.PI)) * lz ** n, 6);
      if (dot(out, [v.nx, v.ny, v.nz]) > 0)
        expect(bsdfEval(v, out[0], out[1], out[2])).toBeCloseTo(
          v.ks * ((n + 2) / (2 * Math.PI)) * lz ** n,
          6,
        );
    }
    // below the surface: no reflection
    expect(bsdfEval(v, -v.nx, -v.ny, -v.nz)).toBe(0);
  });
});

describe('the exact reference’s occlusion test', () => {
  it('clears a sphere outside the pyramid and refuses one inside it', () => {
    const light = examScene().lights[0].rect;
    expect(sphereClearOfPyramid(light, 0, -3, 0, [0, 3, 0.5], 0.5)).toBe(true);
    expect(sphereClearOfPyramid(light, 0, -0.5, 0, [0, -0.5, 1], 0.3)).toBe(false);
    // beyond the light, away from p
    expect(sphereClearOfPyramid(light, 0, -0.5, 0, [0, -0.5, 4], 0.5)).toBe(true);
  });
});
