/**
 * The progressive CPU render of the page: the image split into bands of rows, one worker per band
 * (./jobs.ts), each adding one sample per pixel per pass in float64 and posting its band's sums
 * after every pass. The main thread only merges the bands and, once per animation frame, copies
 * the pixels into the canvas (./pixels.ts). A run starts when what the image depends on changes,
 * runs only while `running` (the canvas on screen) and stops at `target` samples per pixel (spp, or
 * where a paused link holds it); a run stopped before its target starts again from its first pass
 * when it may run again (the passes are seeded by their number, so it redraws the same samples),
 * and one whose samples had all arrived when it stopped is shown as it is, not run again.
 * The GPU renderer's hook (./gpu/useGpuRender.ts) reports its progress in the same shape.
 */
import { useEffect, useRef, useState, type RefObject } from 'react';
import { runWorkerTask, isCancelled } from '../../workers';
import { mergeTile, splitRows } from '../../core/render/tileJob';
import { newAccumulation, type Accumulation } from '../../core/render/cpuRenderer';
import { relMse } from '../../core/render/relMse';
import { makeRenderWorker } from './jobs';
import { copyPixels, imageStats, pixelMeans } from './pixels';
import { frameDrawer, readoutGate } from './frameDrawer';
import type { RenderModel } from './model';

export interface RenderProgress {
  /** Samples every pixel has. */
  spp: number;
  /** The samples per pixel `mean` and the relMSE were measured at (the GPU reads its sums back now and then). */
  statsSpp: number;
  /** Paths traced per second of wall time since the run started (NaN before the first pass). */
  samplesPerSecond: number;
  mean: number;
  /** relMSE against the reference where it has values, and how many pixels entered it. */
  relMse: number;
  relMsePixels: number;
  done: boolean;
  error: string | null;
  /** The finished image's pixel means (linear radiance, rows from the top), null before the end. */
  means: Float64Array | null;
  /**
   * What summing in float32 costs at `statsSpp`: the mean over pixels of |naive − Kahan| / Kahan of
   * the GPU's two running sums (core/render/f32Sum); NaN on the CPU, which sums in float64.
   */
  f32NaiveError: number;
}

export const EMPTY_PROGRESS: RenderProgress = {
  spp: 0,
  statsSpp: 0,
  samplesPerSecond: NaN,
  mean: NaN,
  relMse: NaN,
  relMsePixels: 0,
  done: false,
  error: null,
  means: null,
  f32NaiveError: NaN,
};

/** The least time between two updates of the readouts while a run goes on (ms). */
const READOUT_MS = 250;

/** Workers per render: the cores but one (the page's), at least one, at most four. */
export function workerCount(cores: number | undefined): number {
  return Math.max(1, Math.min(4, (cores ?? 2) - 1));
}

/** What the image depends on, as a string (a new one starts a new run). */
export function renderKey(m: RenderModel): string {
  const e = m.spec.exam;
  return JSON.stringify([
    m.spec.scene,
    { ...e, grid: [e.grid.width, e.grid.height, Array.from(e.grid.values)] },
    m.view,
    m.trace,
    m.res,
    m.spp,
    m.seed,
  ]);
}

/** relMSE over the pixels whose reference is finite; NaN without one. */
function errorAgainst(acc: Accumulation, reference: Float64Array | null): { e: number; n: number } {
  if (!reference || reference.length !== acc.sum.length) return { e: NaN, n: 0 };
  let n = 0;
  for (let k = 0; k < reference.length; k++) if (Number.isFinite(reference[k])) n++;
  return { e: n > 0 ? relMse(pixelMeans(acc.sum, acc.count), reference) : NaN, n };
}

/** Draws an accumulation's pixels into the canvas (reusing `image` when given); returns the image. */
function showPixels(
  canvas: HTMLCanvasElement | null,
  acc: Accumulation,
  image: ImageData | null,
): ImageData | null {
  const ctx = canvas?.getContext('2d');
  if (!ctx) return image;
  const out = image ?? ctx.createImageData(acc.width, acc.height);
  copyPixels(acc.sum, acc.count, out.data);
  ctx.putImageData(out, 0, 0);
  return out;
}

