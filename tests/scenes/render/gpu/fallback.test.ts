/**
 * Which renderer draws the page: the GPU where asked and possible, else the CPU with the reason
 * named; the read-back schedule and the means of read-back sums.
 */
import { describe, expect, it } from 'vitest';
import { chooseRenderer } from '../../../../src/scenes/render/gpu/fallback';
import { isCheckpoint, meansOf } from '../../../../src/scenes/render/gpu/useGpuRender';

const full = { webgl2: true, floatTarget: true, software: null };

describe('chooseRenderer', () => {
  it('uses the GPU when asked and everything is there', () => {
    expect(chooseRenderer('gpu', full, null)).toEqual({ renderer: 'gpu', unavailable: null });
    expect(chooseRenderer('gpu', { ...full, software: 'SwiftShader' }, null).renderer).toBe('gpu');
  });

  it('uses the CPU when asked, whatever the browser has, with no notice', () => {
    expect(chooseRenderer('cpu', full, null)).toEqual({ renderer: 'cpu', unavailable: null });
    expect(
      chooseRenderer('cpu', { webgl2: false, floatTarget: false, software: null }, 'x').unavailable,
    ).toBeNull();
  });

  it('falls back to the CPU naming what is missing', () => {
    const none = chooseRenderer('gpu', { webgl2: false, floatTarget: false, software: null }, null);
    expect(none.renderer).toBe('cpu');
    expect(none.unavailable).toMatch(/WebGL2/);
    const noFloat = chooseRenderer('gpu', { ...full, floatTarget: false }, null);
    expect(noFloat.renderer).toBe('cpu');
    expect(noFloat.unavailable).toMatch(/EXT_color_buffer_float/);
    const lost = chooseRenderer('gpu', full, 'the WebGL context was lost');
    expect(lost).toEqual({ renderer: 'cpu', unavailable: 'the WebGL context was lost' });
  });
});

describe('the GPU render’s read backs', () => {
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
