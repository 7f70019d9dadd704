/**
 * The wipe and the loupe outside the browser: the wipe's pixels are the reference's left of the
 * split and the render's from it on; the loupe's window is the 9 × 9 pixels around its pixel,
 * black outside the image; the markup names the loupe's pixel, both images' values there, and
 * says FLIP is still computing until it arrives.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { ImageCompare, loupePixels, wipePixels } from '../../src/ui/ImageCompare';

const W = 5,
  H = 4;
/** A grey image whose pixel (i, j) has value base + 10 j + i. */
function ramp(base: number): Uint8ClampedArray {
  const a = new Uint8ClampedArray(4 * W * H);
  for (let j = 0; j < H; j++)
    for (let i = 0; i < W; i++) {
      const o = 4 * (j * W + i);
      a[o] = a[o + 1] = a[o + 2] = base + 10 * j + i;
      a[o + 3] = 255;
    }
  return a;
}
const props = { width: W, height: H, reference: ramp(0), render: ramp(100), errors: null };

describe('ImageCompare', () => {
  it('wipes: reference left of the split, render from it on', () => {
    for (const split of [0, 2, W]) {
      const out = wipePixels(props, split);
      for (let j = 0; j < H; j++)
        for (let i = 0; i < W; i++) expect(out[4 * (j * W + i)]).toBe((i < split ? 0 : 100) + 10 * j + i);
    }
  });

  it('magnifies the 9 × 9 window around the pixel, black outside the image', () => {
    const win = loupePixels(props.reference, W, H, 0, 0);
    // window centre (4, 4) is the pixel (0, 0); (5, 6) is pixel (1, 2)
    expect(win[4 * (4 * 9 + 4)]).toBe(0);
    expect(win[4 * (6 * 9 + 5)]).toBe(21);
    // (0, 0) of the window is pixel (−4, −4): outside, black but opaque
    expect([win[0], win[3]]).toEqual([0, 255]);
  });

  it('names the loupe’s pixel and both values there; FLIP waits for its result', () => {
    const html = renderToStaticMarkup(<ImageCompare {...props} />);
    // the loupe opens at the centre pixel (2, 2): reference 22, render 122
    expect(html).toContain('data-pixel="2,2"');
    expect(html).toMatch(/reference 22, render\s*(<!-- -->)?\s*122/);
    expect(html).toContain('FLIP (computing)');
    const withFlip = renderToStaticMarkup(
      <ImageCompare {...props} errors={Float32Array.from({ length: W * H }, (_, k) => k / 100)} />,
    );
    expect(withFlip).toContain('FLIP 0.12');
  });
});
