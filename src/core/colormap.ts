/**
 * The one colormap module of the project (pure: no DOM). Two perceptually ordered ramps, ten stops
 * sampled evenly from matplotlib's "viridis" and "magma" (van der Walt & Smith, 2015; the same
 * values as d3-scale-chromatic's interpolators at t = k/9), and one diverging ramp, ColorBrewer's
 * 11-class "RdBu" (Brewer, colorbrewer2.org) ordered blue to red; all linearly interpolated in sRGB.
 * Viridis colours values (texels, densities); magma colours error maps, as NVIDIA's FLIP tool
 * does; the diverging ramp colours signed differences (blue below the middle, red above,
 * near-white at it), readable for the common colour-vision deficiencies.
 */

/** A ramp: its name and its evenly spaced sRGB stops (0–255). */
export interface Colormap {
  readonly name: 'viridis' | 'magma' | 'diverging';
  readonly stops: readonly (readonly [number, number, number])[];
}

const VIRIDIS_STOPS: readonly (readonly [number, number, number])[] = [
  [68, 1, 84],
  [72, 40, 120],
  [62, 74, 137],
  [49, 104, 142],
  [38, 130, 142],
  [31, 158, 137],
  [53, 183, 121],
  [109, 205, 89],
  [180, 222, 44],
  [253, 231, 37],
];

const MAGMA_STOPS: readonly (readonly [number, number, number])[] = [
  [0, 0, 4],
  [24, 15, 61],
  [68, 15, 118],
  [114, 31, 129],
  [158, 47, 127],
  [205, 64, 113],
  [241, 96, 93],
  [253, 150, 104],
  [254, 202, 141],
  [252, 253, 191],
];

const DIVERGING_STOPS: readonly (readonly [number, number, number])[] = [
  [5, 48, 97],
  [33, 102, 172],
  [67, 147, 195],
  [146, 197, 222],
  [209, 229, 240],
  [247, 247, 247],
  [253, 219, 199],
  [244, 165, 130],
  [214, 96, 77],
  [178, 24, 43],
  [103, 0, 31],
];

export const VIRIDIS: Colormap = { name: 'viridis', stops: VIRIDIS_STOPS };
export const MAGMA: Colormap = { name: 'magma', stops: MAGMA_STOPS };
export const DIVERGING: Colormap = { name: 'diverging', stops: DIVERGING_STOPS };

/** RGB (0–255) of t ∈ [0, 1] (clamped; NaN → 0) on `map`. Writes into out (length ≥ offset + 3). */
export function colorInto(
  t: number,
  out: Uint8ClampedArray | Uint8Array | number[],
  offset = 0,
  map: Colormap = VIRIDIS,
): void {
  const STOPS = map.stops;
  const x = Number.isFinite(t) ? Math.min(Math.max(t, 0), 1) : 0;
  const s = x * (STOPS.length - 1);
  const k = Math.min(Math.floor(s), STOPS.length - 2);
  const f = s - k;
  const a = STOPS[k];
  const b = STOPS[k + 1];
  out[offset] = Math.round(a[0] + (b[0] - a[0]) * f);
  out[offset + 1] = Math.round(a[1] + (b[1] - a[1]) * f);
  out[offset + 2] = Math.round(a[2] + (b[2] - a[2]) * f);
}

/** The stops flat (r, g, b, r, g, b, …) for the batched loop below. */
const FLAT = {
  viridis: new Float64Array(VIRIDIS_STOPS.flat()),
  magma: new Float64Array(MAGMA_STOPS.flat()),
  diverging: new Float64Array(DIVERGING_STOPS.flat()),
};

/**
 * Opaque RGBA of the first n values, each mapped to [0, 1] on [min, max] ({@link normalizeValue})
 * and coloured as {@link colorInto} does, written to img from byte 0. One plain loop over typed
 * arrays with the same arithmetic (so the same bytes), for whole images.
 */
export function colorizeInto(
  values: Float64Array,
  n: number,
  min: number,
  max: number,
  img: Uint8ClampedArray,
  map: Colormap = VIRIDIS,
): void {
  const STOPS = map.stops;
  const LAST = STOPS.length - 2;
  const flat = FLAT[map.name];
  const ramp = max > min;
  const span = max - min;
  for (let k = 0; k < n; k++) {
    const t = ramp ? (values[k] - min) / span : 0.5;
    const x = Number.isFinite(t) ? Math.min(Math.max(t, 0), 1) : 0;
    const s = x * (STOPS.length - 1);
    const i = Math.min(Math.floor(s), LAST);
    const f = s - i;
    const a = 3 * i;
    const o = 4 * k;
    img[o] = Math.round(flat[a] + (flat[a + 3] - flat[a]) * f);
    img[o + 1] = Math.round(flat[a + 1] + (flat[a + 4] - flat[a + 1]) * f);
    img[o + 2] = Math.round(flat[a + 2] + (flat[a + 5] - flat[a + 2]) * f);
    img[o + 3] = 255;
  }
}

/** CSS colour of t ∈ [0, 1] on `map`. */
export function colorCss(t: number, map: Colormap = VIRIDIS): string {
  const c = [0, 0, 0];
  colorInto(t, c, 0, map);
  return `rgb(${c[0]},${c[1]},${c[2]})`;
}

/** True when dark text reads better than light text on the colour of t (relative luminance > 0.25). */
export function darkTextOn(t: number, map: Colormap = VIRIDIS): boolean {
  const c = [0, 0, 0];
  colorInto(t, c, 0, map);
  const lin = c.map((v) => {
    const s = v / 255;
    return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  });
  return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2] > 0.25;
}

/** Map value x to [0, 1] on the range [min, max] (a flat grid maps to ½). */
export function normalizeValue(x: number, min: number, max: number): number {
  return max > min ? (x - min) / (max - min) : 0.5;
}
