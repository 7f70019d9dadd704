/*
 * C baseline for the batched exam-lobe kernel (p(ω) = k cos θ e^φ on the upper hemisphere):
 *   sin θ = √ξ1 (⇔ θ = ½ acos(1 − 2ξ1) = asin √ξ1), φ = log1p((e^{2π} − 1) ξ2),
 *   out = (sin θ cos φ, sin θ sin φ, cos θ), unit vectors interleaved in a double array.
 * The same arithmetic as sampleExamLobeBatch in src/core/sampling/examLobe.ts.
 * Build: gcc -O2 -o exam_lobe exam_lobe.c -lm. Prints one JSON object with samples/second
 * (best of several repetitions over N samples), so scripts/bench.mjs can compare it with JS.
 */
#define _POSIX_C_SOURCE 199309L
#define PI_D 3.14159265358979323846
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static void exam_lobe_batch(const double *restrict u, double *restrict out, long n) {
  const double c0 = expm1(2.0 * PI_D);
  const double two_pi = 2.0 * PI_D;
  const double two_pi_below = 6.283185307179585;
  for (long i = 0; i < n; i++) {
    const double u1 = u[2 * i];
    const double s = sqrt(u1);
    double phi = log1p(c0 * u[2 * i + 1]);
    if (phi >= two_pi) phi = two_pi_below;
    out[3 * i] = s * cos(phi);
    out[3 * i + 1] = s * sin(phi);
    out[3 * i + 2] = sqrt(1.0 - u1);
  }
}

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv) {
  long n = argc > 1 ? atol(argv[1]) : 1000000;
  int reps = argc > 2 ? atoi(argv[2]) : 15;
  double *u = malloc(sizeof(double) * 2 * n);
  double *out = malloc(sizeof(double) * 3 * n);
  if (!u || !out) return 1;
  uint64_t x = 0x9e3779b97f4a7c15ull; /* splitmix64 for the inputs */
  for (long i = 0; i < 2 * n; i++) {
    uint64_t z = (x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    u[i] = (double)(z >> 11) * 0x1.0p-53;
  }
  double best = 1e300, checksum = 0;
  for (int r = 0; r < reps; r++) {
    double t0 = now_s();
    exam_lobe_batch(u, out, n);
    double dt = now_s() - t0;
    if (dt < best) best = dt;
    checksum += out[3 * (r % n) + 2];
  }
  printf("{\"n\": %ld, \"reps\": %d, \"bestSeconds\": %.9g, \"samplesPerSecond\": %.6g, \"checksum\": %.17g}\n", n, reps, best,
         (double)n / best, checksum);
  free(u);
  free(out);
  return 0;
}
