/**
 * The measurement panel's markup outside the browser: before FLIP arrives it shows no number for
 * flip-mean (never a stale one), the scene's relMSE to full precision, one option per image and
 * the three download buttons, the error map's disabled until its map exists.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { ImageMeasurePanel } from '../../src/ui/ImageMeasurePanel';
import type { ImageSet } from '../../src/ui/imageMeasure';

const px = (v: number) => new Uint8ClampedArray(4 * 4).fill(v);
const set: ImageSet = {
  width: 2,
  height: 2,
  reference: px(200),
  referenceLabel: 'exact',
  images: [
    { id: 'a', label: 'strategy A', pixels: px(190), relMse: 0.012345678901 },
    { id: 'b', label: 'strategy B', pixels: px(100), relMse: 0.5 },
  ],
  relMseOf: 'the radiance per pixel',
  fileStem: 'floor',
};

describe('ImageMeasurePanel', () => {
  it('says the images are not ready when there are none', () => {
    expect(renderToStaticMarkup(<ImageMeasurePanel set={null} />)).toMatch(/not rendered yet/);
  });
  it('shows relMSE at once, FLIP as not yet computed, the chooser and the downloads', () => {
    const html = renderToStaticMarkup(<ImageMeasurePanel set={set} />);
    expect(html).toMatch(
      /data-testid="flip-mean"[^>]*data-value="none"|data-value="none"[^>]*data-testid="flip-mean"/,
    );
    expect(html).toContain('data-value="0.012345678901"');
    expect(html.match(/<option /g)).toHaveLength(2);
    expect(html).toContain('strategy B');
    for (const id of ['download-render', 'download-reference', 'download-error-map'])
      expect(html).toContain(`data-testid="${id}"`);
    expect(html).toMatch(
      /<button[^>]*disabled=""[^>]*data-testid="download-error-map"|data-testid="download-error-map"[^>]*disabled=""/,
    );
    expect(html).toContain('floor-reference.png');
  });
});
