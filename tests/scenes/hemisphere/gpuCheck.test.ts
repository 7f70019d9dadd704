// The GPU warp's check, run here on directions made by the float32 emulation of the shader: the
// exam's warp in either form passes the χ² test and matches the emulation exactly; a warp with a
// uniform φ (the e^φ factor forgotten) fails the χ² test; the other form's directions are told
// apart from the emulation.
import { describe, expect, it } from 'vitest';
import { gpuXi } from '../../../src/core/sampling';
import {
  checkGpuDirections,
  emulateWarp,
  EMULATED,
  type WarpForm,
} from '../../../src/scenes/hemisphere/gpuCheck';

const N = 200_000;

function directions(seed: number, form: WarpForm, uniformPhi = false): Float32Array {
  const out = new Float32Array(3 * N);
  for (let i = 0; i < N; i++) {
    let d = emulateWarp(i, seed, form);
    if (uniformPhi) {
      const s = Math.hypot(d[0], d[1]);
      const phi = 2 * Math.PI * gpuXi(i, seed)[1];
      d = [s * Math.cos(phi), s * Math.sin(phi), d[2]];
    }
    out.set(d, 3 * i);
  }
  return out;
}

const check = (dirs: Float32Array, seed: number, form: WarpForm) =>
  checkGpuDirections({ dirs, seed, form, alpha: 0.01, tests: 2 });

describe('checkGpuDirections', () => {
  for (const form of [0, 1] as const)
    it(`form ${form}: the exam's warp passes, and equals the emulation`, () => {
      const c = check(directions(11, form), 11, form);
      expect(c.pass).toBe(true);
      expect(c.p).toBeGreaterThan(c.threshold);
      expect(c.dof).toBeGreaterThan(100);
      expect(c.dof).toBeLessThanOrEqual(10 * 20 - 1);
      expect(c.maxDiff).toBe(0);
    });

  it('a uniform φ fails the χ² test', () => {
    const c = check(directions(11, 1, true), 11, 1);
    expect(c.pass).toBe(false);
    expect(c.p).toBeLessThan(c.threshold);
  });

  it('the other form’s directions differ from the emulation (first EMULATED only)', () => {
    const c = check(directions(11, 0), 11, 1);
    expect(c.maxDiff).toBeGreaterThan(0);
    expect(EMULATED).toBeLessThanOrEqual(N);
  });
});
