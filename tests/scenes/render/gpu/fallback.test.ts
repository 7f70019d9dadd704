/**
 * Which renderer draws the page: the GPU where asked and possible, else the CPU with the reason
 * named; the read-back schedule and the means of read-back sums.
 */
import { describe, expect, it } from 'vitest';
import { chooseRenderer } from '../../../../src/scenes/render/gpu/fallback';
import { meansOf } from '../../../../src/scenes/render/gpu/useGpuRender';
import { isCheckpoint } from '../../../../src/scenes/render/gpu/gpuProtocol';
import { softwareName } from '../../../../src/scenes/render/gpu/gpuRenderer';

const full = { webgl2: true, offscreen: true };

describe('chooseRenderer', () => {
  it('uses the GPU when asked and everything is there', () => {
    expect(chooseRenderer('gpu', full, null)).toEqual({ renderer: 'gpu', unavailable: null });
  });

  it('uses the CPU when asked, whatever the browser has, with no notice', () => {
    expect(chooseRenderer('cpu', full, null)).toEqual({ renderer: 'cpu', unavailable: null });
    expect(chooseRenderer('cpu', { webgl2: false, offscreen: false }, 'x').unavailable).toBeNull();
  });

  it('falls back to the CPU naming what is missing', () => {
    const none = chooseRenderer('gpu', { webgl2: false, offscreen: false }, null);
    expect(none.renderer).toBe('cpu');
    expect(none.unavailable).toMatch(/WebGL2/);
    const noWorker = chooseRenderer('gpu', { ...full, offscreen: false }, null);
    expect(noWorker.renderer).toBe('cpu');
    expect(noWorker.unavailable).toMatch(/OffscreenCanvas/);
    // what the worker finds (a missing float target, a shader that does not compile) comes as a failure
    const noFloat = chooseRenderer('gpu', full, 'WebGL2 here lacks EXT_color_buffer_float');
    expect(noFloat).toEqual({ renderer: 'cpu', unavailable: 'WebGL2 here lacks EXT_color_buffer_float' });
    const lost = chooseRenderer('gpu', full, 'the WebGL context was lost');
    expect(lost).toEqual({ renderer: 'cpu', unavailable: 'the WebGL context was lost' });
  });
});

describe('the GPU render’s read backs and the renderer’s name', () => {
  it('names a software WebGL', () => {
    expect(
      softwareName('ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero)), SwiftShader driver)'),
    ).toBe('SwiftShader');
    expect(softwareName('llvmpipe (LLVM 15.0.7, 256 bits)')).toBe('llvmpipe');
    expect(softwareName('ANGLE (NVIDIA, NVIDIA GeForce RTX 3080)')).toBeNull();
  });

  it('reads at powers of two and at the target only', () => {
    const at = Array.from({ length: 24 }, (_, k) => k + 1).filter((n) => isCheckpoint(n, 24));
    expect(at).toEqual([1, 2, 4, 8, 16, 24]);
    expect(isCheckpoint(0, 24)).toBe(false);
  });

  it('takes the Kahan channel over the count as the mean', () => {
    const rgba = Float32Array.of(9, 8, 0.5, 70, 0, 0, 0, 0);
    expect(Array.from(meansOf(rgba, 4))).toEqual([2, 0]);
    expect(meansOf(rgba, 0).every(Number.isNaN)).toBe(true);
  });
});
