import { describe, expect, test } from 'vitest';
import { comparedStrategies } from '../../../src/scenes/monte-carlo/compared';

describe('comparedStrategies', () => {
  const pairs = (s: { pdf: string; seq: string }[]) => s.map((x) => `${x.pdf}/${x.seq}`);

  test('each pdf with independent samples, then the uniform pdf with stratified and Sobol points', () => {
    expect(pairs(comparedStrategies('uniform', 'independent', true))).toEqual([
      'uniform/independent',
      'linear/independent',
      'proportional/independent',
      'uniform/stratified',
      'uniform/sobol',
    ]);
  });

  test('the page’s own strategy is added once, and only when its pdf is usable', () => {
    const withOwn = comparedStrategies('custom', 'halton', true);
    expect(pairs(withOwn).at(-1)).toBe('custom/halton');
    expect(withOwn.at(-1)?.label).toBe('custom p · Halton');
    expect(comparedStrategies('custom', 'halton', false)).toHaveLength(5);
    expect(comparedStrategies('uniform', 'sobol', true)).toHaveLength(5);
  });
});
