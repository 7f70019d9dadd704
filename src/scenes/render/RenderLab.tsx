/**
 * The render lab (#/render): a progressive path tracer of the exam's own objects, drawn by a WebGL2
 * fragment shader in float32 where the browser allows (./gpu) or by the core's float64 renderer in
 * workers (`renderer=cpu`, the ground truth), where any pixel opens onto the numbers behind it (the
 * ray, the quadratic, the texture lookup, the estimator and its reference; always the CPU's). The
 * image and the inspector come first; the settings, the comparison of the two renderers and the
 * explanations are folded below them.
 */
import { lazy, memo, useCallback, useEffect, useMemo, useRef, useState, type MouseEvent } from 'react';
import type { SceneProps } from '../../kit/scene';
import { Notice, Readout } from '../../ui';
import { observeVisibility } from '../../ui/useInView';
import { useWorkerJob } from '../../workers';
import { buildScene } from '../../core/render/scene';
import { formatCount, formatNumber } from '../../core/format';
import { makeRenderWorker } from './jobs';
import { inspectArgs, referenceArgs } from './jobArgs';
import { buildRenderModel, type RenderModel } from './model';
import { describeImage, regionsOf } from './describe';
import { useProgressiveRender } from './useProgressiveRender';
import { useGpuRender } from './gpu/useGpuRender';
import { useOpeningDone } from '../../ui/useOpeningDone';
import { gpuSupport, softwareName, type GpuSupport } from './gpu/gpuRenderer';
import { chooseRenderer } from './gpu/fallback';
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
import { copyMeans } from './pixels';
import './render.css';

