import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { paramChanges } from '../../src/app/paramChanges';

interface V {
  seed: number;
  n: number;
}

describe('paramChanges', () => {
  it('a patch builds on the address that came before it, before any render shows that address', () => {
    const c = paramChanges<V>({ seed: 1, n: 20 });
    c.fromAddress({ seed: 9, n: 200_000 });
    const { values } = c.patch({ seed: 10 });
    expect(values).toEqual({ seed: 10, n: 200_000 });
    expect(c.current()).toEqual({ seed: 10, n: 200_000 });
  });

  it('a URL write pending for a patch is dropped once the address changed after it', () => {
    const c = paramChanges<V>({ seed: 1, n: 20 });
    const first = c.patch({ seed: 4 });
    expect(first.latest()).toBe(true);
    c.fromAddress({ seed: 5, n: 20 });
    expect(first.latest()).toBe(false);
    const second = c.patch({ n: 30 });
    expect(second.latest()).toBe(true);
    expect(c.patch({ n: 40 }).latest()).toBe(true);
    expect(second.latest()).toBe(false);
  });

  it('whatever the interleaving, the last change wins and only its own URL write is still allowed', () => {
    const change = fc.oneof(
      fc.record({
        kind: fc.constant('address' as const),
        seed: fc.nat(1000),
        n: fc.integer({ min: 1, max: 1e6 }),
      }),
      fc.record({ kind: fc.constant('patch' as const), seed: fc.nat(1000) }),
    );
    fc.assert(
      fc.property(fc.array(change, { minLength: 1, maxLength: 30 }), (list) => {
        const c = paramChanges<V>({ seed: 0, n: 1 });
        // the model: replay the changes in order on plain values
        let expected: V = { seed: 0, n: 1 };
        const writes: (() => boolean)[] = [];
        for (const ch of list) {
          if (ch.kind === 'address') {
            expected = { seed: ch.seed, n: ch.n };
            c.fromAddress({ seed: ch.seed, n: ch.n });
            writes.push(() => false);
          } else {
            expected = { ...expected, seed: ch.seed };
            writes.push(c.patch({ seed: ch.seed }).latest);
          }
        }
        expect(c.current()).toEqual(expected);
        const allowed = writes.map((w) => w());
        const lastIsPatch = list[list.length - 1].kind === 'patch';
        expect(allowed.filter(Boolean).length).toBe(lastIsPatch ? 1 : 0);
        if (lastIsPatch) expect(allowed[allowed.length - 1]).toBe(true);
      }),
      { seed: 36, numRuns: 300 },
    );
  });
});
