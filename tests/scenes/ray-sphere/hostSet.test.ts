/** A host's `set` on the ray–sphere scene: a ray direction it could not normalise. */
import { hostSetCases } from '../../app/hostSet';

hostSetCases('ray-sphere', {
  refused: [
    [{ d: [0, 0, 0] }, 'd'],
    [{ d: [1e-200, 0, 0] }, 'd'],
  ],
  accepted: [[{ d: [0, 1, 0], r: 2 }]],
});
