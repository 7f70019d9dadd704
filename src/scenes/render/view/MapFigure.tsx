/**
 * A per-pixel quantity of a res × res image drawn in viridis (core/colormap), from 0 to `max` (values
 * above it are drawn as `max`): the render lab's standard-deviation map and its t-test map.
 */
import { useEffect, useRef } from 'react';
import { colorizeInto } from '../../../core/colormap';

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
  const canvas = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    const g = canvas.current?.getContext('2d');
    if (!g) return;
    const img = g.createImageData(res, res);
    colorizeInto(values, res * res, 0, max, img.data);
    g.putImageData(img, 0, 0);
  }, [values, res, max]);
  return (
    <figure className="et-image">
      <canvas ref={canvas} width={res} height={res} role="img" aria-label={label} />
      <figcaption>{caption}</figcaption>
    </figure>
  );
}
