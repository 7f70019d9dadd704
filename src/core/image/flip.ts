/**
 * LDR-FLIP: the perceptual difference between a reference image and a test image, as a per-pixel
 * error in [0, 1], for an observer at a given number of pixels per degree of visual angle.
 *
 * Written from Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "FLIP: A
 * Difference Evaluator for Alternating Images", HPG 2020, and the constants of NVIDIA's reference
 * implementation (NVlabs/flip). The two pipelines:
 *
 * - colour: sRGB → linear RGB → XYZ → YCxCz (opponent space); each channel filtered by its
 *   contrast-sensitivity function (Gaussians whose width follows the pixels per degree); back to
 *   linear RGB, clamped to the unit cube; → L*a*b*, Hunt-adjusted (a, b scaled by L/100); the HyAB
 *   distance |ΔL| + ‖(Δa, Δb)‖ raised to q_c = 0.7 and mapped to [0, 1] by the piecewise-linear
 *   redistribution (p_c = 0.4, p_t = 0.95) against the largest such distance (green against blue);
 * - features: on the normalized achromatic channel (Y + 16)/116, edges (first derivative of a
 *   Gaussian) and points (second derivative), Gaussian σ = ½ · 0.082° in pixels; the larger of the
 *   differences of their magnitudes, / √2, raised to q_f = 0.5.
 *
 * The per-pixel error is ΔE_c^(1 − ΔE_f). Every filter is separable and applied as two 1-D passes
 * with the edge pixel repeated beyond the border, over Float64Arrays: O(pixels × kernel width).
 */

/** Pixels per degree of the reference tool's default observer: 0.7 m from a 0.7 m wide, 3840-pixel display. */
export const DEFAULT_PPD = ((0.7 * 3840) / 0.7) * (Math.PI / 180);

/** An image of sRGB values in [0, 1], three interleaved channels per pixel, rows from the top. */
export interface RgbImage {
  width: number;
  height: number;
  /** Length 3 · width · height. */
  data: Float32Array | Float64Array;
}

const QC = 0.7;
const QF = 0.5;
const PC = 0.4;
const PT = 0.95;
/** Peak-to-trough width of the human edge detector, in degrees (2 standard deviations). */
const EDGE_WIDTH_DEG = 0.082;

/** The CIE D65 white and its inverse, as the reference implementation gives them. */
const WHITE = [0.950428545, 1, 1.088900371] as const;
const INV_WHITE = [1.052156925, 1, 0.91835767] as const;

/** Linear sRGB → XYZ (D65), exact fractions. */
const RGB2XYZ = [
  10135552 / 24577794,
  8788810 / 24577794,
  4435075 / 24577794,
  2613072 / 12288897,
  8788810 / 12288897,
  887015 / 12288897,
  1425312 / 73733382,
  8788810 / 73733382,
  70074185 / 73733382,
] as const;
/** Its inverse, as published with the reference implementation. */
const XYZ2RGB = [
  3.241003275, -1.537398934, -0.498615861, -0.969224334, 1.875930071, 0.041554224, 0.055639423, -0.204011202,
  1.057148933,
] as const;

/** sRGB transfer function, decoded. */
export function srgbToLinear(c: number): number {
  return c > 0.04045 ? ((c + 0.055) / 1.055) ** 2.4 : c / 12.92;
}

/** Linear sRGB → CIE L*a*b* (D65 white). Writes [L, a, b] into out. */
export function linearRgbToLab(r: number, g: number, b: number, out: number[]): void {
  const delta = 6 / 29;
  const f = (t: number) => (t > delta * delta * delta ? Math.cbrt(t) : t / (3 * delta * delta) + 4 / 29);
  const x = f((RGB2XYZ[0] * r + RGB2XYZ[1] * g + RGB2XYZ[2] * b) * INV_WHITE[0]);
  const y = f((RGB2XYZ[3] * r + RGB2XYZ[4] * g + RGB2XYZ[5] * b) * INV_WHITE[1]);
  const z = f((RGB2XYZ[6] * r + RGB2XYZ[7] * g + RGB2XYZ[8] * b) * INV_WHITE[2]);
  out[0] = 116 * y - 16;
  out[1] = 500 * (x - y);
  out[2] = 200 * (y - z);
}

