/**
 * The texture scene's figures in words: the numbers are the model's (computed here from the exam
 * grid's definition L(u, v) = 21 + 4u − 20v or from the model), and the texts change with the state.
 */
import { describe, expect, it } from 'vitest';
import { checkerGrid, examGrid } from '../../../src/core/texture';
import { addressingNotes, lookupOptions } from '../../../src/scenes/texture/model';
import { frameAt, pathOf } from '../../../src/scenes/texture/path';
import { pathProfile } from '../../../src/scenes/texture/pathProfile';
import { sphereModel } from '../../../src/scenes/texture/sphere';
import {
  coord,
  describeLookup,
  describePath,
  describePathStructure,
  describeSphere,
  describeTexture,
  describeReconstruction,
  gridTableColumns,
  gridTableRows,
  nearestEvents,
  pathEvents,
  pathSamples,
  pathTableRows,
  short,
  textureName,
} from '../../../src/scenes/texture/view/describe';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const EXAM = lookupOptions({ align: 'corner', vflip: false, wrap: 'clamp' });
const PATH = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
const EXAM_POINT = { x: 1, y: 1, z: Math.SQRT2, normalize: true };

function state(t: number, opts = EXAM, grid = examGrid(), point = EXAM_POINT) {
  const frame = frameAt(grid, opts, PATH, t);
  const sphere = sphereModel(grid, point, opts);
  return {
    name: textureName(grid, 'grid', true),
    opts,
    frame,
    path: PATH,
    notes: addressingNotes(frame.u, frame.v, opts, frame.lookup),
    editing: null,
    sphere: describeSphere(sphere, point, point.normalize),
  };
}

describe('formats', () => {
  it('coordinates keep two decimals, values four significant digits', () => {
    expect(coord(0.4)).toBe('0.40');
    expect(coord(0.24)).toBe('0.24');
    expect(coord(0.1234)).toBe('0.1234');
    expect(coord(-0)).toBe('0.00');
    expect(short(17.8 + 1e-12)).toBe('17.8');
    expect(short(21 - 4 * Math.PI)).toBe(String(Number((21 - 4 * Math.PI).toPrecision(4))));
    expect(short(NaN)).toBe('undefined');
  });
});

