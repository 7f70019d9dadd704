import { describe, expect, test } from 'vitest';
import { isValidElement, type ReactElement } from 'react';
import { bindControls } from '../../src/ui/paramControls';
import type { ParamSchema, ParamValues } from '../../src/kit/params';

const schema = {
  n: { kind: 'number', default: 64, min: 1, max: 4096, integer: true },
  r: { kind: 'number', default: 0.5, min: 0.1, max: 2 },
  wrap: { kind: 'enum', default: 'clamp', values: ['clamp', 'repeat'] },
  flip: { kind: 'bool', default: false },
} as const satisfies ParamSchema;

type V = ParamValues<typeof schema>;
const values: V = { n: 64, r: 0.5, wrap: 'clamp', flip: false };

function bound() {
  const patches: Partial<V>[] = [];
  const c = bindControls(schema, values, (p) => patches.push(p));
  return { c, patches };
}

type Props = Record<string, unknown> & { onChange: (v: unknown) => void };
const props = (node: unknown): Props => {
  expect(isValidElement(node)).toBe(true);
  return (node as ReactElement<Props>).props;
};

describe('bindControls', () => {
  test('a slider takes its range from the schema and writes whole numbers for an integer parameter', () => {
    const { c, patches } = bound();
    const p = props(c.slider('n', 'Samples'));
    expect([p.min, p.max, p.step, p.value, p.testId]).toEqual([1, 4096, 1, 64, 'n']);
    p.onChange(12.6);
    expect(patches).toEqual([{ n: 13 }]);
  });

  test('a real parameter keeps its value; a narrower range and options pass through', () => {
    const { c, patches } = bound();
    const p = props(c.slider('r', 'Radius', { max: 1, log: true, testId: 'radius' }));
    expect([p.min, p.max, p.step, p.log, p.testId]).toEqual([0.1, 1, undefined, true, 'radius']);
    p.onChange(0.73);
    expect(patches).toEqual([{ r: 0.73 }]);
  });

  test('select, toggle and number write their own parameter', () => {
    const { c, patches } = bound();
    props(
      c.select('wrap', 'Wrap', [
        { value: 'clamp', label: 'Clamp' },
        { value: 'repeat', label: 'Repeat' },
      ]),
    ).onChange('repeat');
    props(c.toggle('flip', 'Flip')).onChange(true);
    const num = props(c.number('n', 'Seed'));
    expect([num.min, num.max, num.step]).toEqual([1, 4096, 1]);
    num.onChange(7.2);
    expect(patches).toEqual([{ wrap: 'repeat' }, { flip: true }, { n: 7 }]);
  });
});
