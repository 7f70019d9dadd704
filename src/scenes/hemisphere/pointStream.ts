/**
 * The 3D view's points, off the main thread: the worker's `points` task fills them chunk by chunk
 * (./jobs pointsJob) and the page only copies each chunk into its buffers, so no main-thread task
 * grows with n (up to 10⁶ points). Should the worker fail, the page's own lobe fills the rest in
 * slices of at most SLICE_MS (src/ui/chunked), the same numbers either way.
 */
import { isCancelled, runWorkerTask } from '../../workers';
import { nextTask, SLICE_MS } from '../../ui/chunked';
import { fillPoints, pointsChunk, pointsScratch, type PointsArgs, type PointsChunk } from './jobs';
import type { Lobe } from './lobe';
import { makeWorker } from './worker';

/**
 * Streams the points of `args` to `onChunk`, in order, from point 0. `lobe` is the page's lobe for
 * the same parameters (the fallback's). Returns a function that stops the stream: no chunk is
 * delivered after it is called.
 */
export function streamPoints(args: PointsArgs, lobe: Lobe, onChunk: (c: PointsChunk) => void): () => void {
  let stopped = false;
  let received = 0;
  const ctl = new AbortController();
  const deliver = (c: PointsChunk) => {
    if (stopped || c.start !== received) return;
    received += c.count;
    onChunk(c);
  };
  runWorkerTask(makeWorker, 'points', args, {
    signal: ctl.signal,
    onProgress: (_f, c) => {
      if (c) deliver(c);
    },
  }).catch((err: unknown) => {
    if (stopped || isCancelled(err)) return;
    slicedFill(
      args,
      lobe,
      () => received,
      deliver,
      () => stopped,
    );
  });
  return () => {
    stopped = true;
    ctl.abort();
  };
}

/** The fallback: the remaining points on the main thread, one task of at most ~SLICE_MS each. */
function slicedFill(
  a: PointsArgs,
  lobe: Lobe,
  from: () => number,
  deliver: (c: PointsChunk) => void,
  stopped: () => boolean,
): void {
  const scratch = pointsScratch();
  // points per chunk, adapted so that one chunk takes about a quarter of a slice
  let size = 512;
  const step = () => {
    const t0 = performance.now();
    while (!stopped() && from() < a.n && performance.now() - t0 < SLICE_MS) {
      const c0 = performance.now();
      const c = pointsChunk(from(), Math.min(size, a.n - from()));
      fillPoints(lobe, a.points, a.seed, a.n, c.start, c.start + c.count, c, scratch);
      deliver(c);
      const ms = performance.now() - c0;
      if (ms < SLICE_MS / 8) size = Math.min(1 << 14, 2 * size);
      else if (ms > SLICE_MS / 2) size = Math.max(256, size >> 1);
    }
    if (!stopped() && from() < a.n) nextTask(step);
  };
  nextTask(step);
}
