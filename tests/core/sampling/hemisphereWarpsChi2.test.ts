/**
 * Distribution tests of the hemisphere warps with the χ² test the scene uses (core/verify):
 * every correct sampler is accepted at α = 0.01 (Šidák-corrected over the tests in this file) and
 * deliberately broken variants (a missing square root, a wrong exponent) are rejected.
 * Source: Nori `warptest`, Mitsuba 3 `test_warp.py`, pbrt-v4 `sampling_test.cpp`.
 */
import { describe, expect, it } from 'vitest';
import { hemisphereChi2 } from '../../../src/core/verify';
import { fillSequence2D } from '../../../src/core/random';
import {
  EXAM_E2PI_M1,
  cosineHemispherePdf,
  examLobePdf,
  phongLobePdf,
  sampleCosineHemisphereBatch,
  sampleExamLobeBatch,
  samplePhongLobeBatch,
  sampleUniformHemisphereBatch,
  uniformHemispherePdf,
} from '../../../src/core/sampling';

const N = 200_000;
const TESTS = 6; // correct samplers checked in this file (Šidák)

function uniforms(seed: number): Float64Array {
  return fillSequence2D('independent', seed, N, new Float64Array(2 * N));
}

function run(sample: (u: Float64Array, out: Float64Array) => void, pdf: (x: number, y: number, z: number) => number, seed: number) {
  const out = new Float64Array(3 * N);
  sample(uniforms(seed), out);
  return hemisphereChi2(out, N, pdf, { tests: TESTS, cosThetaBins: 10, phiBins: 20 });
}

describe('χ² acceptance of the hemisphere warps (α = 0.01, Šidák)', () => {
  it('exam lobe k cos θ e^φ', () => {
    const r = run((u, o) => sampleExamLobeBatch(u, o, N), examLobePdf, 1);
    expect(r.outside).toBe(0);
    expect(r.pass).toBe(true);
  });
  it('uniform hemisphere', () => {
    const r = run((u, o) => sampleUniformHemisphereBatch(u, o, N), (_x, _y, z) => uniformHemispherePdf(z), 2);
    expect(r.pass).toBe(true);
  });
  it('cosine hemisphere', () => {
    const r = run((u, o) => sampleCosineHemisphereBatch(u, o, N), (_x, _y, z) => cosineHemispherePdf(z), 3);
    expect(r.pass).toBe(true);
  });
  it('Phong lobe n = 8 and n = 50', () => {
    for (const [n, seed] of [
      [8, 4],
      [50, 5],
    ]) {
      const r = run((u, o) => samplePhongLobeBatch(u, o, N, n), (_x, _y, z) => phongLobePdf(z, n), seed);
      expect(r.pass).toBe(true);
    }
  });
  it('exam lobe with Sobol points is accepted too (marginals stay exact)', () => {
    const out = new Float64Array(3 * N);
    sampleExamLobeBatch(fillSequence2D('sobol', 9, N, new Float64Array(2 * N)), out, N);
    const r = hemisphereChi2(out, N, examLobePdf, { tests: TESTS });
    expect(r.pass).toBe(true);
  });
});

describe('χ² rejects broken samplers', () => {
  it('exam lobe with a missing square root (sin θ = ξ₁ instead of √ξ₁)', () => {
    const r = run((u, o) => {
      for (let i = 0; i < N; i++) {
        const s = u[2 * i];
        const phi = Math.log1p(EXAM_E2PI_M1 * u[2 * i + 1]);
        o[3 * i] = s * Math.cos(phi);
        o[3 * i + 1] = s * Math.sin(phi);
        o[3 * i + 2] = Math.sqrt(1 - s * s);
      }
    }, examLobePdf, 11);
    expect(r.pass).toBe(false);
    expect(r.pValue).toBeLessThan(1e-10);
  });
  it('exam lobe with a wrong exponent in φ (P(φ) from e^{2φ})', () => {
    const c2 = Math.expm1(4 * Math.PI);
    const r = run((u, o) => {
      for (let i = 0; i < N; i++) {
        const s = Math.sqrt(u[2 * i]);
        const phi = 0.5 * Math.log1p(c2 * u[2 * i + 1]);
        o[3 * i] = s * Math.cos(phi);
        o[3 * i + 1] = s * Math.sin(phi);
        o[3 * i + 2] = Math.sqrt(1 - u[2 * i]);
      }
    }, examLobePdf, 12);
    expect(r.pass).toBe(false);
  });
  it('Phong sampler with exponent n + 1 tested against the pdf for n (n = 8)', () => {
    const r = run((u, o) => samplePhongLobeBatch(u, o, N, 9), (_x, _y, z) => phongLobePdf(z, 8), 13);
    expect(r.pass).toBe(false);
  });
  it('uniform sampler tested against the cosine pdf', () => {
    const r = run((u, o) => sampleUniformHemisphereBatch(u, o, N), (_x, _y, z) => cosineHemispherePdf(z), 14);
    expect(r.pass).toBe(false);
  });
});