/** HyAB distance between two Hunt-adjusted L*a*b* colours (the adjustment done here). */
export function huntHyab(l1: number, a1: number, b1: number, l2: number, a2: number, b2: number): number {
  const h1 = 0.01 * l1;
  const h2 = 0.01 * l2;
  return Math.abs(l1 - l2) + Math.hypot(h1 * a1 - h2 * a2, h1 * b1 - h2 * b2);
}

/** The largest colour distance FLIP expects, green against blue, raised to q_c. */
export function maxColorDistance(): number {
  const g = [0, 0, 0];
  const b = [0, 0, 0];
  linearRgbToLab(0, 1, 0, g);
  linearRgbToLab(0, 0, 1, b);
  return huntHyab(g[0], g[1], g[2], b[0], b[1], b[2]) ** QC;
}

/** The power-law colour error (HyAB^q_c) mapped to [0, 1]: [0, p_c·cmax) → [0, p_t), the rest → [p_t, 1]. */
export function redistribute(e: number, cmax: number): number {
  const knee = PC * cmax;
  return e < knee ? (PT / knee) * e : PT + ((e - knee) / (cmax - knee)) * (1 - PT);
}

/** A normalized 1-D Gaussian exp(−π² (xΔ)² / b) on −r … r, with Δ = 1/ppd; also its raw sum. */
function csfGaussian(b: number, r: number, ppd: number): { taps: Float64Array; sum: number } {
  const taps = new Float64Array(2 * r + 1);
  let sum = 0;
  for (let i = -r; i <= r; i++) {
    const x = i / ppd;
    const v = Math.exp((-Math.PI * Math.PI * x * x) / b);
    taps[i + r] = v;
    sum += v;
  }
  for (let i = 0; i < taps.length; i++) taps[i] /= sum;
  return { taps, sum };
}

/**
 * One channel's contrast-sensitivity filter as a sum of separable Gaussians: terms of weight w and
 * 1-D taps (the 2-D kernel is Σ w · g(x) g(y), normalized to sum 1).
 */
export interface CsfFilter {
  terms: { weight: number; taps: Float64Array }[];
}

/**
 * The three filters (achromatic, red–green, blue–yellow) for `ppd` pixels per degree:
 * s(x) = a₁ √(π/b₁) e^(−π² x²/b₁) + a₂ √(π/b₂) e^(−π² x²/b₂), x in degrees, on a square of
 * radius ⌈3 √(b_max / (2π²)) · ppd⌉ pixels, normalized to sum 1.
 */
export function csfFilters(ppd: number): [CsfFilter, CsfFilter, CsfFilter] {
  const params: [number, number, number, number][] = [
    [1, 0.0047, 0, 1e-5],
    [1, 0.0053, 0, 1e-5],
    [34.1, 0.04, 13.5, 0.025],
  ];
  const bMax = 0.04;
  const r = Math.ceil(3 * Math.sqrt(bMax / (2 * Math.PI * Math.PI)) * ppd);
  return params.map(([a1, b1, a2, b2]) => {
    const g1 = csfGaussian(b1, r, ppd);
    const g2 = csfGaussian(b2, r, ppd);
    const w1 = a1 * Math.sqrt(Math.PI / b1) * g1.sum * g1.sum;
    const w2 = a2 * Math.sqrt(Math.PI / b2) * g2.sum * g2.sum;
    const total = w1 + w2;
    const terms = [{ weight: w1 / total, taps: g1.taps }];
    if (w2 > 0) terms.push({ weight: w2 / total, taps: g2.taps });
    return { terms };
  }) as [CsfFilter, CsfFilter, CsfFilter];
}

/**
 * 2-D correlation of a w × h plane with the separable kernel kx(x) · ky(y) (odd lengths, centred),
 * the border pixel repeated outside the image. `tmp` and `out` have length w · h.
 */
