/** Progress in localStorage: recorded per question and seed, robust to junk and to missing storage. */
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { loadProgress, PROGRESS_KEY, recordCheck, resetProgress } from '../../src/practice/progress';
import { MemoryStorage } from './memoryWindow';

const g = globalThis as unknown as { window?: { localStorage: unknown } };
let store: MemoryStorage;
beforeEach(() => {
  store = new MemoryStorage();
  g.window = { localStorage: store };
});
afterEach(() => {
  delete g.window;
});

describe('practice progress', () => {
  it('records attempted and fully correct variants once each, and resets', () => {
    recordCheck('q3', 17, false);
    recordCheck('q3', 17, true);
    recordCheck('q3', 17, true);
    recordCheck('q5', 2, false);
    const p = loadProgress();
    expect(p.q3).toEqual({ attempted: [17], correct: [17] });
    expect(p.q5).toEqual({ attempted: [2], correct: [] });
    expect(p.q1).toEqual({ attempted: [], correct: [] });
    resetProgress();
    expect(loadProgress().q3.attempted).toEqual([]);
  });
  it('ignores junk, inherited keys and bad seeds', () => {
    for (const junk of [
      '{',
      'null',
      '42',
      '{"q1": 5}',
      '{"__proto__": {"attempted": [1]}}',
      '{"q2": {"attempted": [-1, 1.5, "7", 8], "correct": "x"}}',
    ]) {
      store.setItem(PROGRESS_KEY, junk);
      const p = loadProgress();
      expect(p.q1.attempted).toEqual([]);
      expect(Object.keys(p)).toEqual(['q1', 'q2', 'q3', 'q4', 'q5', 'q6']);
    }
    expect(loadProgress().q2).toEqual({ attempted: [8], correct: [] });
  });
  it('works without storage (private mode, sandboxed iframes)', () => {
    g.window = {
      get localStorage(): never {
        throw new Error('denied');
      },
    } as unknown as { localStorage: unknown };
    expect(() => recordCheck('q1', 1, true)).not.toThrow();
    expect(loadProgress().q1.attempted).toEqual([]);
    expect(() => resetProgress()).not.toThrow();
  });
  it('normalises corrupted progress: each seed once, a correct variant is also tried', () => {
    store.setItem(
      PROGRESS_KEY,
      JSON.stringify({ q3: { attempted: [7], correct: [7, 7, 7] }, q4: { attempted: [], correct: [2] } }),
    );
    const p = loadProgress();
    expect(p.q3).toEqual({ attempted: [7], correct: [7] });
    expect(p.q4).toEqual({ attempted: [2], correct: [2] });
  });
});
