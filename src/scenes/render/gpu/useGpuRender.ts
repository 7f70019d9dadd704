/**
 * The progressive GPU render of the page: one path per pixel per animation frame into the float
 * sums (./gpuRenderer), the mean drawn to the canvas after each, only while `running` (the canvas
 * on screen) and until `target` samples per pixel; no frame is requested while nothing changes.
 * The sums are read back (without waiting on the GPU) only at 1, 2, 4, 8 … samples per pixel and
 * at the target, for the mean, the relMSE against the reference and, at the end, the image's means
 * for the measuring panel. A context that cannot be made, a shader that does not compile or a
 * context lost is reported to `onFailure`, and the page draws with the CPU instead.
 */
import { useEffect, useRef, useState, type RefObject } from 'react';
import { buildScene } from '../../../core/render/scene';
import { relMse } from '../../../core/render/relMse';
import { EMPTY_PROGRESS, renderKey, type RenderProgress } from '../useProgressiveRender';
import type { RenderModel } from '../model';
import { createGpuRenderer, renderContext, type GpuRenderer } from './gpuRenderer';
import { sceneUniforms } from './sceneUniforms';

/** Whether the sums are read back after the frame that brings them to n samples per pixel. */
export function isCheckpoint(n: number, target: number): boolean {
  return n >= target || (n > 0 && (n & (n - 1)) === 0);
}

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

export function useGpuRender(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  m: RenderModel,
  active: boolean,
  running: boolean,
  target: number,
  reference: Float64Array | null,
  onFailure: (why: string) => void,
): RenderProgress {
  const key = renderKey(m);
  const res = m.res;
  const [renderer, setRenderer] = useState<GpuRenderer | null>(null);
  const [progress, setProgress] = useState<RenderProgress>(EMPTY_PROGRESS);
  const latest = useRef({ m, reference, onFailure });
  latest.current = { m, reference, onFailure };
  const lastMeans = useRef<{ means: Float64Array; n: number } | null>(null);

  // the context and the programs, for as long as the page draws on the GPU at this size
  useEffect(() => {
    const canvas = canvasRef.current;
    if (!active || !canvas) return;
    let live = true;
    let made: GpuRenderer | null = null;
    const fail = (why: string) => {
      if (live) latest.current.onFailure(why);
    };
    const lost = (e: Event) => {
      e.preventDefault();
      fail('the WebGL context was lost');
    };
    canvas.addEventListener('webglcontextlost', lost);
    const gl = renderContext(canvas);
    if (!gl) fail('the canvas gave no WebGL2 context with float render targets');
    else
      void createGpuRenderer(gl, res).then((r) => {
        if (typeof r === 'string') return fail(r);
        if (!live) return r.dispose();
        made = r;
        setRenderer(r);
      });
    return () => {
      live = false;
      canvas.removeEventListener('webglcontextlost', lost);
      made?.dispose();
      setRenderer(null);
    };
  }, [active, res, canvasRef]);

  // a new image: load the scene and clear the sums
  useEffect(() => {
    lastMeans.current = null;
    setProgress(EMPTY_PROGRESS);
    if (!renderer) return;
    const { m: model } = latest.current;
    renderer.load(sceneUniforms(buildScene(model.spec), model.view, model.res, model.trace), model.seed);
    renderer.display();
  }, [key, renderer]);

  // the frames: one sample per pixel each, while running and short of the target
  useEffect(() => {
    if (!renderer) return;
    const pixels = res * res;
    const start = performance.now();
    const from = renderer.count;
    let frame = 0;
    let live = true;
    let reading = false;
    const read = (n: number) => {
      if (reading) return;
      reading = true;
      void renderer.readBack().then((rgba) => {
        reading = false;
        if (!live || !rgba) return;
        const means = meansOf(rgba, n);
        lastMeans.current = { means, n };
        let total = 0;
        for (const x of means) total += x;
        const err = errorOf(means, latest.current.reference);
        const done = n >= latest.current.m.spp;
        setProgress((p) => ({
          ...p,
          statsSpp: n,
          mean: total / means.length,
          relMse: err.e,
          relMsePixels: err.n,
          done,
          means: done ? means : null,
        }));
        // the frames went on while the sums travelled: the last checkpoint still needs its read
        if (renderer.count >= target && n < renderer.count) read(renderer.count);
      });
    };
    if (!running || renderer.count >= target) {
      // held (paused, off screen or done): the figures are those of the sums as they are
      if (renderer.count > 0 && lastMeans.current?.n !== renderer.count) read(renderer.count);
      return () => {
        live = false;
      };
    }
    const tick = () => {
      frame = 0;
      if (!live || renderer.gl.isContextLost()) return;
      renderer.step();
      renderer.display();
      const n = renderer.count;
      setProgress((p) => ({
        ...p,
        spp: n,
        samplesPerSecond: (pixels * (n - from)) / ((performance.now() - start) / 1000),
      }));
      if (isCheckpoint(n, target)) read(n);
      if (n < target) frame = requestAnimationFrame(tick);
    };
    frame = requestAnimationFrame(tick);
    return () => {
      live = false;
      if (frame) cancelAnimationFrame(frame);
    };
  }, [renderer, running, target, key, res]);

  // a reference that arrives after the last read back still gives its error
  useEffect(() => {
    const last = lastMeans.current;
    if (!last || !reference) return;
    const err = errorOf(last.means, reference);
    setProgress((p) => ({ ...p, relMse: err.e, relMsePixels: err.n }));
  }, [reference]);

  return progress;
}
