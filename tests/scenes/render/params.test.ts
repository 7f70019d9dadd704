/**
 * The render lab's fold choices live in the link: the equal-time budget (`et`) and the strategy the
 * Welch map compares with (`vs`), read back from the address and refused, by name, when unusable.
 */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../../src/kit/params';
import { LIGHT_SAMPLING, schema, welchOther } from '../../../src/scenes/render/params';
import { STRATEGIES } from '../../../src/core/render/directLight';

describe('render lab fold parameters', () => {
  it('et and vs are read from the link', () => {
    const r = parseParams(schema, 'et=4000&vs=mis-balance');
    expect(r.problems).toEqual([]);
    expect(r.values.et).toBe('4000');
    expect(r.values.vs).toBe('mis-balance');
  });

  it('a budget or strategy the folds do not offer is named and falls back to the default', () => {
    const r = parseParams(schema, 'et=999&vs=uniform');
    expect(r.values.et).toBe('1000');
    expect(r.values.vs).toBe('auto');
    const named = r.problems.map((p) => p.name).sort();
    expect(named).toEqual(['et', 'vs']);
  });

  it('auto compares with a light-sampling strategy other than the page’s own', () => {
    for (const s of STRATEGIES) {
      const other = welchOther('auto', s);
      expect(LIGHT_SAMPLING).toContain(other);
      expect(other).not.toBe(s);
    }
    expect(welchOther('mis-power', 'area')).toBe('mis-power');
  });
});
