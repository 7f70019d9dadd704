/**
 * The measurement of one image against its reference, as rendering papers report it: LDR-FLIP
 * (mean and weighted median, NVIDIA's viewing conditions: 0.7 m from a 0.7 m wide 4K display) and
 * relMSE, the FLIP error map in magma beside the two images, and the three as 8-bit sRGB PNG
 * downloads. FLIP is computed on exactly the bytes shown and downloaded (in a worker), so NVIDIA's
 * tool run on the two downloaded PNGs prints the mean shown here.
 */
import { useEffect, useId, useMemo, useRef, useState } from 'react';
import { crc32, encodePng } from '../core/image/png';
import { useWorkerJob } from '../workers/useWorkerJob';
import { makeFlipWorker } from '../workers/flipWorker';
import { Readout } from './Readout';
import { ImageCompare } from './ImageCompare';
import { downloadFile } from './download';
import { formatNumber } from './format';
import { keepTextParenthesesTogether } from './texBreaks';
import { paintRgba, type ImageSet } from './imageMeasure';
import './imageMeasure.css';

const bytes = (p: Uint8ClampedArray) => new Uint8Array(p.buffer, p.byteOffset, p.byteLength);

function savePng(name: string, pixels: Uint8ClampedArray, width: number, height: number): void {
  downloadFile(name, new Uint8Array(encodePng({ width, height, data: pixels })), 'image/png');
}

export function ImageMeasurePanel({ set }: { set: ImageSet | null }) {
  const [chosen, setChosen] = useState<string | null>(null);
  const selectId = useId();
  const image = set?.images.find((im) => im.id === chosen) ?? set?.images[0];
  const args = useMemo(
    () =>
      set && image
        ? { width: set.width, height: set.height, reference: set.reference, test: image.pixels }
        : null,
    [set, image],
  );
  // the identity of the job is the pixels themselves (not the typed arrays' JSON)
  const key = args
    ? `${args.width}x${args.height}:${crc32(bytes(args.reference))}:${crc32(bytes(args.test))}`
    : 'none';
  const flip = useWorkerJob(makeFlipWorker, 'flip', args, { key });
  const cRef = useRef<HTMLCanvasElement>(null);
  const cTest = useRef<HTMLCanvasElement>(null);
  const cMap = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    if (!set || !image) return;
    paintRgba(cRef.current, set.reference, set.width, set.height);
    paintRgba(cTest.current, image.pixels, set.width, set.height);
  }, [set, image]);
  const map = flip.result?.errorMap;
  useEffect(() => {
    if (set) paintRgba(cMap.current, map, set.width, set.height);
  }, [set, map]);

  if (!set || !image)
    return <p className="measure-note">The images are not rendered yet; they are measured once they are.</p>;
  const { width: w, height: h } = set;
  const stem = `${set.fileStem}-${image.id}`;
  const canvas = (ref: React.RefObject<HTMLCanvasElement | null>, testId: string, label: string) => (
    <canvas
      ref={ref}
      width={w}
      height={h}
      className="measure-canvas"
      role="img"
      aria-label={label}
      data-testid={testId}
    />
  );
  return (
    <div className="measure" data-testid="measure-panel">
      {set.images.length > 1 ? (
        // a plain field, not ./controls Select: importing that here splits the page's entry chunk
        <div className="field">
          <label htmlFor={selectId} className="field-label">
            Image measured
          </label>
          <select
            id={selectId}
            data-testid="measure-image"
            value={image.id}
            onChange={(e) => setChosen(e.target.value)}
          >
            {set.images.map((im) => (
              <option key={im.id} value={im.id}>
                {im.label}
              </option>
            ))}
          </select>
        </div>
      ) : null}
      <div className="measure-images">
        <figure>
          {canvas(cRef, 'measure-reference', `Reference: ${set.referenceLabel}`)}
          <figcaption>reference: {set.referenceLabel}</figcaption>
        </figure>
        <figure>
          {canvas(cTest, 'measure-render', `Render: ${image.label}`)}
          <figcaption>render: {image.label}</figcaption>
        </figure>
        <figure>
          {canvas(
            cMap,
            'measure-error-map',
            flip.result
              ? `FLIP error map, magma: mean ${formatNumber(flip.result.mean, 4)}, largest ${formatNumber(flip.result.max, 4)}`
              : 'FLIP error map (computing)',
          )}
          <figcaption>FLIP error (magma: 0 black … 1 pale yellow)</figcaption>
        </figure>
      </div>
      <ImageCompare
        width={w}
        height={h}
        reference={set.reference}
        render={image.pixels}
        errors={flip.result?.errors ?? null}
      />
      <div className="readouts" aria-live="polite">
        <Readout
          id="flip-mean"
          label="FLIP, mean"
          value={flip.result?.mean ?? null}
          note={flip.error ? `FLIP failed: ${flip.error.message}` : flip.result ? null : 'computing…'}
        />
        <Readout id="flip-median" label="FLIP, weighted median" value={flip.result?.weightedMedian ?? null} />
        <Readout id="rel-mse" label={`relMSE (ε = 0.01) of ${set.relMseOf}`} value={image.relMse} />
      </div>
      <div className="measure-downloads" role="group" aria-label="Download as 8-bit sRGB PNG">
        <button
          type="button"
          data-testid="download-render"
          onClick={() => savePng(`${stem}-render.png`, image.pixels, w, h)}
        >
          Download render (PNG)
        </button>
        <button
          type="button"
          data-testid="download-reference"
          onClick={() => savePng(`${set.fileStem}-reference.png`, set.reference, w, h)}
        >
          Download reference (PNG)
        </button>
        <button
          type="button"
          data-testid="download-error-map"
          disabled={!map}
          onClick={() => map && savePng(`${stem}-flip.png`, map, w, h)}
        >
          Download FLIP error map (PNG)
        </button>
      </div>
      <p className="measure-note">
        FLIP (Andersson et al., HPG 2020) is the perceptual difference a viewer 0.7 m from a 0.7 m wide,
        3840-pixel display (about 67 pixels per degree) sees when the two images alternate: 0 none, 1 the
        largest. It is computed on exactly the 8-bit sRGB pixels shown and downloaded, so{' '}
        <code>
          flip -r {set.fileStem}-reference.png -t {stem}-render.png
        </code>{' '}
        (NVIDIA’s tool) or <code>node scripts/flip.mjs</code> on the two files prints the same mean. relMSE is
        the mean of {keepTextParenthesesTogether('(x − ref)²/(ref² + 0.01)')} over {set.relMseOf}.
      </p>
    </div>
  );
}
