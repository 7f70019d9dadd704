import { describe, expect, it } from 'vitest';
import { DEMO_B, demoCurve, describeDemo } from '../../src/app/accessibilityDemo';

describe('the accessibility page example', () => {
  it('roots where g = 0, and the description names them', () => {
    const r = 1;
    const { roots } = demoCurve(r);
    expect(roots).toHaveLength(2);
    for (const t of roots) expect((t - 2) ** 2 + DEMO_B ** 2 - r * r).toBeCloseTo(0, 12);
    const d = describeDemo(r);
    expect(d).toContain(`t = ${roots[0]!.toFixed(2)}`);
    expect(d).toContain(`t = ${roots[1]!.toFixed(2)}`);
  });
  it('a miss says by how much, a graze says it touches', () => {
    expect(describeDemo(0.3)).toMatch(/misses.*0\.20 beyond the radius/);
    expect(demoCurve(0.3).roots).toEqual([]);
    expect(describeDemo(DEMO_B)).toContain('touches');
  });
});
