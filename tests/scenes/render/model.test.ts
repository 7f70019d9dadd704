/**
 * The render lab's URL contract and model: parsing and clamping of its parameters, the named
 * problems of values it would not use, the camera and pixel fallbacks, and the click → pixel map.
 */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/render/params';
import { buildRenderModel } from '../../../src/scenes/render/model';
import { checkValues } from '../../../src/scenes/render/check';
import { pixelAt } from '../../../src/scenes/render/RenderLab';
import { inspectArgs, inspectOptions } from '../../../src/scenes/render/jobArgs';
import { defaultView, EXAM_DEFAULTS } from '../../../src/core/render/scene';
import { renderKey, workerCount } from '../../../src/scenes/render/useProgressiveRender';

const model = (q: string) => buildRenderModel(parseParams(schema, q).values);

describe('render lab parameters', () => {
  it('opens on the exam scene with the preset view and no inspected pixel', () => {
    const m = model('');
    expect(m.spec.scene).toBe('exam');
    expect(m.spec.exam.rho).toBe(EXAM_DEFAULTS.rho);
    expect(m.view).toEqual(defaultView('exam'));
    expect(m.px).toBeNull();
    expect(m.problems).toEqual([]);
    expect(inspectArgs(m)).toBeNull();
  });

  it('clamps res, spp and bounces with named notices', () => {
    const { values, problems } = parseParams(schema, 'res=4096&spp=0&bounces=20&strategy=nope');
    expect(values.res).toBe(512);
    expect(values.spp).toBe(1);
    expect(values.bounces).toBe(8);
    expect(values.strategy).toBe('mis-power');
    expect(problems.map((p) => p.name).sort()).toEqual(['bounces', 'res', 'spp', 'strategy']);
  });

  it('passes a biased variant to the estimator, and names one that changes nothing', () => {
    expect(model('bias=no-cos-l&strategy=area').trace.bias).toBe('no-cos-l');
    expect(model('bias=no-cos-l&strategy=area').problems).toEqual([]);
    expect(model('bias=clamp').problems).toEqual([]);
    const idle = model('bias=no-cos-l&strategy=cosine');
    expect(idle.problems.map((p) => p.name)).toEqual(['bias']);
    expect(idle.problems[0].message).toMatch(/only area sampling/);
    expect(parseParams(schema, 'bias=wrong').problems.map((p) => p.name)).toEqual(['bias']);
  });

  it('asks for the gpu renderer by default, takes cpu, and names anything else', () => {
    expect(model('').renderer).toBe('gpu');
    expect(model('renderer=cpu').renderer).toBe('cpu');
    const { values, problems } = parseParams(schema, 'renderer=webgl');
    expect(values.renderer).toBe('gpu');
    expect(problems[0].name).toBe('renderer');
  });

  it('runs to spp while playing, holds at t when paused, and clamps t to spp with a named problem', () => {
    expect(model('spp=32').target).toBe(32);
    expect(model('spp=32&t=5').target).toBe(32);
    expect(model('spp=32&play=0').target).toBe(0);
    const held = model('spp=32&play=0&t=12');
    expect(held.target).toBe(12);
    expect(held.problems).toEqual([]);
    const over = model('spp=32&play=0&t=100');
    expect(over.target).toBe(32);
    expect(over.problems.map((p) => p.name)).toEqual(['t']);
    expect(over.problems[0].message).toMatch(/more than spp=32; holding at 32/);
    expect(checkValues(parseParams(schema, 'spp=8&play=0&t=9').values).map((p) => p.name)).toEqual(['t']);
    // t outside its own range is clamped by the parser, with its own problem
    expect(parseParams(schema, 't=-3').problems.map((p) => p.name)).toEqual(['t']);
  });

  it('takes eye, look and fov from the link, each in place of the preset’s', () => {
    const m = model('scene=furnace&eye=1,2,3&fov=30');
    expect(m.view).toEqual({ eye: [1, 2, 3], look: defaultView('furnace').look, fov: 30 });
  });

  it('names a camera that looks at its own eye, and looks elsewhere', () => {
    const m = model('eye=1,1,1&look=1,1,1');
    expect(m.problems.map((p) => p.name)).toEqual(['look']);
    expect(m.view.look).not.toEqual(m.view.eye);
  });

  it('names a bad grid and falls back to the exam’s', () => {
    const m = model('grid=1,2;3');
    expect(m.problems[0].name).toBe('grid');
    expect(m.spec.exam.grid.width).toBe(5);
    expect(checkValues(parseParams(schema, 'grid=1,2;3').values).map((p) => p.name)).toEqual(['grid']);
  });

  it('keeps the inspected pixel inside the image', () => {
    const m = model('res=64&px=100,3.4');
    expect(m.px).toEqual([63, 3]);
    expect(m.problems.map((p) => p.name)).toEqual(['px']);
    const a = inspectArgs(m);
    expect(a?.px).toEqual([63, 3]);
    expect(inspectOptions(a!)).toMatchObject({ width: 64, height: 64, pn: 4096, strategy: 'mis-power' });
  });

  it('restarts the render only when the image changes', () => {
    expect(renderKey(model('px=1,1&pn=100'))).toBe(renderKey(model('')));
    expect(renderKey(model('seed=2'))).not.toBe(renderKey(model('')));
    expect(renderKey(model('grid=1,2;3,4'))).not.toBe(renderKey(model('')));
  });

  it('uses the cores but one for workers, one to four', () => {
    expect(workerCount(undefined)).toBe(1);
    expect(workerCount(1)).toBe(1);
    expect(workerCount(3)).toBe(2);
    expect(workerCount(64)).toBe(4);
  });
});

describe('a click on the image', () => {
  it('maps to the pixel under it at any drawn size', () => {
    expect(pixelAt(0, 0, 300, 300, 128)).toEqual([0, 0]);
    expect(pixelAt(299.9, 150, 300, 300, 128)).toEqual([127, 64]);
    expect(pixelAt(300, 10, 300, 300, 128)).toBeNull();
    expect(pixelAt(-1, 10, 300, 300, 128)).toBeNull();
    expect(pixelAt(1, 1, 0, 0, 128)).toBeNull();
  });
});
