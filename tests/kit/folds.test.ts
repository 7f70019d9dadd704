import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { FOLD_NAME, MAX_OPEN_FOLDS, openFoldsValue, parseOpenFolds, toggledFolds } from '../../src/kit/folds';
import { parseShellFlags, shellExtras } from '../../src/kit/shell';
import { sharedFlags } from '../../src/kit/shareLink';

describe('open= (folded sections a link opens)', () => {
  it('reads a comma list of names, once each, in order', () => {
    expect(parseOpenFolds('sweep,gpu-warp, sweep ,,table2')).toEqual({
      names: ['sweep', 'gpu-warp', 'table2'],
      problem: null,
    });
    expect(parseOpenFolds(null)).toEqual({ names: [], problem: null });
    expect(parseOpenFolds('')).toEqual({ names: [], problem: null });
  });

  it('drops what cannot be a name and says which', () => {
    const r = parseOpenFolds('sweep,<script>,Gpu,9lives');
    expect(r.names).toEqual(['sweep']);
    expect(r.problem).toContain('"<script>"');
    expect(r.problem).toContain('"Gpu"');
    expect(r.problem).toContain('"9lives"');
    expect(r.problem).toMatch(/left closed/);
  });

  it('opens at most MAX_OPEN_FOLDS, and says so', () => {
    const many = Array.from({ length: MAX_OPEN_FOLDS + 5 }, (_, i) => `f${i}`).join(',');
    const r = parseOpenFolds(many);
    expect(r.names).toHaveLength(MAX_OPEN_FOLDS);
    expect(r.problem).toMatch(/only the first/);
  });

  it('never throws, and every name it keeps is a valid name', () => {
    fc.assert(
      fc.property(fc.string({ maxLength: 200 }), (s) => {
        const r = parseOpenFolds(s);
        return r.names.every((n) => FOLD_NAME.test(n)) && r.names.length <= MAX_OPEN_FOLDS;
      }),
      { seed: 35 },
    );
  });

  it('a name opened goes last; a name closed leaves; the value round-trips', () => {
    expect(toggledFolds(['a', 'b'], 'a', true)).toEqual(['b', 'a']);
    expect(toggledFolds(['a', 'b'], 'a', false)).toEqual(['b']);
    expect(toggledFolds([], 'c', false)).toEqual([]);
    expect(openFoldsValue([])).toBeUndefined();
    expect(parseOpenFolds(openFoldsValue(['x', 'y-2']) ?? null).names).toEqual(['x', 'y-2']);
  });

  it('is a shell flag: parsed with the others, its problems named, kept in links the page writes', () => {
    const f = parseShellFlags('present=1&open=sweep,BAD');
    expect(f.open).toEqual(['sweep']);
    expect(f.problems.map((p) => p.name)).toEqual(['open']);
    expect(shellExtras({ ...f, open: ['sweep', 'gpu'] }).open).toBe('sweep,gpu');
    expect(shellExtras({ ...f, open: [] }).open).toBeUndefined();
    const shared = sharedFlags({
      present: false,
      asking: false,
      keep: false,
      part: null,
      theme: null,
      open: ['gpu'],
    });
    expect(shared.open).toBe('gpu');
  });
});
