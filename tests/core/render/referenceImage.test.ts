/** The exact reference image: closed forms where they exist, NaN elsewhere. */
import { describe, expect, it } from 'vitest';
import { referenceImage } from '../../../src/core/render/referenceImage';
import { defaultView, examScene, furnaceScene } from '../../../src/core/render/scene';

describe('the exact reference image', () => {
  it('is 1 at every pixel of the white furnace, at any bounce count', () => {
    const r = referenceImage(furnaceScene(), defaultView('furnace'), 16, 16, 5);
    expect(r.exact).toBe(256);
    expect([...r.values].every((x) => x === 1)).toBe(true);
  });

  it('has no value on shadowed or multi-bounce pixels of the exam scene', () => {
    const one = referenceImage(examScene(), defaultView('exam'), 24, 24, 1);
    expect(one.exact).toBeGreaterThan(0);
    expect(one.exact).toBeLessThan(24 * 24);
    expect([...one.values].filter(Number.isFinite).length).toBe(one.exact);
    const two = referenceImage(examScene(), defaultView('exam'), 24, 24, 2);
    // with two bounces only the background and the light keep a closed form
    expect(two.exact).toBeLessThan(one.exact);
  });
});
