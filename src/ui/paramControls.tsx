/**
 * Controls bound to a scene's URL parameters. A scene's settings panel is mostly sliders, selects
 * and check boxes, each reading one parameter and writing it back with `setParams`; spelled out,
 * every one repeats the same six lines. `bindControls(schema, params, setParams)` returns makers that
 * take the parameter's name and label and read the rest from the schema: the range of a slider is the
 * range the URL parser clamps to (so a control can never offer a value a link would refuse), and a
 * whole-number parameter's slider writes whole numbers.
 */
import type { ComponentType, ReactNode } from 'react';
import type { ParamSchema, ParamSpec, ParamValues } from '../kit/params';
import { NumberField, Select, Slider, Toggle, type SliderProps } from './controls';

type KeysOfKind<S extends ParamSchema, K extends ParamSpec['kind']> = {
  [N in keyof S]: S[N] extends { kind: K } ? N : never;
}[keyof S] &
  string;

type NumberSpec = Extract<ParamSpec, { kind: 'number' }>;

/** What the controls of a number parameter (Slider, NumberField) all take. */
interface NumberControlProps {
  label: ReactNode;
  value: number;
  onChange: (x: number) => void;
}

export interface SliderOptions extends Pick<SliderProps, 'log' | 'unit' | 'digits' | 'step'> {
  /** A narrower range than the schema's (the number box still clamps to this one). */
  min?: number;
  max?: number;
  testId?: string;
}

export interface BoundControls<S extends ParamSchema> {
  /** A slider with a number box for a number parameter. */
  slider(name: KeysOfKind<S, 'number'>, label: ReactNode, opts?: SliderOptions): ReactNode;
  /** A bare number box for a number parameter (a seed, an exact count). */
  number(name: KeysOfKind<S, 'number'>, label: ReactNode, opts?: { testId?: string }): ReactNode;
  /** A select for an enum parameter, with a label per value (in the order given). */
  select<N extends KeysOfKind<S, 'enum'>>(
    name: N,
    label: ReactNode,
    options: readonly { value: ParamValues<S>[N]; label: string }[],
    opts?: { testId?: string },
  ): ReactNode;
  /** A check box for a boolean parameter. */
  toggle(name: KeysOfKind<S, 'bool'>, label: ReactNode, opts?: { testId?: string }): ReactNode;
}

export function bindControls<S extends ParamSchema>(
  schema: S,
  params: ParamValues<S>,
  setParams: (patch: Partial<ParamValues<S>>) => void,
): BoundControls<S> {
  const set = (name: string, v: unknown) => setParams({ [name]: v } as Partial<ParamValues<S>>);
  const get = (name: string) => (params as Record<string, unknown>)[name];
  const numberSpec = (name: string) => schema[name] as NumberSpec;
  const whole = (spec: NumberSpec, v: number) => (spec.integer ? Math.round(v) : v);
  // A number parameter's control, a slider or a bare box: it shows the parameter's value and writes
  // what it is given back (rounded for a whole-number parameter); `rest` is what differs.
  const numberControl = <P extends NumberControlProps>(
    Control: ComponentType<P>,
    name: string,
    label: ReactNode,
    rest: Omit<P, keyof NumberControlProps>,
  ) => {
    const spec = numberSpec(name);
    const bound: NumberControlProps = {
      label,
      value: get(name) as number,
      onChange: (v) => set(name, whole(spec, v)),
    };
    return <Control key={name} {...(rest as P)} {...bound} />;
  };
  return {
    slider(name, label, opts = {}) {
      const spec = numberSpec(name);
      return numberControl(Slider, name, label, {
        min: opts.min ?? spec.min ?? 0,
        max: opts.max ?? spec.max ?? 1,
        step: opts.step ?? (spec.integer ? 1 : undefined),
        log: opts.log,
        unit: opts.unit,
        digits: opts.digits,
        testId: opts.testId ?? name,
      });
    },
    number(name, label, opts = {}) {
      const spec = numberSpec(name);
      const step = spec.integer ? 1 : undefined;
      return numberControl(NumberField, name, label, {
        min: spec.min,
        max: spec.max,
        step,
        testId: opts.testId,
      });
    },
    select(name, label, options, opts = {}) {
      return (
        <Select
          key={name}
          label={label}
          value={get(name) as string}
          options={options as readonly { value: string; label: string }[]}
          onChange={(v) => set(name, v)}
          testId={opts.testId ?? name}
        />
      );
    },
    toggle(name, label, opts = {}) {
      return (
        <Toggle
          key={name}
          label={label}
          checked={get(name) as boolean}
          onChange={(v) => set(name, v)}
          testId={opts.testId ?? name}
        />
      );
    },
  };
}
