/**
 * The display's encoding of a linear value: clipped to [0, 1], then the sRGB transfer function
 * (IEC 61966-2-1: linear below 0.0031308, a 1/2.4 power above), as an 8-bit level. What the app
 * shows of a rendered image, and what it measures FLIP on, are these bytes.
 */
export function srgbByte(linear: number): number {
  const x = linear > 0 ? (linear < 1 ? linear : 1) : 0;
  const s = x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055;
  return Math.round(255 * s);
}
