/**
 * Key presses on a cross-section handle faster than frames (src/scenes/ray-sphere/view/keyChain.ts):
 * each press steps on from where the previous one sent the handle until a draw shows that value;
 * a draw of a value no press sent ends the chain. The browser test (ray-sphere-a11y.spec.ts)
 * checks the same with real key events faster than frames.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { afterDraw, afterPress, stepFrom, type KeyChain } from '../../../src/scenes/ray-sphere/view/keyChain';

const v = (r: number) => JSON.stringify(r);

describe('key presses faster than frames', () => {
  it('three presses before any draw step 1 → 2 → 3; draws of the values on the way keep the chain; the last ends it', () => {
    let chain: KeyChain | null = null;
    let r = 1; // what is drawn
    for (let k = 0; k < 3; k++) {
      const from = stepFrom(chain, 'r');
      const next = (typeof from === 'number' ? from : r) + 1;
      chain = afterPress(chain, 'r', next, v(next), v(r));
    }
    expect(chain?.at).toBe(4);
    // the scene applies one edit per frame: 2, then 3, then 4 are drawn
    for (const drawn of [2, 3]) {
      r = drawn;
      chain = afterDraw(chain, v(r));
      expect(chain).not.toBeNull();
      expect(stepFrom(chain, 'r')).toBe(4);
    }
    chain = afterDraw(chain, v(4));
    expect(chain).toBeNull();
  });

  it('a draw of a value no press sent (a link, a drag) ends the chain: the next press steps from what is drawn', () => {
    let chain: KeyChain | null = afterPress(null, 'r', 2, v(2), v(1));
    chain = afterDraw(chain, v(7));
    expect(chain).toBeNull();
    expect(stepFrom(chain, 'r')).toBeNull();
  });

  it('a press on another handle starts a chain of its own from what that handle shows', () => {
    const chain = afterPress(null, 'r', 2, v(2), v(1));
    expect(stepFrom(chain, 'o')).toBeNull();
    const other = afterPress(chain, 'o', [3, 4], '[3,4]', '[0,0]');
    expect(other.target).toBe('o');
    expect([...other.seen]).toEqual(['[0,0]', '[3,4]']);
  });

  it('however presses and draws interleave, every press lands: the chain ends exactly on the last value sent', () => {
    fc.assert(
      fc.property(fc.array(fc.boolean(), { minLength: 1, maxLength: 40 }), (events) => {
        // true: a key press (sends drawn-or-ahead + 1); false: a frame applies the oldest edit not yet drawn
        let chain: KeyChain | null = null;
        let drawn = 0;
        const queue: number[] = [];
        let presses = 0;
        for (const press of events) {
          if (press) {
            const from = stepFrom(chain, 'r');
            const next = (typeof from === 'number' ? from : drawn) + 1;
            chain = afterPress(chain, 'r', next, v(next), v(drawn));
            queue.push(next);
            presses++;
          } else if (queue.length) {
            drawn = queue.shift()!;
            chain = afterDraw(chain, v(drawn));
          }
        }
        while (queue.length) {
          drawn = queue.shift()!;
          chain = afterDraw(chain, v(drawn));
        }
        expect(drawn).toBe(presses);
        expect(chain).toBeNull();
      }),
      { seed: 20261207 },
    );
  });
});
