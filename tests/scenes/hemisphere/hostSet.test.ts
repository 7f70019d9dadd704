/** A host's `set` on the hemisphere scene: typed densities that are none, expressions that do not compile. */
import { hostSetCases } from '../../app/hostSet';

hostSetCases('hemisphere', {
  refused: [
    [{ lobe: 'custom', pdf: '-1' }, 'pdf'],
    [{ lobe: 'custom', pdf: 'import(1)' }, 'pdf'],
    [{ pdf: 'import(1)' }, 'pdf'],
    [{ f: 'cos(theta' }, 'f'],
    // a page already on custom refuses a bad density set on its own
    [{ pdf: '0*theta' }, 'pdf', 'lobe=custom'],
  ],
  accepted: [[{ lobe: 'custom', pdf: 'cos(theta)' }], [{ f: 'sin(theta)*cos(phi)^2' }]],
});
