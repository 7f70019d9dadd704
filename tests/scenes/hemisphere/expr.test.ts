import { describe, expect, test } from 'vitest';
import { compileThetaPhi, compileThetaPhiFast } from '../../../src/scenes/hemisphere/expr';
import { schema } from '../../../src/scenes/hemisphere/params';

describe('the default integrand without the parser', () => {
  test('the schema default takes the fast path; the parser gives the same values and TeX', async () => {
    const src = schema.f.default;
    const fast = compileThetaPhiFast(src);
    const slow = await compileThetaPhi(src);
    expect(fast && fast.ok).toBe(true);
    expect(slow.ok).toBe(true);
    if (!fast || !fast.ok || !slow.ok) return;
    expect(fast.tex).toBe(slow.tex);
    for (let i = 0; i <= 40; i++) {
      const t = (i / 40) * (Math.PI / 2);
      const p = (i / 40) * 2 * Math.PI;
      expect(fast.fn(t, p)).toBe(slow.fn(t, p));
    }
  });

  test('spacing does not matter; anything else goes to the parser', () => {
    expect(compileThetaPhiFast(' cos( theta ) ')).not.toBeNull();
    for (const s of ['cos(theta)^2', 'cos(phi)', 'sin(theta)', '', 'cos(theta) + 0'])
      expect(compileThetaPhiFast(s)).toBeNull();
  });
});