/** The readouts of an accumulation of a run to `spp` samples per pixel. */
function progressOf(
  acc: Accumulation,
  spp: number,
  reference: Float64Array | null,
  samplesPerSecond: number,
): RenderProgress {
  const stats = imageStats(acc.sum, acc.count);
  const err = errorAgainst(acc, reference);
  const done = stats.spp >= spp;
  return {
    spp: stats.spp,
    statsSpp: stats.spp,
    samplesPerSecond,
    mean: stats.mean,
    relMse: err.e,
    relMsePixels: err.n,
    done,
    error: null,
    means: done ? pixelMeans(acc.sum, acc.count) : null,
    f32NaiveError: NaN,
  };
}

export function useProgressiveRender(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  m: RenderModel,
  running: boolean,
  target: number,
  reference: Float64Array | null,
  /** Set to the samples per pixel the canvas shows (the readouts may be up to READOUT_MS behind it). */
  drawnSpp?: { current: number },
): RenderProgress {
  const key = renderKey(m);
  const [progress, setProgress] = useState<RenderProgress>(EMPTY_PROGRESS);
  const finished = useRef<string | null>(null);
  const latest = useRef({ m, reference });
  latest.current = { m, reference };
  const accRef = useRef<Accumulation | null>(null);

  // a new image: clear the canvas and the readouts
  useEffect(() => {
    finished.current = null;
    accRef.current = null;
    if (drawnSpp) drawnSpp.current = 0;
    setProgress(EMPTY_PROGRESS);
    const c = canvasRef.current;
    c?.getContext('2d')?.clearRect(0, 0, c.width, c.height);
  }, [key, canvasRef, drawnSpp]);

  useEffect(() => {
    if (!running || target < 1) return;
    const { m: model } = latest.current;
    // finished, or paused where the run already is (or beyond): hold the image, and show it (the
    // run may have stopped before the frame that would have drawn its last passes)
    const held = accRef.current;
    const heldSpp = held ? imageStats(held.sum, held.count).spp : 0;
    if (held && (finished.current === `${key}@${target}` || heldSpp >= target)) {
      showPixels(canvasRef.current, held, null);
      if (drawnSpp) drawnSpp.current = heldSpp;
      setProgress((p) => progressOf(held, model.spp, latest.current.reference, p.samplesPerSecond));
      return;
    }
    const res = model.res;
    const acc = newAccumulation(res, res);
    accRef.current = acc;
    const ctl = new AbortController();
    const tiles = splitRows(res, res, workerCount(globalThis.navigator?.hardwareConcurrency));
    const paths = tiles.map(() => 0);
    const tileSpp = tiles.map(() => 0);
    const start = performance.now();
    let image: ImageData | null = null;
    // the canvas every frame, the readouts (a React render) 4 times a second and once whole
    const readouts = readoutGate(() => {
      const total = paths.reduce((a, b) => a + b, 0);
      const perSecond = total / ((performance.now() - start) / 1000);
      setProgress(progressOf(acc, model.spp, latest.current.reference, perSecond));
    }, READOUT_MS);
    const draw = () => {
      image = showPixels(canvasRef.current, acc, image);
      if (drawnSpp) drawnSpp.current = Math.min(...tileSpp);
      readouts.frame();
    };
    const drawer = frameDrawer(draw);
    const runs = tiles.map((tile, n) =>
      runWorkerTask(
        makeRenderWorker,
        'tile',
        {
          spec: model.spec,
          view: model.view,
          width: res,
          height: res,
          tile,
          seed: model.seed,
          spp: target,
          passSpp: 1,
          ...model.trace,
        },
        {
          signal: ctl.signal,
          onProgress: (_f, partial) => {
            if (!partial) return;
            mergeTile(acc, partial);
            paths[n] = partial.paths;
            tileSpp[n] = partial.spp;
            drawer.schedule();
          },
        },
      ),
    );
    Promise.all(runs).then(
      () => {
        finished.current = `${key}@${target}`;
        readouts.last();
        drawer.complete();
      },
      (err: unknown) => {
        if (isCancelled(err)) return;
        ctl.abort();
        setProgress((p) => ({ ...p, error: err instanceof Error ? err.message : String(err) }));
      },
    );
    return () => {
      ctl.abort();
      drawer.stop();
      // the readouts say what the canvas shows, also when the run stopped between two of them
      readouts.flush();
    };
  }, [key, running, target, canvasRef, drawnSpp]);

  // a reference that arrives after the image has stopped still gives its error
  useEffect(() => {
    const acc = accRef.current;
    if (!acc || !reference) return;
    const err = errorAgainst(acc, reference);
    setProgress((p) => (p.spp > 0 ? { ...p, relMse: err.e, relMsePixels: err.n } : p));
  }, [reference]);

  return progress;
}
