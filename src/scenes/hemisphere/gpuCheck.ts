/**
 * The check of the GPU warp's directions (./view/GpuWarpPanel): a χ² test of the 10⁶ directions
 * the vertex shader wrote against the exam's pdf, and their largest difference from a float32
 * emulation of the same shader arithmetic over the first 4096. Pure and synchronous; the page
 * runs it in the scene's worker (./hemisphere.worker), since binning 10⁶ directions takes a few
 * hundred ms.
 */
import { examLobePdf, gpuXi, phiLnF32, phiLog1pF32, thetaAcosF32 } from '../../core/sampling';
import { hemisphereChi2 } from '../../core/verify';

/** The shader's two forms of the exam's inversion: 0 textbook (arccos, ln), 1 stable (√, log1p). */
export type WarpForm = 0 | 1;

/** Directions compared with the emulation (the first ones the shader made). */
export const EMULATED = 4096;

export interface GpuCheckArgs {
  /** x, y, z per direction, as read back from the transform-feedback buffer. */
  dirs: Float32Array;
  seed: number;
  form: WarpForm;
  /** χ² significance before the Šidák correction, and how many tests share it. */
  alpha: number;
  tests: number;
}

export interface GpuCheck {
  p: number;
  statistic: number;
  dof: number;
  threshold: number;
  pass: boolean;
  /** Largest |GPU − emulation| over the first EMULATED directions' components (absolute). */
  maxDiff: number;
  /** How long the check took where it ran (ms). */
  ms: number;
}

/** The float32 emulation of sample i (the vertex shader's arithmetic, correctly rounded built-ins). */
export function emulateWarp(i: number, seed: number, form: WarpForm): [number, number, number] {
  const fr = Math.fround;
  const [x1, x2] = gpuXi(i, seed);
  let s: number;
  let c: number;
  let phi: number;
  if (form === 0) {
    const th = thetaAcosF32(x1);
    s = fr(Math.sin(th));
    c = fr(Math.cos(th));
    phi = phiLnF32(x2);
  } else {
    s = fr(Math.sqrt(x1));
    c = fr(Math.sqrt(fr(1 - x1)));
    phi = phiLog1pF32(x2);
  }
  phi = Math.min(phi, fr(6.283185));
  return [fr(s * fr(Math.cos(phi))), fr(s * fr(Math.sin(phi))), c];
}

export function checkGpuDirections({ dirs, seed, form, alpha, tests }: GpuCheckArgs): GpuCheck {
  const t0 = performance.now();
  const n = Math.floor(dirs.length / 3);
  const res = hemisphereChi2(Float64Array.from(dirs), n, examLobePdf, {
    cosThetaBins: 10,
    phiBins: 20,
    alpha,
    tests,
  });
  let maxDiff = 0;
  for (let i = 0; i < Math.min(EMULATED, n); i++) {
    const e = emulateWarp(i, seed, form);
    for (let k = 0; k < 3; k++) maxDiff = Math.max(maxDiff, Math.abs(dirs[3 * i + k] - e[k]));
  }
  return {
    p: res.pValue,
    statistic: res.statistic,
    dof: res.dof,
    threshold: res.sidakAlpha,
    pass: res.pass,
    maxDiff,
    ms: performance.now() - t0,
  };
}
