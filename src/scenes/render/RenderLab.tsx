/**
 * The render lab (#/render): a progressive path tracer of the exam's own objects on the core's
 * float64 CPU renderer in workers, where any pixel opens onto the numbers behind it (the ray, the
 * quadratic, the texture lookup, the estimator and its reference). The image and the inspector come
 * first; the settings and the explanations are folded below them.
 */
import { useCallback, useEffect, useMemo, useRef, useState, type MouseEvent } from 'react';
import type { SceneProps } from '../../kit/scene';
import { Notice, Readout } from '../../ui';
import { observeVisibility } from '../../ui/useInView';
import { useWorkerJob } from '../../workers';
import { buildScene } from '../../core/render/scene';
import { formatCount, formatNumber } from '../../core/format';
import { makeRenderWorker } from './jobs';
import { inspectArgs, referenceArgs } from './jobArgs';
import { buildRenderModel } from './model';
import { describeImage } from './describe';
import { useProgressiveRender } from './useProgressiveRender';
import { schema, type RenderParams } from './params';
import { Inspector } from './view/Inspector';
import { Controls } from './view/Controls';
import { About } from './view/About';
import { EqualTime } from './view/EqualTime';
import { Spread } from './view/Spread';
import { Welch } from './view/Welch';
import { Fold } from '../../ui/Fold';
import { ImageMeasure } from '../../ui/ImageMeasure';
import { renderImageSet } from './imageSet';
import './render.css';

/** The pixel under a click on the canvas (drawn at any CSS size). */
export function pixelAt(
  x: number,
  y: number,
  width: number,
  height: number,
  res: number,
): [number, number] | null {
  if (!(width > 0 && height > 0)) return null;
  const i = Math.floor((x / width) * res),
    j = Math.floor((y / height) * res);
  return i >= 0 && i < res && j >= 0 && j < res ? [i, j] : null;
}

export default function RenderLab({ params, setParams }: SceneProps<typeof schema>) {
  const set = useCallback((p: Partial<RenderParams>) => setParams(p), [setParams]);
  const m = useMemo(() => buildRenderModel(params), [params]);
  const scene = useMemo(() => buildScene(m.spec), [m.spec]);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const [visible, setVisible] = useState(false);
  useEffect(() => {
    const c = canvasRef.current;
    return c ? observeVisibility(c, setVisible) : undefined;
  }, []);

  const refJob = useWorkerJob(makeRenderWorker, 'reference', referenceArgs(m), { delayMs: 150 });
  const reference = refJob.result?.values ?? null;
  const progress = useProgressiveRender(canvasRef, m, params.play && visible, reference);
  const iArgs = inspectArgs(m);
  // (without a pixel the job is disabled; its arguments are then a placeholder)
  const inspect = useWorkerJob(
    makeRenderWorker,
    'inspect',
    iArgs ?? { ...referenceArgs(m), px: [0, 0], seed: m.seed, pn: m.pn },
    { enabled: iArgs !== null, delayMs: 100 },
  );
  const inspection = iArgs ? inspect.result : undefined;

  const onClick = (e: MouseEvent<HTMLCanvasElement>) => {
    const box = e.currentTarget.getBoundingClientRect();
    const px = pixelAt(e.clientX - box.left, e.clientY - box.top, box.width, box.height, m.res);
    if (px) set({ px });
  };
  const description = describeImage(scene, m.view, m.res, progress);
  // once the run is done: the pixels shown, measured against the reference (FLIP, PNG downloads)
  const measured = useMemo(() => {
    if (!progress.done || !reference) return null;
    const shown = canvasRef.current?.getContext('2d')?.getImageData(0, 0, m.res, m.res).data;
    return shown && shown.length === 4 * m.res * m.res
      ? renderImageSet(shown, reference, m.res, progress.spp, progress.relMse, m.trace.strategy)
      : null;
  }, [progress.done, progress.spp, progress.relMse, reference, m.res, m.trace.strategy]);
  const mark = m.px
    ? { left: `${((m.px[0] + 0.5) / m.res) * 100}%`, top: `${((m.px[1] + 0.5) / m.res) * 100}%` }
    : null;

  return (
    <div className="render-lab">
      {m.problems.map((p) => (
        <Notice key={p.name} kind="warn" testId={`render-problem-${p.name}`}>
          <code>{p.name}</code> {p.message}
        </Notice>
      ))}
      <div className="render-top">
        <figure className="render-figure">
          <div className="render-canvas-box">
            <canvas
              ref={canvasRef}
              width={m.res}
              height={m.res}
              className="render-canvas"
              data-testid="render-canvas"
              role="img"
              aria-label={description}
              onClick={onClick}
            />
            {mark ? <span className="render-mark" style={mark} aria-hidden="true" /> : null}
          </div>
          <figcaption data-testid="render-description">{description}</figcaption>
          <div className="readouts">
            <Readout id="spp" label={`samples per pixel (of ${m.spp})`} value={progress.spp} />
            <Readout
              id="samples-per-second"
              label="paths per second"
              value={progress.samplesPerSecond}
              digits={3}
            />
            <Readout id="renderer" label="renderer" value={params.renderer} note="float64, in workers" />
            <Readout
              id="rel-mse"
              label="relMSE vs exact"
              value={progress.relMsePixels > 0 ? progress.relMse : null}
              digits={4}
              note={
                reference
                  ? `over ${formatCount(progress.relMsePixels)} of ${formatCount(m.res * m.res)} pixels with a closed form`
                  : 'computing the reference…'
              }
            />
          </div>
          {progress.error ? (
            <Notice kind="error" testId="render-error">
              The render stopped: {progress.error}
            </Notice>
          ) : null}
          <p className="render-status" role="status" data-testid="render-status">
            {progress.done
              ? `Done: ${m.spp} samples per pixel.`
              : !params.play
                ? 'Paused (play=0).'
                : !visible
                  ? 'Waiting until the image is on screen.'
                  : `Rendering… ${progress.spp} of ${m.spp} samples per pixel; mean ${formatNumber(progress.mean, 4)}.`}
          </p>
          <ImageMeasure
            set={measured}
            summary="Measure the finished image against the exact reference: FLIP, relMSE, error map, PNG downloads"
          />
        </figure>
        <section className="render-inspector-panel" aria-labelledby="render-inspector-title">
          <h2 id="render-inspector-title">The pixel inspector</h2>
          <Inspector m={m} result={inspection} pending={inspect.running || (iArgs !== null && !inspection)} />
        </section>
      </div>
      <Fold name="settings" summary="Settings" testId="render-settings" className="render-fold">
        <Controls params={params} set={set} />
      </Fold>
      <Fold
        name="equal-time"
        summary="Equal time and equal error: every strategy for the same time, measured against the reference"
        className="render-fold"
      >
        <EqualTime m={m} et={params.et} onEt={(et) => set({ et })} />
      </Fold>
      <Fold
        name="spread"
        summary="The error without a reference: the image rendered K times, and the noise of one run"
        className="render-fold"
      >
        <Spread m={m} />
      </Fold>
      <Fold
        name="welch"
        summary="Two estimators, pixel by pixel: does every pixel converge to the same value? (Welch's t-test)"
        className="render-fold"
      >
        <Welch m={m} vs={params.vs} onVs={(vs) => set({ vs })} />
      </Fold>
      <About />
    </div>
  );
}
