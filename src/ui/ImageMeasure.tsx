/**
 * "Measure against the reference": a disclosure under a scene's images whose content (FLIP in a
 * worker, the error map, relMSE and the PNG downloads: ./ImageMeasurePanel) is a lazy chunk that
 * loads, and measures, only once the reader opens it.
 */
import { lazy } from 'react';
import { Fold } from './Fold';
import type { ImageSet } from './imageMeasure';

const ImageMeasurePanel = lazy(() =>
  import('./ImageMeasurePanel').then((m) => ({ default: m.ImageMeasurePanel })),
);

/** `set` is null while the images are not ready (the panel says so). */
export function ImageMeasure({
  set,
  summary,
  name = 'measure',
}: {
  set: ImageSet | null;
  summary?: string;
  /** The fold's name in the link's `open=` (unique on the page). */
  name?: string;
}) {
  return (
    <Fold
      name={name}
      testId="measure-details"
      summary={summary ?? 'Measure against the reference: FLIP, relMSE, error map, PNG downloads'}
    >
      <ImageMeasurePanel set={set} />
    </Fold>
  );
}
