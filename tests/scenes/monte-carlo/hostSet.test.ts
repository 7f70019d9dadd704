/** A host's `set` on the Monte Carlo scene: limits it would swap and integrands that do not compile. */
import { hostSetCases } from '../../app/hostSet';

hostSetCases('monte-carlo', {
  refused: [
    [{ a: 1, b: 1 }, 'b'],
    [{ a: 3 }, 'b'],
    [{ f: 'x +* 2' }, 'f'],
    // a set that keeps the limits unusable in a new way, on a page that already shows a fallback
    [{ b: 0.5 }, 'b', 'a=1&b=1'],
  ],
  accepted: [
    [{ a: 0.5, b: 1.5 }],
    // a fallback the page already shows does not block an unrelated set
    [{ n: 64 }, 'a=1&b=1'],
  ],
});
