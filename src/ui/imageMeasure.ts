/** What a scene hands the image-measurement disclosure (./ImageMeasure.tsx): plain data, no React; and how its views draw it. */

/** One image that has a reference: its 8-bit sRGB pixels (RGBA, rows from the top) as shown. */
export interface MeasuredImage {
  /** Short identifier, used in the file names (e.g. "area"). */
  id: string;
  /** What the image is, for the chooser and the caption (e.g. "uniform by area"). */
  label: string;
  pixels: Uint8ClampedArray;
  /** relMSE of this image against the reference (core/image/relMse), computed by the scene. */
  relMse: number;
}

/** The reference and the images measured against it, all `width` × `height`. */
export interface ImageSet {
  width: number;
  height: number;
  reference: Uint8ClampedArray;
  /** What the reference is (caption). */
  referenceLabel: string;
  images: MeasuredImage[];
  /** What relMSE is computed over, e.g. "the radiance per pixel". */
  relMseOf: string;
  /** Start of the downloaded files' names, e.g. "area-light-floor". */
  fileStem: string;
}

/** Draws RGBA8 pixels (`w` × `h`, rows from the top) into a canvas of that size; anything else is left undrawn. */
export function paintRgba(
  canvas: HTMLCanvasElement | null,
  pixels: Uint8ClampedArray | undefined,
  w: number,
  h: number,
): void {
  const g = canvas?.getContext('2d');
  if (!g || !pixels || pixels.length !== 4 * w * h) return;
  g.putImageData(new ImageData(new Uint8ClampedArray(pixels), w, h), 0, 0);
}
