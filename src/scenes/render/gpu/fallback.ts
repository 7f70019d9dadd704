/**
 * Which renderer draws the page's image: the GPU's float32 one where the link asks for it (the
 * default) and the browser has what it needs, else the CPU's float64 one, with the reason named for
 * the page's notice. What the GPU renderer needs: WebGL2, and EXT_color_buffer_float to render into
 * float targets; a context lost or a shader that does not compile also sends the page to the CPU.
 */
import type { GpuSupport } from './gpuRenderer';

export type RendererId = 'gpu' | 'cpu';

export interface RendererChoice {
  renderer: RendererId;
  /** Why the GPU renderer was asked for and not used (null when it is used or not asked for). */
  unavailable: string | null;
}

export function chooseRenderer(
  requested: RendererId,
  support: GpuSupport,
  failure: string | null,
): RendererChoice {
  if (requested === 'cpu') return { renderer: 'cpu', unavailable: null };
  if (!support.webgl2) return { renderer: 'cpu', unavailable: 'this browser has no WebGL2' };
  if (!support.offscreen)
    return {
      renderer: 'cpu',
      unavailable: 'this browser cannot hand a canvas to a worker (OffscreenCanvas), where the shader runs',
    };
  if (failure) return { renderer: 'cpu', unavailable: failure };
  return { renderer: 'gpu', unavailable: null };
}