export function separable(
  src: Float64Array,
  w: number,
  h: number,
  kx: Float64Array,
  ky: Float64Array,
  tmp: Float64Array,
  out: Float64Array,
): void {
  const rx = (kx.length - 1) / 2;
  const ry = (ky.length - 1) / 2;
  for (let y = 0; y < h; y++) {
    const row = y * w;
    for (let x = 0; x < w; x++) {
      let s = 0;
      for (let k = -rx; k <= rx; k++) {
        const xx = x + k < 0 ? 0 : x + k >= w ? w - 1 : x + k;
        s += kx[k + rx] * src[row + xx];
      }
      tmp[row + x] = s;
    }
  }
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      let s = 0;
      for (let k = -ry; k <= ry; k++) {
        const yy = y + k < 0 ? 0 : y + k >= h ? h - 1 : y + k;
        s += ky[k + ry] * tmp[yy * w + x];
      }
      out[y * w + x] = s;
    }
  }
}

/** The feature detectors' 1-D pieces: the Gaussian (sum 1), its first and second derivatives (± parts sum to ±1). */
export function featureKernels(ppd: number): {
  gauss: Float64Array;
  edge: Float64Array;
  point: Float64Array;
} {
  const sd = 0.5 * EDGE_WIDTH_DEG * ppd;
  const r = Math.ceil(3 * sd);
  const n = 2 * r + 1;
  const gauss = new Float64Array(n);
  const edge = new Float64Array(n);
  const point = new Float64Array(n);
  for (let i = -r; i <= r; i++) {
    const g = Math.exp((-i * i) / (2 * sd * sd));
    gauss[i + r] = g;
    edge[i + r] = -i * g;
    point[i + r] = ((i * i) / (sd * sd) - 1) * g;
  }
  const normalizeSigned = (k: Float64Array) => {
    let pos = 0;
    let neg = 0;
    for (const v of k)
      if (v > 0) pos += v;
      else neg -= v;
    for (let i = 0; i < n; i++) k[i] = k[i] > 0 ? k[i] / pos : k[i] < 0 ? k[i] / neg : 0;
  };
  let gs = 0;
  for (const v of gauss) gs += v;
  for (let i = 0; i < n; i++) gauss[i] /= gs;
  normalizeSigned(edge);
  normalizeSigned(point);
  return { gauss, edge, point };
}

/** YCxCz planes of an sRGB image (each of length w · h). */
function toYCxCz(img: RgbImage): [Float64Array, Float64Array, Float64Array] {
  const n = img.width * img.height;
  const Y = new Float64Array(n);
  const Cx = new Float64Array(n);
  const Cz = new Float64Array(n);
  const d = img.data;
  for (let i = 0; i < n; i++) {
    const r = srgbToLinear(d[3 * i]);
    const g = srgbToLinear(d[3 * i + 1]);
    const b = srgbToLinear(d[3 * i + 2]);
    const x = (RGB2XYZ[0] * r + RGB2XYZ[1] * g + RGB2XYZ[2] * b) * INV_WHITE[0];
    const y = (RGB2XYZ[3] * r + RGB2XYZ[4] * g + RGB2XYZ[5] * b) * INV_WHITE[1];
    const z = (RGB2XYZ[6] * r + RGB2XYZ[7] * g + RGB2XYZ[8] * b) * INV_WHITE[2];
    Y[i] = 116 * y - 16;
    Cx[i] = 500 * (x - y);
    Cz[i] = 200 * (y - z);
  }
  return [Y, Cx, Cz];
}

/** One plane filtered by a CSF (a sum of separable terms). */
function filterCsf(plane: Float64Array, w: number, h: number, f: CsfFilter, tmp: Float64Array): Float64Array {
  const out = new Float64Array(w * h);
  const part = new Float64Array(w * h);
  for (const t of f.terms) {
    separable(plane, w, h, t.taps, t.taps, tmp, part);
    for (let i = 0; i < out.length; i++) out[i] += t.weight * part[i];
  }
  return out;
}

