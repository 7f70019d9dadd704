/**
 * The texture scene's animation plumbing (the shared store of src/ui/animation.tsx, and the frame
 * cache of src/scenes/texture/anim.tsx): the timeline store that
 * lets only the animated parts re-render per frame, the worked steps' position, and the frame
 * cache that the animated parts share (it must return exactly the model's frame at t).
 */
import { describe, expect, it } from 'vitest';
import { animContext } from '../../../src/scenes/texture/view/anim';
import {
  createAnimationStore as createTimelineStore,
  heldPosition as workedPosition,
} from '../../../src/ui/animation';
import { drawnLookup, lookupOptions, resolveGrid } from '../../../src/scenes/texture/model';
import { frameAt, pathOf } from '../../../src/scenes/texture/path';
import type { Timeline } from '../../../src/ui';

const tl = (t: number, playing: boolean) => ({ t, playing }) as Timeline;

describe('timeline store', () => {
  it('starts at the link position (clamped), notifies only on a change of position or playing', () => {
    expect(createTimelineStore(Number.NaN).t()).toBe(0);
    expect(createTimelineStore(7).t()).toBe(1);
    const s = createTimelineStore(0.3);
    expect(s.t()).toBe(0.3);
    expect(s.timeline()).toBeNull();
    let calls = 0;
    const off = s.subscribe(() => calls++);
    const a = tl(0.3, false);
    s.publish(a);
    expect(calls).toBe(0);
    expect(s.timeline()).toBe(a);
    s.publish(tl(0.3, true));
    expect(calls).toBe(1);
    expect(s.playing()).toBe(true);
    s.publish(tl(0.41, true));
    expect(calls).toBe(2);
    expect(s.t()).toBe(0.41);
    off();
    s.publish(tl(0.5, true));
    expect(calls).toBe(2);
    expect(s.t()).toBe(0.5);
  });

  it('worked steps: held at the position where playing started, the exact position when paused', () => {
    expect(workedPosition(0.437, false, 0.1)).toBe(0.437);
    expect(workedPosition(0.437, true, 0.1)).toBe(0.1);
    const s = createTimelineStore(0.2);
    s.publish(tl(0.2, true));
    s.publish(tl(0.437, true));
    expect(s.tStill()).toBe(0.2);
    s.publish(tl(0.6, true));
    expect(s.tStill()).toBe(0.2);
    s.publish(tl(0.61, false));
    expect(s.tStill()).toBe(0.61);
  });

  it('the figures hold the paused position while playing; frames reach the frame listeners with the live position', () => {
    const s = createTimelineStore(0.2);
    expect(s.tStill()).toBe(0.2);
    s.publish(tl(0.2, true));
    s.publish(tl(0.35, true));
    expect(s.tStill()).toBe(0.2); // held: the figures move by per-frame writes, not by React
    const seen: number[] = [];
    const off = s.subscribeFrame((x) => seen.push(x));
    s.frame(0.36);
    s.frame(0.37);
    expect(seen).toEqual([0.36, 0.37]);
    expect(s.tLive()).toBe(0.37);
    off();
    s.frame(0.38);
    expect(seen).toEqual([0.36, 0.37]);
    s.publish(tl(0.38, false)); // paused: the figures render the exact position
    expect(s.tStill()).toBe(0.38);
    expect(s.t()).toBe(0.38);
  });
});

describe('frame cache', () => {
  it('returns the model frame at t (and its drawn lookup), the same object for the same t', () => {
    const src = resolveGrid({ grid: '', preset: 'random', size: 6, seed: 3 });
    const opts = lookupOptions({ align: 'center', vflip: true, wrap: 'mirror' });
    const path = pathOf({ u: -0.3, v: 0.2, u2: 1.4, v2: 0.9, path: 'circle' });
    const ctx = animContext(createTimelineStore(0), src.grid, opts, src, path);
    for (const t of [0, 0.13, 0.5, 0.97, 1]) {
      const f = ctx.frame(t);
      const want = frameAt(src.grid, opts, path, t);
      expect(f.frame).toEqual(want);
      expect(f.dq).toEqual(drawnLookup(src.grid, want.u, want.v, opts));
      expect(ctx.frame(t)).toBe(f);
    }
  });
});
