/**
 * The GPU renderer's random numbers, in GLSL: every (pixel, sample index, seed) starts its own
 * stream, so a frame needs no state from the last one and the image does not depend on how the GPU
 * schedules its work. The start is a hash of the three numbers; the stream is PCG's 32-bit LCG step
 * followed by its RXS-M-XS output permutation (O'Neill, "PCG: A Family of Simple Fast
 * Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014), which is also
 * the hash: `pcg` of Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020. The
 * top 24 bits make a float in [0, 1) with every value exact in float32. The streams differ from the
 * CPU renderer's (core/random/rng): the two agree in distribution, not sample by sample.
 */
export const GLSL_RANDOM = `
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

uint rngState;

void rngInit(uint pixel, uint index, uint seed) {
  rngState = pcgHash(pixel ^ pcgHash(index ^ pcgHash(seed)));
}

float rand() {
  rngState = rngState * 747796405u + 2891336453u;
  uint s = rngState;
  uint word = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
  return float(((word >> 22u) ^ word) >> 8u) * (1.0 / 16777216.0);
}
`;