describe('the main figure', () => {
  it('at the exam’s query: the cell, the four nodes and their weights, bilinear and nearest', () => {
    const s = describeTexture(state(0));
    expect(s).toMatch(/^The exam’s 5 × 5 texture, corner nodes, clamp addressing\./);
    expect(s).toContain('The query point at u 0.40, v 0.24 lies in cell (1, 0)');
    // the cell [0.25, 0.5] × [0, 0.25]: upper row 17, 18, lower row 22, 23
    expect(s).toContain(`bilinear ${short(L(0.4, 0.24))} from 17, 18 above and 22, 23 below`);
    // weights: fu = 0.6, fv = 0.96
    expect(s).toContain(
      `(weights ${short(0.4 * 0.96)}, ${short(0.6 * 0.96)}, ${short(0.4 * 0.04)}, ${short(0.6 * 0.04)})`,
    );
    expect(s).toContain('nearest 18, the node (2, 1) at (0.50, 0.25)');
    expect(s).toContain('at the start of its path, a line from (0.40, 0.24) to (0.85, 0.80)');
    // the sphere point: (π/4, π/4) → (1/8, 1/4)
    expect(s).toContain('azimuth φ 45°, polar angle θ 45°');
    expect(s).toContain(`(u, v) = (φ/2π, θ/π) = (0.125, 0.25), bilinear ${short(L(1 / 8, 1 / 4))}`);
  });

  it('follows the moving point: at t = 0.3 the numbers are the model’s there', () => {
    const s0 = describeTexture(state(0));
    const st = state(0.3);
    const s = describeTexture(st);
    expect(s).not.toBe(s0);
    expect(s).toContain(`u ${coord(st.frame.u)}, v ${coord(st.frame.v)}`);
    expect(s).toContain(`bilinear ${short(L(st.frame.u, st.frame.v))} from`);
    expect(s).toContain(`nearest ${short(st.frame.lookup.near.value)}`);
    expect(s).toContain('The query is at t = 0.30 on its path');
  });

  it('changes with the conventions and says why the query was changed', () => {
    const flipped = describeTexture(state(0, lookupOptions({ align: 'corner', vflip: true, wrap: 'clamp' })));
    expect(flipped).toContain('v flipped (v′ = 1 − v)');
    expect(flipped).toContain('v-flip: v′ = 1 − v = 0.76.');
    // nearest in the flipped frame: j = round(0.76 · 4) = 3
    expect(flipped).toContain(`nearest ${21 - 5 * 3 + 2}`);
    const centres = describeTexture(
      state(0, lookupOptions({ align: 'center', vflip: false, wrap: 'repeat' })),
    );
    expect(centres).toContain('texel centres, repeat addressing');
    expect(centres).not.toBe(describeTexture(state(0)));
  });

  it('names other textures and the cell being edited', () => {
    expect(textureName(checkerGrid(8, 8), 'checker', false)).toBe('an 8 × 8 checkerboard');
    expect(textureName(checkerGrid(6, 6), 'random', false)).toBe('a 6 × 6 random texture');
    const s = describeTexture({ ...state(0), editing: { i: 2, j: 1, value: 18 } });
    expect(s).toContain('Editing cells: node (2, 1) chosen, value 18.');
  });

  it('describes a lookup on its own', () => {
    const f = frameAt(examGrid(), EXAM, PATH, 0);
    expect(describeLookup(f.lookup, 0.4, 0.24)).toContain('cell (1, 0)');
    expect(describePath(pathOf({ u: 0.4, v: 0.24, u2: 0.6, v2: 0.7, path: 'circle' }), 0.5)).toBe(
      'The query is at t = 0.50 on its path, a circle through (0.40, 0.24) and (0.60, 0.70).',
    );
  });
});

describe('ask first: the setup without the results', () => {
  it('says where the query and the sphere point are, and no value looked up', () => {
    const st = state(0);
    const s = describeTexture({
      ...st,
      ask: true,
      sphere: describeSphere(sphereModel(examGrid(), EXAM_POINT, EXAM), EXAM_POINT, true, true),
    });
    expect(s).toContain('The query point at u 0.40, v 0.24; the values looked up there are hidden');
    expect(s).toContain('The sphere point (1, 1, 1.414); its angles and texture coordinates are hidden');
    expect(s).not.toMatch(/bilinear|nearest|45°|0\.125/);
    expect(describeTexture(st)).toMatch(/bilinear/);
  });
});

describe('the sphere point', () => {
  it('normalized, not normalized, at a pole, and without a direction', () => {
    const g = examGrid();
    const raw = describeSphere(sphereModel(g, { ...EXAM_POINT, normalize: false }, EXAM), EXAM_POINT, false);
    expect(raw).toContain(`(φ, θ) = (${coord(Math.PI / 4)}, ${coord(Math.PI / 4)}) in radians`);
    expect(raw).toContain(`bilinear ${short(21 - 4 * Math.PI)}`);
    const pole = { x: 0, y: 0, z: 2, normalize: true };
    expect(describeSphere(sphereModel(g, pole, EXAM), pole, true)).toContain('a pole: φ taken as 0');
    const none = { x: 0, y: 0, z: 0, normalize: true };
    const s = describeSphere(sphereModel(g, none, EXAM), none, true);
    expect(s).toMatch(/^The sphere point \(0, 0, 0\) gives no texture coordinates: /);
  });
});

