/**
 * The messages between the page and the GPU renderer's worker (./gpu.worker.ts). The worker owns
 * the WebGL2 context (on the page's canvas, handed over as an OffscreenCanvas, or on one of its
 * own when nothing is shown), so neither compiling the shader nor waiting for the GPU ever holds
 * up the page.
 */
import type { SceneUniforms } from './sceneUniforms';

export type ToGpuWorker =
  /** Make the context and the programs for res × res images; canvas null: draw nowhere. */
  | { kind: 'init'; res: number; canvas: OffscreenCanvas | null }
  /** A new image, number `id`: these uniforms and seed, the sums cleared. */
  | { kind: 'load'; id: number; uniforms: SceneUniforms; seed: number }
  /** Add one sample per pixel per frame until `target` (stop: target ≤ the count). */
  | { kind: 'run'; target: number };

export type FromGpuWorker =
  /** The programs are linked; `renderer` is the WebGL renderer's name. */
  | { kind: 'ready'; renderer: string }
  | { kind: 'failed'; why: string }
  /** A frame was added to image `id`: samples per pixel now, and paths per second since the run's start. */
  | { kind: 'frame'; id: number; count: number; samplesPerSecond: number }
  /** Asked to run to fewer samples than image `id` has (a pause arrives after frames already made): where it holds. */
  | { kind: 'held'; id: number; count: number }
  /** Image `id`'s sums at `count` samples per pixel (RGBA per pixel: naive, Kahan, compensation, squares). */
  | { kind: 'sums'; id: number; count: number; rgba: Float32Array };

/** Whether the sums are read back after the frame that brings them to n samples per pixel. */
export function isCheckpoint(n: number, target: number): boolean {
  return n >= target || (n > 0 && (n & (n - 1)) === 0);
}
