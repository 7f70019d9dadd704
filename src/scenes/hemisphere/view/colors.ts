/**
 * Colour of a point (ξ₁, ξ₂) of the unit square: a bilinear blend of four corner colours, so the
 * same colour marks a point in the square and its image on the hemisphere (the warp made visible).
 */
const C00 = [0.16, 0.4, 0.95]; // ξ = (0, 0): blue
const C10 = [0.98, 0.55, 0.1]; // (1, 0): orange
const C01 = [0.1, 0.72, 0.42]; // (0, 1): green
const C11 = [0.85, 0.18, 0.62]; // (1, 1): magenta

/** Write the RGB (0…255) of (a, b) ∈ [0, 1]² into out[o..o+2]. */
export function xiColor(a: number, b: number, out: Uint8Array | number[], o = 0): void {
  for (let c = 0; c < 3; c++) {
    const v = (1 - a) * (1 - b) * C00[c]! + a * (1 - b) * C10[c]! + (1 - a) * b * C01[c]! + a * b * C11[c]!;
    out[o + c] = Math.round(v * 255);
  }
}

/** CSS colour string of (a, b). */
export function xiCss(a: number, b: number): string {
  const c = [0, 0, 0];
  xiColor(a, b, c);
  return `rgb(${c[0]},${c[1]},${c[2]})`;
}
