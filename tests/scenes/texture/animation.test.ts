/**
 * The texture scene's animation model: the query's path, the values along it, and the
 * creases of the bilinear reconstruction. Expected values are derived from the definitions here.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/texture/params';
import { creases } from '../../../src/scenes/texture/creases';
import { frameAt, pathOf, pathPoint, type QueryPath } from '../../../src/scenes/texture/path';
import { lookupAt, lookupOptions, resolveGrid } from '../../../src/scenes/texture/model';
import { pathProfile } from '../../../src/scenes/texture/pathProfile';
import {
  bilinear,
  checkerGrid,
  examGrid,
  nearest,
  randomGrid,
  type LookupOptions,
} from '../../../src/core/texture';

const EXAM: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const L = (u: number, v: number) => 21 + 4 * u - 20 * v;

describe('path', () => {
  it('defaults: a line from the exam query (0.4, 0.24) to (0.85, 0.8); t = 0 is the query exactly', () => {
    const p = parseParams(schema, '').values;
    expect(p.t).toBe(0);
    expect(p.play).toBe(false);
    const path = pathOf(p);
    expect(path.kind).toBe('line');
    expect(pathPoint(path, 0)).toEqual({ u: 0.4, v: 0.24 });
    expect(pathPoint(path, 1)).toEqual({ u: p.u2, v: p.v2 });
  });

  it('line: constant speed, clamped t', () => {
    const path: QueryPath = { kind: 'line', a: [0.1, 0.2], b: [0.9, 0.6] };
    const m = pathPoint(path, 0.5);
    expect(m.u).toBeCloseTo(0.5, 15);
    expect(m.v).toBeCloseTo(0.4, 15);
    expect(pathPoint(path, -3)).toEqual({ u: 0.1, v: 0.2 });
    expect(pathPoint(path, 7)).toEqual({ u: 0.9, v: 0.6 });
    expect(pathPoint(path, Number.NaN)).toEqual({ u: 0.1, v: 0.2 });
  });

  it('circle: through both ends (a at t = 0 and 1, b at t = ½), counter-clockwise, on the circle', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (au, av, bu, bv, t) => {
          const path: QueryPath = { kind: 'circle', a: [au, av], b: [bu, bv] };
          const c = [(au + bu) / 2, (av + bv) / 2];
          const r = Math.hypot(bu - au, bv - av) / 2;
          const p = pathPoint(path, t);
          expect(Math.abs(Math.hypot(p.u - c[0], p.v - c[1]) - r)).toBeLessThan(1e-9);
          const h = pathPoint(path, 0.5);
          expect(Math.abs(h.u - bu)).toBeLessThan(1e-9);
          expect(Math.abs(h.v - bv)).toBeLessThan(1e-9);
        },
      ),
    );
    const path: QueryPath = { kind: 'circle', a: [1, 0.5], b: [0, 0.5] };
    expect(pathPoint(path, 0)).toEqual({ u: 1, v: 0.5 });
    expect(pathPoint(path, 1)).toEqual({ u: 1, v: 0.5 });
    // a quarter turn counter-clockwise from (1, ½) about (½, ½) is (½, 1)
    const q = pathPoint(path, 0.25);
    expect(q.u).toBeCloseTo(0.5, 12);
    expect(q.v).toBeCloseTo(1, 12);
  });

  it('the frame at t is the lookup at the path point (what the scene shows at t)', () => {
    const g = randomGrid(6, 6, 7);
    const path: QueryPath = { kind: 'line', a: [0.05, 0.9], b: [0.95, 0.1] };
    for (const t of [0, 0.13, 0.5, 0.77, 1]) {
      const f = frameAt(g, EXAM, path, t);
      const p = pathPoint(path, t);
      expect(f.lookup).toEqual(lookupAt(g, p.u, p.v, EXAM));
      expect(f.lookup.bil.value).toBe(bilinear(g, p.u, p.v, EXAM));
    }
  });
});

describe('values along the path', () => {
  const line: QueryPath = { kind: 'line', a: [0.4, 0.24], b: [0.85, 0.8] };

  it('exam grid: the borders crossed are where the line meets the node lines; no kinks (the texture is linear)', () => {
    const p = pathProfile(examGrid(), EXAM, line);
    // u = 0.5, 0.75 and v = 0.25, 0.5, 0.75 along u = 0.4 + 0.45 t, v = 0.24 + 0.56 t
    const want = [
      (0.25 - 0.24) / 0.56,
      (0.5 - 0.4) / 0.45,
      (0.5 - 0.24) / 0.56,
      (0.75 - 0.4) / 0.45,
      (0.75 - 0.24) / 0.56,
    ].sort((a, b) => a - b);
    expect(p.borders.map((b) => b.t)).toHaveLength(want.length);
    p.borders.forEach((b, k) => expect(Math.abs(b.t - want[k])).toBeLessThan(1e-9));
    expect(p.borders.every((b) => !b.kink && !b.jump)).toBe(true);
    // bilinear along the path equals the linear function
    p.ts.forEach((t, k) =>
      expect(Math.abs(p.bil[k] - L(0.4 + 0.45 * t, 0.24 + 0.56 * t))).toBeLessThan(1e-9),
    );
    expect(p.breaks).toEqual([]);
  });

  it('nearest is a step function: each piece equals the lookup inside it, switching where the nearest node changes', () => {
    const g = examGrid();
    const p = pathProfile(g, EXAM, line);
    // nearest node changes where u crosses 0.625 and v crosses 0.375, 0.625
    const want = [(0.375 - 0.24) / 0.56, (0.625 - 0.4) / 0.45, (0.625 - 0.24) / 0.56].sort((a, b) => a - b);
    expect(p.nearSwitches).toHaveLength(3);
    p.nearSwitches.forEach((t, k) => expect(Math.abs(t - want[k])).toBeLessThan(1e-9));
    for (const piece of p.near) {
      for (const f of [0.1, 0.5, 0.9]) {
        const q = pathPoint(line, piece.t0 + f * (piece.t1 - piece.t0));
        expect(nearest(g, q.u, q.v, EXAM)).toBe(piece.value);
      }
    }
    expect(p.near[0].t0).toBe(0);
    expect(p.near[p.near.length - 1].t1).toBe(1);
  });

  it('checkerboard: every border crossed is a kink', () => {
    const p = pathProfile(checkerGrid(8, 8), EXAM, line);
    expect(p.borders.length).toBeGreaterThan(3);
    expect(p.borders.every((b) => b.kink)).toBe(true);
  });

  it('repeat with corner nodes across u = 1: one border, a jump (column 4 to column 0), no kink claimed', () => {
    const p = pathProfile(
      examGrid(),
      { ...EXAM, wrap: 'repeat' },
      { kind: 'line', a: [0.4, 0.24], b: [1.6, 0.3] },
    );
    const jumps = p.borders.filter((b) => b.jump);
    expect(jumps).toHaveLength(1);
    expect(Math.abs(jumps[0].t - 0.5)).toBeLessThan(1e-9);
    expect(p.breaks).toHaveLength(1);
    // the two sides of the break: u → 1⁻ is column 4, u → 1⁺ wraps to column 0
    const k = p.breaks[0];
    expect(p.bil[k - 1] - p.bil[k]).toBeCloseTo(4, 6);
  });

  it('clamp: leaving [0, 1] is a kink (the value freezes at the edge)', () => {
    const p = pathProfile(examGrid(), EXAM, { kind: 'line', a: [0.5, 0.5], b: [1.5, 0.5] });
    const edge = p.borders.find((b) => Math.abs(b.t - 0.5) < 1e-9);
    expect(edge?.kink).toBe(true);
    expect(p.bil[p.bil.length - 1]).toBeCloseTo(L(1, 0.5), 12);
  });

  it('toggling the conventions changes the profile (texel centres on the exam grid)', () => {
    const a = pathProfile(examGrid(), EXAM, line);
    const b = pathProfile(examGrid(), { ...EXAM, align: 'center' }, line);
    expect(b.bil[0]).not.toBe(a.bil[0]);
    expect(b.bil[0]).toBeCloseTo(bilinear(examGrid(), 0.4, 0.24, { ...EXAM, align: 'center' }), 15);
  });
});

describe('creases of the bilinear reconstruction', () => {
  it('the exam grid is linear: no crease on any of its 6 interior node lines', () => {
    const c = creases(examGrid(), EXAM);
    expect(c.lines).toBe(6);
    expect(c.creased).toBe(0);
    expect(c.list).toEqual([]);
  });

  it('the checkerboard creases along every interior node line, full length', () => {
    const c = creases(checkerGrid(8, 8), EXAM);
    expect(c.lines).toBe(12);
    expect(c.creased).toBe(12);
    expect(c.list.every((x) => x.from === 0 && x.to === 1)).toBe(true);
  });

  it('one bumped value creases only the node lines through it, only in the cells next to it', () => {
    const g = examGrid();
    const values = new Float64Array(g.values);
    values[2 * 5 + 2] += 10; // node (2, 2) at (0.5, 0.5)
    const c = creases({ ...g, values }, EXAM);
    // lines u = 0.25, 0.5, 0.75 and v = 0.25, 0.5, 0.75 each crease over v (or u) ∈ [0.25, 0.75]
    expect(c.creased).toBe(6);
    for (const x of c.list) {
      expect(x.from).toBe(0.25);
      expect(x.to).toBe(0.75);
    }
  });

  it('texel centres with clamp: the linear exam grid creases at the first and last centres (flat beyond them)', () => {
    const c = creases(examGrid(), { ...EXAM, align: 'center' });
    expect(c.lines).toBe(10);
    expect(c.list.map((x) => `${x.axis}${x.at}`).sort()).toEqual(['u0.1', 'u0.9', 'v0.1', 'v0.9']);
  });
});

describe('scene parameters', () => {
  it('t, play, path, u2, v2 parse and clamp', () => {
    const p = parseParams(schema, 't=0.35&play=1&path=circle&u2=0.1&v2=9').values;
    expect(p.t).toBe(0.35);
    expect(p.play).toBe(true);
    expect(p.path).toBe('circle');
    expect(p.u2).toBe(0.1);
    expect(p.v2).toBe(4);
    const bad = parseParams(schema, 't=2&path=spiral');
    expect(bad.values.t).toBe(1);
    expect(bad.values.path).toBe('line');
    expect(resolveGrid(bad.values).isExam).toBe(true);
    expect(lookupOptions(bad.values)).toEqual(EXAM);
  });
});
