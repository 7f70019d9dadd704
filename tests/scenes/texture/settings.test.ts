/** What the folded settings of #/texture say they are set to while closed. */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/texture/params';
import { settingsInUse } from '../../../src/scenes/texture/settings';

const at = (query: string, isExam = true) => settingsInUse(parseParams(schema, query).values, isExam);

describe('settingsInUse', () => {
  it('names the exam’s settings as such', () => {
    expect(at('')).toBe('the exam’s');
    // the query and the sphere point are not among the folded settings
    expect(at('u=0.7&v=0.1&x=-1')).toBe('the exam’s');
  });

  it('names each setting that differs from the exam, in the panel’s order', () => {
    expect(at('align=center')).toBe('texel centres');
    expect(at('vflip=1&wrap=mirror')).toBe('v flipped, mirrored repeat');
    expect(at('wrap=repeat&preset=checker&size=16', false)).toBe('repeat, checkerboard 16 × 16');
    expect(at('preset=random&seed=7', false)).toBe('random 8 × 8 (seed 7)');
  });

  it('says when the grid given as text is not the exam’s', () => {
    expect(at('grid=1,2;3,4', false)).toBe('a grid of your own');
  });
});
