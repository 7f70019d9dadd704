/**
 * The floor under the light rendered progressively with each strategy, side by side with the
 * analytic reference, so the noise each strategy leaves is seen. Rendering runs in a worker (with
 * progress and cancel); the canvases are repainted only when a new pass arrives.
 */
import { useEffect, useMemo, useRef } from 'react';
import { useWorkerJob } from '../../../workers';
import { Panel, Readout, useSeenOnce } from '../../../ui';
import { formatNumber } from '../../../ui/Readout';
import { PASS_TOTAL, type FloorJob } from '../floor';
import { STRATEGIES, STRATEGY_LABEL } from '../strategies';
import { makeWorker, type FloorFrame } from '../jobs';
import { fmt } from './format';
import { floorImageSet, floorPixels, floorScale } from '../floorPixels';
import { ImageMeasure } from '../../../ui/ImageMeasure';

/** Paint a radiance image as ../floorPixels shows it (the measurement reads the same bytes). */
function paint(canvas: HTMLCanvasElement | null, img: Float32Array | undefined, size: number, scale: number) {
  if (!canvas || !img) return;
  if (canvas.width !== size) canvas.width = canvas.height = size;
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  ctx.putImageData(new ImageData(floorPixels(img, size, scale), size, size), 0, 0);
}

/** A floor image's accessible name: what it is and, for a strategy, its error against the reference. */
function floorImageLabel(label: string, i: number, fr: FloorFrame | undefined): string {
  if (!fr) return `Floor rendered with ${label} (not rendered yet)`;
  if (i === 0) return `Floor rendered with ${label}: the exact radiance, brightest in the light’s footprint`;
  const rmse = fr.rmse[i - 1];
  return `Floor rendered with ${label} at ${fr.spp} samples per pixel: RMSE ${rmse === undefined ? '—' : formatNumber(rmse, 3)} against the reference`;
}

/**
 * `pass` (from the timeline, model.floorPassAt) picks which progressive pass is shown: the images
 * refine in step with the animation. While the render is still running, the newest pass not beyond
 * the wanted one is shown; once done, exactly the wanted one (a function of the job and t).
 */
export function FloorImages({ job, pass = PASS_TOTAL.length - 1 }: { job: FloorJob; pass?: number }) {
  // Starts when the images come near the screen (not on load), and restarts when the scene changes
  // (debounced so dragging a slider does not queue renders).
  const box = useRef<HTMLDivElement>(null);
  const seenOnce = useSeenOnce(box);
  const task = useWorkerJob(makeWorker, 'render', job, {
    delayMs: 250,
    enabled: seenOnce,
  });
  const refs = useRef<(HTMLCanvasElement | null)[]>([]);
  // Partials seen for the current job, by pass (a partial carries one pass; the result all of them).
  const seen = useRef<{ job: FloorJob | null; byPass: Map<number, FloorFrame> }>({
    job: null,
    byPass: new Map(),
  });
  if (seen.current.job !== job) seen.current = { job, byPass: new Map() };
  if (task.partial) seen.current.byPass.set(PASS_TOTAL.indexOf(task.partial.spp), task.partial);

  let fr: FloorFrame | undefined;
  if (task.result?.passes.length) fr = task.result.passes[Math.min(pass, task.result.passes.length - 1)];
  else {
    for (const [k, f] of seen.current.byPass) if (k <= pass && (!fr || f.spp > fr.spp)) fr = f;
    fr ??= task.partial ?? undefined;
  }
  const full = task.result ?? task.partial;
  useEffect(() => {
    if (!fr) return;
    const scale = floorScale(fr.reference);
    paint(refs.current[0] ?? null, fr.reference, fr.size, scale);
    fr.images.forEach((img, i) => paint(refs.current[i + 1] ?? null, img, fr.size, scale));
  }, [fr]);

  const measured = useMemo(() => (fr && task.result ? floorImageSet(fr) : null), [fr, task.result]);

  const labels = ['reference (Lambert’s formula)', ...STRATEGIES.map((s) => STRATEGY_LABEL[s])];
  return (
    <div className="al-images" ref={box}>
      <div className="al-progress" aria-live="polite">
        {task.error ? (
          <span className="field-error">Rendering failed: {task.error.message}</span>
        ) : task.running ? (
          <>
            <progress max={1} value={task.progress} aria-label="Rendering progress" />{' '}
            {fr ? `${fr.spp} samples per pixel so far…` : 'starting…'}
          </>
        ) : fr && full ? (
          <span data-testid="floor-spp" data-value={fr.spp}>
            {fr.spp === full.spp
              ? `${fr.spp} samples per pixel (done).`
              : `Showing ${fr.spp} of ${full.spp} samples per pixel, in step with the timeline (done).`}
          </span>
        ) : (
          'Waiting…'
        )}
      </div>
      <div className="al-image-row">
        {labels.map((label, i) => (
          <figure key={label} className="al-figure">
            <canvas
              ref={(el) => {
                refs.current[i] = el;
              }}
              width={job.size}
              height={job.size}
              role="img"
              aria-label={floorImageLabel(label, i, fr)}
            />
            <figcaption>
              {label}
              {i > 0 && fr ? (
                <Readout
                  id={`image-rmse-${STRATEGIES[i - 1]}`}
                  label="RMSE vs reference"
                  value={fr.rmse[i - 1] ?? null}
                  digits={3}
                />
              ) : null}
              {i > 0 && fr ? <span className="al-ms">{(fr.ms[i - 1] ?? 0).toFixed(0)} ms</span> : null}
            </figcaption>
          </figure>
        ))}
      </div>
      <ImageMeasure set={measured} />
    </div>
  );
}

/** The floor images in their panel, with what they show. */
export function FloorPanel({ job, pass }: { job: FloorJob; pass: number }) {
  return (
    <Panel title="The floor, rendered with each strategy">
      <FloorImages job={job} pass={pass} />
      <p className="al-note">
        {job.size} × {job.size} pixels of floor, {fmt(2 * job.half, 3)} units across, all at the same samples
        per pixel, which grow with the timeline (at its end: 64). The light’s footprint is brightest; the
        grain is each strategy’s variance.
      </p>
    </Panel>
  );
}
