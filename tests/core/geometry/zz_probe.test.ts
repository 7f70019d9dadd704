import { it } from 'vitest';
import { sphereImageSetup, renderSphereF32, renderSphereReference, countHitMismatch } from '../../../src/core/geometry';
it('probe', () => {
  for (const D of [10, 100, 1e3, 3e3, 1e4, 3e4, 1e5]) for (const W of [96, 128]) {
    const s = sphereImageSetup(D, W, W);
    const e = renderSphereF32(s);
    const ref = renderSphereReference(s);
    let hits = 0; for (const t of ref) if (t !== Infinity) hits++;
    console.log(D, W, 'hits', hits, 'wrong naive', countHitMismatch(e.naive, ref), 'stable', countHitMismatch(e.stable, ref));
  }
});
