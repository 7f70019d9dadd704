/**
 * The render lab's small images: a res × res canvas whose pixels `paint` fills (RGBA bytes), with a
 * label for screen readers and a caption. {@link MapFigure} draws a per-pixel quantity in viridis
 * (core/colormap) from 0 to `max` (values above it are drawn as `max`): the standard-deviation map
 * and the t-test maps.
 */
import { useCallback, useEffect, useRef } from 'react';
import { colorizeInto } from '../../../core/colormap';

export function CanvasFigure({
  res,
  paint,
  label,
  caption,
}: {
  res: number;
  /** Fills the image's RGBA bytes (rows from the top); keep it stable (useCallback) between draws. */
  paint: (rgba: Uint8ClampedArray) => void;
  /** What the image shows, read by a screen reader. */
  label: string;
  caption: string;
}) {
  const canvas = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    const g = canvas.current?.getContext('2d');
    if (!g) return;
    const img = g.createImageData(res, res);
    paint(img.data);
    g.putImageData(img, 0, 0);
  }, [res, paint]);
  return (
    <figure className="et-image">
      <canvas ref={canvas} width={res} height={res} role="img" aria-label={label} />
      <figcaption>{caption}</figcaption>
    </figure>
  );
}

export function MapFigure({
  values,
  res,
  max,
  label,
  caption,
}: {
  values: Float64Array;
  res: number;
  max: number;
  /** What the map shows, read by a screen reader. */
  label: string;
  caption: string;
}) {
  const paint = useCallback(
    (rgba: Uint8ClampedArray) => colorizeInto(values, res * res, 0, max, rgba),
    [values, res, max],
  );
  return <CanvasFigure res={res} paint={paint} label={label} caption={caption} />;
}
