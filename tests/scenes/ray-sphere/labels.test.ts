// The cross-section's labels and handles: no handle covers a label, labels keep off the root
// markers and each other, the radius handle and the direction tip step aside from the roots.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  boxAt,
  distToSegment,
  overlapArea,
  pickClear,
  placeLabels,
  segmentHitsBox,
  type Box,
} from '../../../src/scenes/ray-sphere/view/labelLayout';
import {
  HANDLE_R,
  handlePositions,
  layoutCross,
  noteText,
  planLabels,
  X_,
  Y_,
  type Kept,
  type RayState,
} from '../../../src/scenes/ray-sphere/view/crossLayout';
import { computeModel } from '../../../src/scenes/ray-sphere/model';
import { CASE_PRESETS, PRECISION_PRESETS } from '../../../src/scenes/ray-sphere/params';

type V = [number, number, number];

const ray = (o: V, d: V, c: V, r: number): RayState => {
  const m = computeModel({ o, d, c, r, method: 'stable' });
  return { ...m.input, res: m.chosen, distanceRatio: m.distanceRatio };
};
/** Label sizes as the page would measure them, over-estimated a little (15 px type). */
const size = (_k: string, text: string): [number, number] => [9.5 * text.length + 2, 19];
const inflate = (b: Box, k: number): Box => ({ x: b.x - k, y: b.y - k, w: b.w + 2 * k, h: b.h + 2 * k });

describe('label geometry', () => {
  it('boxAt keeps a square of half-side gap about the anchor clear, in all eight directions', () => {
    for (const dir of [
      [1, 0],
      [1, -1],
      [0, -1],
      [-1, -1],
      [-1, 0],
      [-1, 1],
      [0, 1],
      [1, 1],
    ] as [number, number][]) {
      const b = boxAt([100, 100], dir, 10, 30, 12);
      expect(overlapArea(b, { x: 90, y: 90, w: 20, h: 20 })).toBe(0);
      // and touches it (no farther than asked)
      expect(overlapArea(inflate(b, 0.5), { x: 90, y: 90, w: 20, h: 20 })).toBeGreaterThan(0);
    }
  });
  it('segments against boxes and points', () => {
    const b = { x: 0, y: 0, w: 10, h: 10 };
    expect(segmentHitsBox([-5, 5], [15, 5], b)).toBe(true);
    expect(segmentHitsBox([-5, 15], [15, 15], b)).toBe(false);
    expect(segmentHitsBox([-5, -5], [-1, 20], b)).toBe(false);
    expect(distToSegment([5, 5], [0, 0], [10, 0])).toBe(5);
    expect(distToSegment([-3, 4], [0, 0], [10, 0])).toBe(5);
  });
  it('placeLabels moves a label off an obstacle at its preferred place', () => {
    const hard = [{ x: 110, y: 80, w: 40, h: 40 }];
    const [b] = placeLabels([{ anchor: [100, 100], gap: 8, w: 30, h: 14, prefer: [0] }], {
      W: 400,
      H: 300,
      hard,
      lines: [],
    });
    expect(overlapArea(b, hard[0])).toBe(0);
  });
  it('pickClear keeps its last choice while it is clear, else takes the first clear one', () => {
    const cands: [number, number][] = [
      [0, 0],
      [100, 0],
      [200, 0],
    ];
    expect(pickClear(cands, [[5, 0]], [], 30, null)).toBe(1);
    expect(pickClear(cands, [[5, 0]], [], 30, 2)).toBe(2);
    expect(pickClear(cands, [[195, 0]], [], 30, 2)).toBe(0);
  });
});

describe('the cross-section: no handle covers a label', () => {
  const check = (rs: RayState, W: number, H: number) => {
    const keep: Kept = { frame: null, view: null };
    const g = layoutCross(rs, [], W, H, null, keep);
    const labels = planLabels(g, size);
    const handles = handlePositions(g).map((h) => ({
      target: h.target,
      box: { x: h.at[0] - HANDLE_R, y: h.at[1] - HANDLE_R, w: 2 * HANDLE_R, h: 2 * HANDLE_R },
    }));
    const markers = g.rootPts.map((p) => ({ x: X_(g, p[0]) - 6.5, y: Y_(g, p[1]) - 6.5, w: 13, h: 13 }));
    for (const l of labels) {
      for (const h of handles) expect(overlapArea(l.box, h.box), `${l.key} under handle ${h.target}`).toBe(0);
      for (const m of markers) expect(overlapArea(l.box, m), `${l.key} on a root marker`).toBe(0);
      for (const k of labels) if (k !== l) expect(overlapArea(l.box, k.box), `${l.key} on ${k.key}`).toBe(0);
    }
    return { g, labels };
  };

  it('at every case preset, on a desktop and on a phone', () => {
    for (const p of CASE_PRESETS)
      for (const [W, H] of [
        [640, 397],
        [335, 280],
      ])
        check(ray(p.params.o as V, p.params.d as V, p.params.c as V, p.params.r!), W, H);
  });

  it('the radius handle steps off a root (it sat at 45° on the exit point, covering t₁)', () => {
    // the exit point of this ray is at 45° on the rim, where the radius handle used to be
    const s = Math.SQRT1_2;
    const { g } = check(ray([s - 3, s, 0], [1, 0, 0], [0, 0, 0], 1), 640, 397);
    const rx = X_(g, g.rHandle[0]);
    const ry = Y_(g, g.rHandle[1]);
    for (const p of g.rootPts)
      expect(Math.hypot(rx - X_(g, p[0]), ry - Y_(g, p[1]))).toBeGreaterThan(2 * HANDLE_R);
  });

  it('for random rays and spheres', () => {
    const coord = fc.double({ min: -4, max: 4, noNaN: true });
    fc.assert(
      fc.property(
        fc.tuple(coord, coord, coord),
        fc.tuple(coord, coord, coord).filter((d) => Math.hypot(...d) > 0.1),
        fc.double({ min: 0.3, max: 3, noNaN: true }),
        (o, d, r) => {
          check(ray(o, d, [0, 0, 0], r), 640, 397);
        },
      ),
      { numRuns: 200, seed: 24 },
    );
  });
});

describe('the not-to-scale note', () => {
  it('fits the figure: broken over two lines on a narrow figure, whole on a wide one', () => {
    const far = PRECISION_PRESETS.find((p) => p.id === 'far')!.params;
    for (const [W, H, lines] of [
      [335, 280, 3],
      [640, 397, 2],
      [1400, 500, 1],
    ] as const) {
      const g = layoutCross(ray(far.o as V, far.d as V, far.c as V, far.r!), [], W, H, null, {
        frame: null,
        view: null,
      });
      const note = planLabels(g, size).filter((l) => l.key.startsWith('note'));
      expect(note).toHaveLength(lines);
      expect(note.map((l) => l.text).join(' ')).toBe(noteText(g));
      for (const l of note) expect(l.box.x + l.box.w, l.text).toBeLessThanOrEqual(W);
    }
  });
});
