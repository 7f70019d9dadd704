/** A host's `set` on the area-light scene: a light with no area. */
import { hostSetCases } from '../../app/hostSet';

hostSetCases('area-light', {
  refused: [
    [{ ls: [0, 0] }, 'ls'],
    [{ ls: [1e-160, 1e-160] }, 'ls'],
  ],
  accepted: [[{ ls: [2, 0.5] }]],
});
