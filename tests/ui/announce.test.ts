import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import {
  ANNOUNCE_GAP_MS,
  announce,
  onAnnounce,
  recentAnnouncements,
  resetAnnouncer,
} from '../../src/ui/announce';

describe('announce (the one live region)', () => {
  beforeEach(() => {
    vi.useFakeTimers({ now: 1_000_000 });
    resetAnnouncer();
  });
  afterEach(() => vi.useRealTimers());

  it('says the first text at once, then at most one text a second, the latest replacing queued ones', () => {
    const heard: string[] = [];
    const off = onAnnounce((a) => heard.push(a.text));
    announce('one');
    expect(heard).toEqual(['one']);
    announce('two');
    announce('three');
    expect(heard).toEqual(['one']);
    vi.advanceTimersByTime(ANNOUNCE_GAP_MS - 1);
    expect(heard).toEqual(['one']);
    vi.advanceTimersByTime(1);
    expect(heard).toEqual(['one', 'three']);
    vi.advanceTimersByTime(5 * ANNOUNCE_GAP_MS);
    expect(heard).toEqual(['one', 'three']);
    off();
  });

  it('now: true speaks at once and drops what was queued', () => {
    const heard: string[] = [];
    const off = onAnnounce((a) => heard.push(a.text));
    announce('a');
    announce('queued');
    announce('key press', { now: true });
    vi.advanceTimersByTime(3 * ANNOUNCE_GAP_MS);
    expect(heard).toEqual(['a', 'key press']);
    expect(recentAnnouncements().map((a) => a.text)).toEqual(['a', 'key press']);
    off();
  });

  it('ignores empty texts and keeps a bounded history in order', () => {
    announce('   ');
    expect(recentAnnouncements()).toHaveLength(0);
    for (let i = 0; i < 80; i++) announce(`t${i}`, { now: true });
    const h = recentAnnouncements();
    expect(h.length).toBeLessThanOrEqual(50);
    expect(h[h.length - 1]!.text).toBe('t79');
    for (let i = 1; i < h.length; i++) expect(h[i]!.seq).toBe(h[i - 1]!.seq + 1);
  });
});
