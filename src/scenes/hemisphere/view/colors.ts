/**
 * Colour of a point (ξ₁, ξ₂) of the unit square: a bilinear blend of four corner colours, so the
 * same colour marks a point in the square and its image on the hemisphere (the warp made visible).
 */
const C00 = [0.16, 0.4, 0.95]; // ξ = (0, 0): blue
const C10 = [0.98, 0.55, 0.1]; // (1, 0): orange
const C01 = [0.1, 0.72, 0.42]; // (0, 1): green
const C11 = [0.85, 0.18, 0.62]; // (1, 1): magenta

// corner colours scaled to 0…255 (+0.5 so that truncation on store rounds)
const R0 = C00[0] * 255,
  G0 = C00[1] * 255,
  B0 = C00[2] * 255;
const RA = (C10[0] - C00[0]) * 255,
  GA = (C10[1] - C00[1]) * 255,
  BA = (C10[2] - C00[2]) * 255;
const RB = (C01[0] - C00[0]) * 255,
  GB = (C01[1] - C00[1]) * 255,
  BB = (C01[2] - C00[2]) * 255;
const RAB = (C11[0] - C10[0] - C01[0] + C00[0]) * 255;
const GAB = (C11[1] - C10[1] - C01[1] + C00[1]) * 255;
const BAB = (C11[2] - C10[2] - C01[2] + C00[2]) * 255;

/** Write the RGB (0…255) of (a, b) ∈ [0, 1]² into out[o..o+2] (bilinear in the corner colours). */
export function xiColor(a: number, b: number, out: Uint8Array | number[], o = 0): void {
  const ab = a * b;
  out[o] = Math.floor(R0 + RA * a + RB * b + RAB * ab + 0.5);
  out[o + 1] = Math.floor(G0 + GA * a + GB * b + GAB * ab + 0.5);
  out[o + 2] = Math.floor(B0 + BA * a + BB * b + BAB * ab + 0.5);
}

/**
 * The brightness the (ξ₁, ξ₂) colours are drawn at. On the light theme's pale backgrounds (the 3D
 * view's, the panel behind the square) the orange and green corners are under 3 : 1 at full
 * brightness, so there every colour is drawn at 70 %; the dark theme shows them as they are
 * (tests/scenes/hemisphere/plotColors.test.ts checks both over the whole square).
 */
export const pointShade = (dark: boolean): number => (dark ? 1 : 0.7);
