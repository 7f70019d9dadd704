/**
 * s·cos φ and s·sin φ from one argument reduction: the hot path of every azimuthal warp computes
 * both, and V8's Math.cos and Math.sin each reduce the argument and evaluate their own kernel.
 *
 * Method (fdlibm, Sun Microsystems 1993, e_rem_pio2.c "medium" case and k_sin.c / k_cos.c):
 * q = nearest integer to φ/(π/2); r = φ − q·π/2 by a Cody–Waite reduction with π/2 split into
 * three 33-bit parts and a tail (each q·PIO2_k exact for |q| < 2²⁰); then fdlibm's
 * minimax polynomials for sin r and cos r on [−π/4, π/4], and the quadrant picks the signs.
 *
 * Domain: |φ| ≤ 2¹⁹·π/2 (≈ 8.2e5) uses the fused path; beyond it, and for non-finite φ, it defers
 * to Math.cos / Math.sin. Accuracy (tests/core/sampling/sinCos.test.ts, against mathjs BigNumber):
 * absolute error ≤ 2⁻⁵³ on [0, 2π] and near-correct relative accuracy at the zeros of sin and cos.
 */

// π/2 = PIO2_1 + PIO2_2 + PIO2_3 + PIO2_3T, the first three of 33 bits each, so q·PIO2_k is
// exact for |q| < 2²⁰ (fdlibm e_rem_pio2.c: pio2_1, pio2_2, pio2_3, pio2_3t).
const PIO2_1 = 1.57079632673412561417;
const PIO2_2 = 6.0771005063039659766e-11;
const PIO2_3 = 2.0222662487111664558e-21;
const PIO2_3T = 8.47842766036889956997e-32;
const TWO_OVER_PI = 0.6366197723675814;
const FUSED_LIMIT = 823549.6619; // 2^19 · π/2

const S1 = -1.66666666666666324348e-1;
const S2 = 8.33333333332248946124e-3;
const S3 = -1.98412698298579493134e-4;
const S4 = 2.75573137070700676789e-6;
const S5 = -2.50507602534068634195e-8;
const S6 = 1.58969099521155010221e-10;
const C1 = 4.16666666666666019037e-2;
const C2 = -1.38888888888741095749e-3;
const C3 = 2.48015872894767294178e-5;
const C4 = -2.75573143513906633035e-7;
const C5 = 2.0875723212981748279e-9;
const C6 = -1.13596475577881948265e-11;

/**
 * Writes s·cos φ to out[o] and s·sin φ to out[o + 1]. Domain: any φ (radians), any s.
 * Source: fdlibm k_sin.c, k_cos.c, e_rem_pio2.c (the polynomials and the reduction constants).
 */
export function writeScaledCosSin(phi: number, s: number, out: Float64Array | number[], o: number): void {
  if (!(phi <= FUSED_LIMIT && phi >= -FUSED_LIMIT)) {
    out[o] = s * Math.cos(phi);
    out[o + 1] = s * Math.sin(phi);
    return;
  }
  const q = Math.round(phi * TWO_OVER_PI);
  // phi − q·PIO2_1 is exact (both are multiples of 2⁻⁵⁰ below 8 and the difference is < 1), and so
  // is the next step when r is tiny (Sterbenz), so r keeps full relative accuracy near kπ/2.
  const r = phi - q * PIO2_1 - q * PIO2_2 - q * PIO2_3 - q * PIO2_3T;
  const z = r * r;
  const sn = r + r * z * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
  const cs = 1 - 0.5 * z + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  switch (q & 3) {
    case 0:
      out[o] = s * cs;
      out[o + 1] = s * sn;
      return;
    case 1:
      out[o] = -s * sn;
      out[o + 1] = s * cs;
      return;
    case 2:
      out[o] = -s * cs;
      out[o + 1] = -s * sn;
      return;
    default:
      out[o] = s * sn;
      out[o + 1] = -s * cs;
  }
}
