/**
 * The progressive GPU render of the page, driven from here and drawn by the GPU renderer's worker
 * (./gpu.worker.ts), which owns the canvas (handed over as an OffscreenCanvas): one path per pixel
 * per animation frame into the float sums, the mean drawn after each, only while `running` (the
 * canvas on screen) and until `target` samples per pixel; no frame while nothing changes. The sums
 * come back at 1, 2, 4 … samples per pixel and at the target, for the mean, the relMSE against the
 * reference and, at the end, the image's means for the measuring panel. A context that cannot be
 * made, a shader that does not compile or a context lost is reported to `onFailure`, and the page
 * draws with the CPU instead. Frames run ahead of the page's messages: when a pause arrives after
 * the worker has gone past it, `onHeld` hears where the image really holds.
 */
import { useEffect, useRef, useState, type RefObject } from 'react';
import { buildScene } from '../../../core/render/scene';
import { relMse } from '../../../core/render/relMse';
import { naiveSumError } from '../../../core/render/f32Sum';
import { EMPTY_PROGRESS, renderKey, type RenderProgress } from '../useProgressiveRender';
import type { RenderModel } from '../model';
import { makeGpuWorker } from '../jobs';
import { sceneUniforms } from './sceneUniforms';
import type { FromGpuWorker, ToGpuWorker } from './gpuProtocol';

/** The pixel means (Kahan sum / n) of read-back sums, RGBA per pixel. */
export function meansOf(rgba: Float32Array, n: number): Float64Array {
  const out = new Float64Array(rgba.length / 4);
  for (let k = 0; k < out.length; k++) out[k] = n > 0 ? rgba[4 * k + 1] / n : NaN;
  return out;
}

function errorOf(means: Float64Array, reference: Float64Array | null): { e: number; n: number } {
  if (!reference || reference.length !== means.length) return { e: NaN, n: 0 };
  let n = 0;
  for (let k = 0; k < reference.length; k++) if (Number.isFinite(reference[k])) n++;
  return { e: n > 0 ? relMse(means, reference) : NaN, n };
}

/**
 * A canvas's worker, kept a moment after its effect ends: a canvas can hand over its drawing only
 * once, so an effect run again on the same canvas (React's development checks do this) takes the
 * same worker back instead of making a second.
 */
interface CanvasWorker {
  worker: Worker;
  /** What the worker said about its context so far (replayed to a new listener). */
  said: FromGpuWorker | null;
  listen: (m: FromGpuWorker) => void;
  timer: ReturnType<typeof setTimeout> | null;
}
const canvasWorkers = new WeakMap<HTMLCanvasElement, CanvasWorker>();

function workerFor(canvas: HTMLCanvasElement, res: number): CanvasWorker {
  const known = canvasWorkers.get(canvas);
  if (known) {
    if (known.timer) clearTimeout(known.timer);
    known.timer = null;
    return known;
  }
  const worker = makeGpuWorker();
  const cw: CanvasWorker = { worker, said: null, listen: () => {}, timer: null };
  worker.onmessage = (e: MessageEvent<FromGpuWorker>) => {
    if (e.data.kind === 'ready' || e.data.kind === 'failed') cw.said = e.data;
    cw.listen(e.data);
  };
  const offscreen = canvas.transferControlToOffscreen();
  worker.postMessage({ kind: 'init', res, canvas: offscreen } satisfies ToGpuWorker, [offscreen]);
  canvasWorkers.set(canvas, cw);
  return cw;
}

export function useGpuRender(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  m: RenderModel,
  active: boolean,
  running: boolean,
  target: number,
  reference: Float64Array | null,
  onFailure: (why: string) => void,
  onHeld: (count: number) => void,
): RenderProgress & { rendererName: string | null } {
  const key = renderKey(m);
  const res = m.res;
  const [worker, setWorker] = useState<{ w: Worker; name: string } | null>(null);
  const [progress, setProgress] = useState<RenderProgress>(EMPTY_PROGRESS);
  const latest = useRef({ m, reference, onFailure, onHeld });
  latest.current = { m, reference, onFailure, onHeld };
  const lastMeans = useRef<{ means: Float64Array; n: number } | null>(null);
  // the number of the image last sent to the worker: what it says of others is stale
  const loaded = useRef(0);

  // the worker and its context, for as long as the page draws on the GPU on this canvas
  useEffect(() => {
    const canvas = canvasRef.current;
    if (!active || !canvas) return;
    const cw = workerFor(canvas, res);
    cw.listen = (msg) => {
      if (msg.kind === 'failed') latest.current.onFailure(msg.why);
      else if (msg.kind === 'ready') setWorker({ w: cw.worker, name: msg.renderer });
      else if (msg.id !== loaded.current) return;
      else if (msg.kind === 'frame')
        setProgress((p) => ({ ...p, spp: msg.count, samplesPerSecond: msg.samplesPerSecond }));
      else if (msg.kind === 'held') {
        setProgress((p) => ({ ...p, spp: msg.count }));
        latest.current.onHeld(msg.count);
      } else {
        const { m: model, reference: ref } = latest.current;
        const means = meansOf(msg.rgba, msg.count);
        lastMeans.current = { means, n: msg.count };
        let total = 0;
        for (const x of means) total += x;
        const err = errorOf(means, ref);
        const done = msg.count >= model.spp;
        setProgress((p) => ({
          ...p,
          statsSpp: msg.count,
          mean: total / means.length,
          relMse: err.e,
          relMsePixels: err.n,
          done,
          means: done ? means : null,
          f32NaiveError: naiveSumError(msg.rgba),
        }));
      }
    };
    if (cw.said) cw.listen(cw.said);
    return () => {
      cw.listen = () => {};
      setWorker(null);
      cw.timer = setTimeout(() => {
        cw.worker.terminate();
        canvasWorkers.delete(canvas);
      }, 0);
    };
  }, [active, res, canvasRef]);

  // a new image: load the scene and clear the sums
  useEffect(() => {
    lastMeans.current = null;
    setProgress(EMPTY_PROGRESS);
    if (!worker) return;
    const { m: model } = latest.current;
    const uniforms = sceneUniforms(buildScene(model.spec), model.view, model.res, model.trace);
    loaded.current++;
    worker.w.postMessage({
      kind: 'load',
      id: loaded.current,
      uniforms,
      seed: model.seed,
    } satisfies ToGpuWorker);
  }, [key, worker]);

  // run to the target while the image is seen; hold otherwise
  useEffect(() => {
    if (!worker) return;
    worker.w.postMessage({ kind: 'run', target: running ? target : 0 } satisfies ToGpuWorker);
  }, [worker, running, target, key]);

  // a reference that arrives after the last read back still gives its error
  useEffect(() => {
    const last = lastMeans.current;
    if (!last || !reference) return;
    const err = errorOf(last.means, reference);
    setProgress((p) => ({ ...p, relMse: err.e, relMsePixels: err.n }));
  }, [reference]);

  return { ...progress, rendererName: worker?.name ?? null };
}