const Compare = lazy(() => import('./view/Compare'));

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
  const cpuCanvas = useRef<HTMLCanvasElement>(null);
  const gpuCanvas = useRef<HTMLCanvasElement>(null);
  const boxRef = useRef<HTMLDivElement>(null);
  const [visible, setVisible] = useState(false);
  useEffect(() => {
    const c = boxRef.current;
    return c ? observeVisibility(c, setVisible) : undefined;
  }, []);
  const support = useMemo(() => gpuSupport(), []);
  const [failure, setFailure] = useState<string | null>(null);
  const choice = chooseRenderer(m.renderer, support, failure);
  const onGpu = choice.renderer === 'gpu';

  // The renderers' workers (SwiftShader's compile and passes on a phone without a GPU, the CPU's
  // tiles) and the reference image start once the page's opening is over: started beside it, they
  // took both cores of a phone from the page while its first screen was being laid out.
  const opened = useOpeningDone();
  const refJob = useWorkerJob(makeRenderWorker, 'reference', referenceArgs(m), {
    delayMs: 150,
    enabled: opened,
  });
  const reference = refJob.result?.values ?? null;
  const cpuDrawn = useRef(0);
  const cpuProgress = useProgressiveRender(
    cpuCanvas,
    m,
    !onGpu && visible && opened,
    m.target,
    reference,
    cpuDrawn,
  );
  // a pause that reached the GPU's worker a few frames late: the link says where the image holds
  const paused = useRef({ play: params.play, target: m.target });
  paused.current = { play: params.play, target: m.target };
  const onHeld = useCallback(
    (count: number) => {
      if (!paused.current.play && count > paused.current.target) setParams({ t: count });
    },
    [setParams],
  );
  const gpuProgress = useGpuRender(
    gpuCanvas,
    m,
    onGpu && opened,
    visible,
    m.target,
    reference,
    setFailure,
    onHeld,
  );
  const progress = onGpu ? gpuProgress : cpuProgress;
  const software = gpuProgress.rendererName ? softwareName(gpuProgress.rendererName) : null;
  // pausing writes where the run is into the link (t, in samples per pixel), as every timeline does:
  // the samples the canvas shows, which the CPU's readouts may trail by a few passes (the count is
  // read when the pause happens, so the callback, and the folds given it, stay the same from one
  // pass of the render to the next)
  const sppNow = useRef((): number => 0);
  sppNow.current = () => (onGpu ? gpuProgress.spp : cpuDrawn.current);
  const pause = useCallback(
    (p: Partial<RenderParams>) => setParams(p.play === false ? { ...p, t: sppNow.current() } : p),
    [setParams],
  );
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
  const regions = useMemo(() => regionsOf(scene, m.view, m.res), [scene, m.view, m.res]);
  const description = describeImage(scene, regions, m.res, { spp: progress.statsSpp, mean: progress.mean });
  // once the run is done: the pixels shown, measured against the reference (FLIP, PNG downloads)
  const measured = useMemo(() => {
    const means = progress.means;
    if (!progress.done || !reference || !means || means.length !== m.res * m.res) return null;
    const shown = new Uint8ClampedArray(4 * means.length);
    copyMeans(means, shown);
    return renderImageSet(shown, reference, m.res, progress.spp, progress.relMse, m.trace.strategy);
  }, [progress.done, progress.means, progress.spp, progress.relMse, reference, m.res, m.trace.strategy]);
  const mark = m.px
    ? { left: `${((m.px[0] + 0.5) / m.res) * 100}%`, top: `${((m.px[1] + 0.5) / m.res) * 100}%` }
    : null;

  return (
    <div className="render-lab">
      {choice.unavailable ? (
        <Notice kind="warn" testId="render-gpu-unavailable">
          The GPU renderer is not available: {choice.unavailable}. The image is rendered on the CPU (float64,
          in workers) instead.
        </Notice>
      ) : null}
      {m.problems.map((p) => (
        <Notice key={p.name} kind="warn" testId={`render-problem-${p.name}`}>
          <code>{p.name}</code> {p.message}
        </Notice>
      ))}
      <div className="render-top">
        <figure className="render-figure">
          <div className="render-canvas-box" ref={boxRef}>
            <canvas
              key={onGpu ? `gpu-${m.res}` : 'cpu'}
              ref={onGpu ? gpuCanvas : cpuCanvas}
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
            <Readout
              id="renderer"
              label="renderer"
              value={choice.renderer}
              note={
                onGpu ? `float32, WebGL2${software ? ` (software: ${software})` : ''}` : 'float64, in workers'
              }
            />
            <Readout
              id="f32-naive-error"
              label="float32 sum: mean |naive − Kahan| / Kahan"
              value={onGpu && Number.isFinite(progress.f32NaiveError) ? progress.f32NaiveError : null}
              digits={2}
              note={
                onGpu
                  ? `at ${progress.statsSpp} samples per pixel (the image is the compensated sum)`
                  : 'the CPU sums in float64'
              }
            />
            <Readout
              id="rel-mse"
              label="relMSE vs exact"
              value={progress.relMsePixels > 0 ? progress.relMse : null}
              digits={4}
              note={
                reference
                  ? `over ${formatCount(progress.relMsePixels)} of ${formatCount(m.res * m.res)} pixels with a closed form${progress.statsSpp !== progress.spp ? `, at ${progress.statsSpp} samples per pixel` : ''}`
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
              : !params.play && progress.spp >= m.target
                ? `Paused at ${progress.spp} of ${m.spp} samples per pixel (play=0, t=${m.target}).`
                : !visible
                  ? 'Waiting until the image is on screen.'
                  : !opened
                    ? 'Starting once the page has loaded.'
                    : `Rendering… ${progress.spp} of ${m.target} samples per pixel${Number.isFinite(progress.mean) ? `; mean ${formatNumber(progress.mean, 4)} at ${progress.statsSpp}` : ''}.`}
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
      <LabFolds m={m} params={params} pause={pause} set={set} support={support} />
      <About />
    </div>
  );
}

/**
 * The folds below the image. Memoised: a pass of the render re-renders the image's figure and
 * readouts, not these (their props change only with the settings).
 */
const LabFolds = memo(function LabFolds({
  m,
  params,
  pause,
  set,
  support,
}: {
  m: RenderModel;
  params: RenderParams;
  pause: (p: Partial<RenderParams>) => void;
  set: (p: Partial<RenderParams>) => void;
  support: GpuSupport;
}) {
  return (
    <>
      <Fold name="settings" summary="Settings" testId="render-settings" className="render-fold">
        <Controls params={params} set={pause} />
      </Fold>
      <Fold
        name="compare"
        summary="The two renderers side by side: the GPU's float32 image against the CPU's float64 one, within their noise"
        className="render-fold"
      >
        <Compare m={m} support={support} />
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
    </>
  );
});
