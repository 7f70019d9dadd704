/** A host's `set` on the texture scene: texel grids that are not rectangular. */
import { hostSetCases } from '../../app/hostSet';

hostSetCases('texture', {
  refused: [
    [{ grid: '1,2,3;4' }, 'grid'],
    [{ grid: '' }, 'grid'],
  ],
  accepted: [[{ grid: '1,2;3,4' }]],
});