/** Hunt-adjusted L*a*b* planes of a CSF-filtered YCxCz image (clamped to the linear-RGB cube first). */
function filteredLab(
  ycc: [Float64Array, Float64Array, Float64Array],
  w: number,
  h: number,
  filters: [CsfFilter, CsfFilter, CsfFilter],
): Float64Array {
  const tmp = new Float64Array(w * h);
  const fy = filterCsf(ycc[0], w, h, filters[0], tmp);
  const fx = filterCsf(ycc[1], w, h, filters[1], tmp);
  const fz = filterCsf(ycc[2], w, h, filters[2], tmp);
  const lab = new Float64Array(3 * w * h);
  const c = [0, 0, 0];
  const clamp = (v: number) => (v < 0 ? 0 : v > 1 ? 1 : v);
  for (let i = 0; i < w * h; i++) {
    const yy = (fy[i] + 16) / 116;
    const X = (yy + fx[i] / 500) * WHITE[0];
    const Yv = yy * WHITE[1];
    const Z = (yy - fz[i] / 200) * WHITE[2];
    const r = clamp(XYZ2RGB[0] * X + XYZ2RGB[1] * Yv + XYZ2RGB[2] * Z);
    const g = clamp(XYZ2RGB[3] * X + XYZ2RGB[4] * Yv + XYZ2RGB[5] * Z);
    const b = clamp(XYZ2RGB[6] * X + XYZ2RGB[7] * Yv + XYZ2RGB[8] * Z);
    linearRgbToLab(r, g, b, c);
    lab[3 * i] = c[0];
    lab[3 * i + 1] = c[1];
    lab[3 * i + 2] = c[2];
  }
  return lab;
}

/** Magnitudes of the edge and point responses of the normalized achromatic plane. */
function features(
  Y: Float64Array,
  w: number,
  h: number,
  k: ReturnType<typeof featureKernels>,
): { edges: Float64Array; points: Float64Array } {
  const n = w * h;
  const yn = new Float64Array(n);
  for (let i = 0; i < n; i++) yn[i] = (Y[i] + 16) / 116;
  const tmp = new Float64Array(n);
  const ex = new Float64Array(n);
  const ey = new Float64Array(n);
  const px = new Float64Array(n);
  const py = new Float64Array(n);
  separable(yn, w, h, k.edge, k.gauss, tmp, ex);
  separable(yn, w, h, k.gauss, k.edge, tmp, ey);
  separable(yn, w, h, k.point, k.gauss, tmp, px);
  separable(yn, w, h, k.gauss, k.point, tmp, py);
  const edges = new Float64Array(n);
  const points = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    edges[i] = Math.hypot(ex[i], ey[i]);
    points[i] = Math.hypot(px[i], py[i]);
  }
  return { edges, points };
}

/**
 * The LDR-FLIP error map of `test` against `reference` (same size), one value in [0, 1] per pixel,
 * rows from the top. Throws a RangeError naming the problem when the sizes differ or are empty.
 */
export function flipErrorMap(reference: RgbImage, test: RgbImage, ppd = DEFAULT_PPD): Float64Array {
  const { width: w, height: h } = reference;
  if (w !== test.width || h !== test.height)
    throw new RangeError(`FLIP needs images of one size: ${w}×${h} against ${test.width}×${test.height}`);
  if (!(w > 0 && h > 0)) throw new RangeError('FLIP needs a non-empty image');
  if (!(ppd > 0 && Number.isFinite(ppd)))
    throw new RangeError(`pixels per degree must be positive, not ${ppd}`);
  const filters = csfFilters(ppd);
  const kernels = featureKernels(ppd);
  const refYcc = toYCxCz(reference);
  const testYcc = toYCxCz(test);
  const refLab = filteredLab(refYcc, w, h, filters);
  const testLab = filteredLab(testYcc, w, h, filters);
  const refF = features(refYcc[0], w, h, kernels);
  const testF = features(testYcc[0], w, h, kernels);
  const cmax = maxColorDistance();
  const out = new Float64Array(w * h);
  for (let i = 0; i < w * h; i++) {
    const j = 3 * i;
    const dc = huntHyab(refLab[j], refLab[j + 1], refLab[j + 2], testLab[j], testLab[j + 1], testLab[j + 2]);
    const ec = redistribute(dc ** QC, cmax);
    const df = Math.max(Math.abs(refF.edges[i] - testF.edges[i]), Math.abs(refF.points[i] - testF.points[i]));
    const ef = (df / Math.SQRT2) ** QF;
    out[i] = ec ** (1 - ef);
  }
  return out;
}