describe('the value along the path', () => {
  it('the exam grid: borders without kinks; the checkerboard: kinks, as events at the borders', () => {
    const pe = pathProfile(examGrid(), EXAM, PATH);
    expect(pe.borders.length).toBeGreaterThan(0);
    const se = describePathStructure(pe);
    expect(se).toContain(`crossing ${pe.borders.length} cell borders`);
    expect(se).toContain('0 with a kink');
    const ee = pathEvents(pe);
    expect(ee.map((e) => e.x)).toEqual(pe.borders.map((b) => b.t));
    expect(ee.every((e) => e.label.includes('no kink'))).toBe(true);

    const pc = pathProfile(checkerGrid(8, 8), EXAM, PATH);
    const kinks = pc.borders.filter((b) => b.kink).length;
    expect(kinks).toBeGreaterThan(0);
    expect(describePathStructure(pc)).toContain(`${kinks} with a kink`);
    expect(pathEvents(pc).filter((e) => e.label.includes('a kink')).length).toBe(kinks);
  });

  it('repeat with corner nodes: a jump where the path leaves [0, 1]', () => {
    const opts = lookupOptions({ align: 'corner', vflip: false, wrap: 'repeat' });
    const path = pathOf({ u: 0.4, v: 0.24, u2: 1.6, v2: 0.3, path: 'line' });
    const p = pathProfile(examGrid(), opts, path);
    const jumps = p.borders.filter((b) => b.jump).length;
    expect(jumps).toBeGreaterThan(0);
    expect(describePathStructure(p)).toContain(`except ${jumps} jump`);
    expect(pathEvents(p).some((e) => e.label.includes('jumps'))).toBe(true);
  });
});

describe('the plot’s data and the texture as tables', () => {
  it('samples: nearest and bilinear at evenly spaced t; bilinear is the plane L on the exam grid', () => {
    const s = pathSamples(examGrid(), EXAM, PATH, 10);
    expect(s.ts).toHaveLength(11);
    s.ts.forEach((t, k) => {
      const f = frameAt(examGrid(), EXAM, PATH, t);
      expect(s.bil[k]).toBeCloseTo(L(f.u, f.v), 9);
      expect(s.near[k]).toBe(f.lookup.near.value);
    });
  });

  it('table rows: the samples plus every border and step, in order, each named', () => {
    const p = pathProfile(examGrid(), EXAM, PATH);
    const rows = pathTableRows(examGrid(), EXAM, PATH, p, 20);
    expect(rows.length).toBe(21 + p.borders.length + p.nearSwitches.length);
    const ts = rows.map((r) => Number(r[0]));
    expect([...ts].sort((a, b) => a - b)).toEqual(ts);
    expect(rows.filter((r) => r[3].includes('cell border')).length).toBe(p.borders.length);
    const steps = nearestEvents(p);
    expect(steps.map((e) => e.x)).toEqual(p.nearSwitches);
    expect(steps[0].label).toBe(`nearest steps to ${short(p.near[1].value)}`);
  });

  it('the grid as rows top first, with the node coordinates as headings', () => {
    const g = examGrid();
    expect(gridTableColumns(g, EXAM)).toEqual(['v \\ u', 'u 0', 'u 0.25', 'u 0.5', 'u 0.75', 'u 1']);
    const rows = gridTableRows(g, EXAM);
    expect(rows[0]).toEqual(['1', '1', '2', '3', '4', '5']);
    expect(rows[4]).toEqual(['0', '21', '22', '23', '24', '25']);
    const centres = lookupOptions({ align: 'center', vflip: false, wrap: 'clamp' });
    expect(gridTableColumns(g, centres)[1]).toBe('u 0.1');
  });

  it('a reconstruction: its range, the query and (bilinear) the creases', () => {
    const s = describeReconstruction('bilinear', { min: 1, max: 25 }, 0.4, 0.24, 12);
    expect(s).toContain('values from 1 to 25');
    expect(s).toContain('12 creased pieces');
    expect(s).toContain('(0.40, 0.24)');
    expect(describeReconstruction('nearest', { min: 0, max: 1 }, 0, 1, 0)).toContain('piecewise constant');
  });
});
