/**
 * Samples per second of hemisphere warps: the batched exam-lobe kernel (unit vectors into a
 * caller-owned Float64Array) beside a naive per-object version written the way the key writes the
 * formulas (θ = ½ arccos(1 − 2ξ₁), φ = ln((e^{2π} − 1)ξ₂ + 1), one {x, y, z} object per sample),
 * and the other batched warps. Run with `npx vitest bench bench/sampling.bench.ts --run`.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import {
  sampleCosineHemisphereBatch,
  sampleExamLobeBatch,
  samplePhongLobeBatch,
  sampleUniformHemisphereBatch,
} from '../src/core/sampling';

const N = 1_000_000;
const u = new Rng(1).fill(new Float64Array(2 * N));
const out = new Float64Array(3 * N);
const C = Math.exp(2 * Math.PI) - 1;

function naiveExam(n: number): { x: number; y: number; z: number }[] {
  const res: { x: number; y: number; z: number }[] = [];
  for (let i = 0; i < n; i++) {
    const theta = 0.5 * Math.acos(1 - 2 * u[2 * i]);
    const phi = Math.log(C * u[2 * i + 1] + 1);
    res.push({ x: Math.sin(theta) * Math.cos(phi), y: Math.sin(theta) * Math.sin(phi), z: Math.cos(theta) });
  }
  return res;
}

describe(`hemisphere warps, ${N.toExponential()} samples per iteration`, () => {
  bench('exam lobe, batched kernel (Float64Array out)', () => {
    sampleExamLobeBatch(u, out, N);
  });
  bench('exam lobe, naive (object per sample, key formulas)', () => {
    naiveExam(N);
  });
  bench('uniform hemisphere, batched', () => {
    sampleUniformHemisphereBatch(u, out, N);
  });
  bench('cosine hemisphere (concentric), batched', () => {
    sampleCosineHemisphereBatch(u, out, N);
  });
  bench('Phong n = 8, batched', () => {
    samplePhongLobeBatch(u, 8, out, N);
  });
});

/**
 * C baseline: the same exam-lobe kernel compiled with `gcc -O2 -lm`, over the same 10⁶ (ξ₁, ξ₂)
 * pairs (written to a temporary file), best of 7 runs, beside the JS kernel timed the same way.
 * Skipped (with a note) where gcc is absent; never fails the bench.
 */
const C_SOURCE = `
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec * 1e3 + t.tv_nsec * 1e-6; }
int main(int argc, char **argv) {
  long n = atol(argv[2]);
  double *u = malloc(sizeof(double) * 2 * n), *out = malloc(sizeof(double) * 3 * n);
  FILE *f = fopen(argv[1], "rb");
  if (!f || fread(u, sizeof(double), 2 * n, f) != (size_t)(2 * n)) return 1;
  fclose(f);
  const double c0 = expm1(2 * M_PI), twoPi = 2 * M_PI, below = nextafter(2 * M_PI, 0);
  double best = 1e30, sum = 0;
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    for (long i = 0; i < n; i++) {
      double u1 = u[2 * i], s = sqrt(u1), phi = log1p(c0 * u[2 * i + 1]);
      if (phi >= twoPi) phi = below;
      out[3 * i] = s * cos(phi);
      out[3 * i + 1] = s * sin(phi);
      out[3 * i + 2] = sqrt(1 - u1);
    }
    double t = now() - t0;
    if (t < best) best = t;
    sum += out[3 * (r * 7919 % n)];
  }
  printf("%.4f %.17g\\n", best, sum);
  return 0;
}
`;

function cBaseline(): void {
  let dir: string;
  try {
    execFileSync('gcc', ['--version'], { stdio: 'ignore' });
    dir = mkdtempSync(join(tmpdir(), 'exam-lobe-'));
  } catch {
    console.log('[sampling bench] gcc not found: C baseline skipped');
    return;
  }
  try {
    writeFileSync(join(dir, 'k.c'), C_SOURCE);
    writeFileSync(join(dir, 'u.bin'), new Uint8Array(u.buffer, u.byteOffset, u.byteLength));
    execFileSync('gcc', ['-O2', '-o', join(dir, 'k'), join(dir, 'k.c'), '-lm']);
    const cMs = Number(
      execFileSync(join(dir, 'k'), [join(dir, 'u.bin'), String(N)], { encoding: 'utf8' }).split(' ')[0],
    );
    let jsMs = Infinity;
    for (let r = 0; r < 7; r++) {
      const t0 = performance.now();
      sampleExamLobeBatch(u, out, N);
      jsMs = Math.min(jsMs, performance.now() - t0);
    }
    console.log(
      `[sampling bench] exam lobe, ${N} samples, best of 7: JS batched ${jsMs.toFixed(2)} ms (${((N / jsMs) * 1e3).toExponential(3)}/s), ` +
        `C gcc -O2 ${cMs.toFixed(2)} ms (${((N / cMs) * 1e3).toExponential(3)}/s): JS/C = ${(jsMs / cMs).toFixed(2)}×`,
    );
  } catch (e) {
    console.log(
      `[sampling bench] C baseline failed to build or run: ${e instanceof Error ? e.message : String(e)}`,
    );
  }
}
cBaseline();
