import { Deferred } from './Deferred';
import { useEffect, useId, useRef, useState, type ReactNode } from 'react';
import { formatNumber } from './Readout';
import { usePresent } from './pageKeys';
import { Stage } from './stage';
import './layout.css';
import './controls.css';

function clamp(x: number, min?: number, max?: number): number {
  if (min !== undefined && x < min) return min;
  if (max !== undefined && x > max) return max;
  return x;
}

function roundToStep(x: number, step: number | undefined): number {
  if (!step || !Number.isFinite(step) || step <= 0) return x;
  const r = Math.round(x / step) * step;
  // trim binary noise from the multiplication (0.1 * 3 → 0.30000000000000004)
  return Number.parseFloat(r.toPrecision(12));
}

export interface NumberFieldProps {
  label: ReactNode;
  value: number;
  onChange: (x: number) => void;
  min?: number;
  max?: number;
  step?: number;
  unit?: string;
  /** Hide the visible label (it stays for screen readers). */
  hideLabel?: boolean;
  id?: string;
  testId?: string;
}

/**
 * A number input that accepts only finite numbers within [min, max]: invalid text is flagged
 * (aria-invalid, with a message) and never reaches the model; Enter or blur commits.
 */
export function NumberField({
  label,
  value,
  onChange,
  min,
  max,
  step,
  unit,
  hideLabel,
  id,
  testId,
}: NumberFieldProps) {
  const autoId = useId();
  const inputId = id ?? autoId;
  const [text, setText] = useState(String(value));
  const [error, setError] = useState<string | null>(null);
  // whether the text was typed since it was last committed: leaving a field commits only then, so
  // a field that loses the focus after another link set its value (before the text caught up with
  // it) does not write its old text back over the link's value
  const edited = useRef(false);
  useEffect(() => {
    setText((t) => (Number(t) === value ? t : String(value)));
    setError(null);
  }, [value]);
  const commit = (raw: string) => {
    edited.current = false;
    const s = raw.trim();
    const x = s === '' ? NaN : Number(s);
    if (!Number.isFinite(x)) {
      setError('Enter a finite number');
      return;
    }
    const c = clamp(x, min, max);
    if (c !== x) {
      setError(`Kept within ${min ?? '−∞'} … ${max ?? '∞'}`);
      setText(String(c));
    } else setError(null);
    if (c !== value) onChange(c);
  };
  return (
    <div className="field">
      <label htmlFor={inputId} className={hideLabel ? 'sr-only' : 'field-label'}>
        {label}
        {unit ? <span className="field-unit"> ({unit})</span> : null}
      </label>
      <input
        id={inputId}
        data-testid={testId}
        className="number-input"
        type="text"
        inputMode="decimal"
        value={text}
        aria-invalid={error ? true : undefined}
        aria-describedby={error ? `${inputId}-err` : undefined}
        onChange={(e) => {
          edited.current = true;
          setText(e.target.value);
          const x = Number(e.target.value);
          if (e.target.value.trim() !== '' && Number.isFinite(x) && x === clamp(x, min, max)) {
            setError(null);
            if (x !== value) onChange(x);
          }
        }}
        onBlur={(e) => {
          if (edited.current) commit(e.target.value);
        }}
        onKeyDown={(e) => {
          if (e.key === 'Enter') commit((e.target as HTMLInputElement).value);
          else if ((e.key === 'ArrowUp' || e.key === 'ArrowDown') && step) {
            e.preventDefault();
            const next = roundToStep(clamp(value + (e.key === 'ArrowUp' ? step : -step), min, max), step);
            onChange(next);
          }
        }}
      />
      {error ? (
        <span id={`${inputId}-err`} className="field-error" role="status">
          {error}
        </span>
      ) : null}
    </div>
  );
}

export interface SliderProps {
  label: ReactNode;
  value: number;
  onChange: (x: number) => void;
  min: number;
  max: number;
  step?: number;
  /** Logarithmic track (min must be > 0); the number box still takes exact values. */
  log?: boolean;
  unit?: string;
  digits?: number;
  testId?: string;
}

const LOG_STEPS = 1000;

/**
 * A labelled range slider with a number box beside it. Keyboard: arrows / PageUp / PageDown /
 * Home / End on the slider (native), exact typing in the box.
 */
export function Slider({ log, unit, digits = 4, testId, ...box }: SliderProps) {
  // `box`: what the number box beside the track takes too
  const { label, value, onChange, min, max, step } = box;
  const id = useId();
  const useLog = !!log && min > 0;
  const toTrack = (x: number) =>
    useLog ? ((Math.log(x) - Math.log(min)) / (Math.log(max) - Math.log(min))) * LOG_STEPS : x;
  const fromTrack = (t: number) => {
    if (!useLog) return t;
    const x = Math.exp(Math.log(min) + (t / LOG_STEPS) * (Math.log(max) - Math.log(min)));
    return step ? clamp(roundToStep(x, step), min, max) : clamp(Number(x.toPrecision(3)), min, max);
  };
  return (
    <div className="field slider-field">
      <label htmlFor={id} className="field-label">
        {label}
        {unit ? <span className="field-unit"> ({unit})</span> : null}
      </label>
      <div className="slider-row">
        <input
          id={id}
          data-testid={testId}
          type="range"
          min={useLog ? 0 : min}
          max={useLog ? LOG_STEPS : max}
          step={useLog ? 1 : (step ?? 'any')}
          value={toTrack(clamp(value, min, max))}
          aria-valuetext={`${formatNumber(value, digits)}${unit ? ` ${unit}` : ''}`}
          onChange={(e) => {
            const x = fromTrack(Number(e.target.value));
            if (Number.isFinite(x) && x !== value) onChange(x);
          }}
        />
        <NumberField {...box} hideLabel />
      </div>
    </div>
  );
}

export interface SelectProps<T extends string> {
  label: ReactNode;
  value: T;
  options: readonly { value: T; label: string }[];
  onChange: (v: T) => void;
  testId?: string;
}

export function Select<T extends string>({ label, value, options, onChange, testId }: SelectProps<T>) {
  const id = useId();
  return (
    <div className="field">
      <label htmlFor={id} className="field-label">
        {label}
      </label>
      <select id={id} data-testid={testId} value={value} onChange={(e) => onChange(e.target.value as T)}>
        {options.map((o) => (
          <option key={o.value} value={o.value}>
            {o.label}
          </option>
        ))}
      </select>
    </div>
  );
}

export interface ToggleProps {
  label: ReactNode;
  checked: boolean;
  onChange: (v: boolean) => void;
  testId?: string;
}

export function Toggle({ label, checked, onChange, testId }: ToggleProps) {
  const id = useId();
  return (
    <div className="field toggle-field">
      <input
        id={id}
        data-testid={testId}
        type="checkbox"
        checked={checked}
        onChange={(e) => onChange(e.target.checked)}
      />
      <label htmlFor={id}>{label}</label>
    </div>
  );
}

export interface ExprFieldProps {
  label: ReactNode;
  value: string;
  onCommit: (s: string) => void;
  /** Message shown under the field (and aria-invalid) when the committed text was rejected. */
  error?: string | null;
  placeholder?: string;
  hint?: ReactNode;
  testId?: string;
}

/** A text field for a typed expression; commits on Enter or blur, never per keystroke. */
export function ExprField({ label, value, onCommit, error, placeholder, hint, testId }: ExprFieldProps) {
  const id = useId();
  const [text, setText] = useState(value);
  useEffect(() => setText(value), [value]);
  return (
    <div className="field expr-field">
      <label htmlFor={id} className="field-label">
        {label}
      </label>
      <input
        id={id}
        data-testid={testId}
        type="text"
        spellCheck={false}
        autoComplete="off"
        className="expr-input"
        value={text}
        placeholder={placeholder}
        maxLength={400}
        aria-invalid={error ? true : undefined}
        aria-describedby={error ? `${id}-err` : hint ? `${id}-hint` : undefined}
        onChange={(e) => setText(e.target.value)}
        onBlur={() => text !== value && onCommit(text)}
        onKeyDown={(e) => {
          if (e.key === 'Enter') onCommit(text);
        }}
      />
      {error ? (
        <span id={`${id}-err`} className="field-error" role="alert">
          {error}
        </span>
      ) : hint ? (
        <span id={`${id}-hint`} className="field-hint">
          {hint}
        </span>
      ) : null}
    </div>
  );
}

export function Panel({
  title,
  children,
  id,
  className,
}: {
  title?: ReactNode;
  children: ReactNode;
  id?: string;
  className?: string;
}) {
  const hid = useId();
  return (
    <section
      className={`panel${className ? ` ${className}` : ''}`}
      id={id}
      aria-labelledby={title ? hid : undefined}
    >
      {title ? (
        <h2 className="panel-title" id={hid}>
          {title}
        </h2>
      ) : null}
      {children}
    </section>
  );
}

/** A visible message; warnings and errors are announced (role=status / role=alert). */
export function Notice({
  kind = 'info',
  children,
  testId,
}: {
  kind?: 'info' | 'warn' | 'error';
  children: ReactNode;
  testId?: string;
}) {
  return (
    <div
      className={`notice notice-${kind}`}
      role={kind === 'error' ? 'alert' : 'status'}
      data-testid={testId}
    >
      {children}
    </div>
  );
}

/**
 * Responsive scene layout: controls | main | aside on wide screens, stacked on phones.
 *
 * `stage` (optional): the scene's main figure, its key readouts and its transport (see ./stage.tsx
 * for sizing the figure). Outside classroom mode it is shown at the top of `main`, with a
 * fullscreen button. In classroom mode (`present=1`) it comes first, filling the first screen,
 * the controls column folds into a drawer over it (the "Controls" button, key `c`), and `main`
 * follows below.
 */
export function SceneLayout({
  controls,
  main,
  aside,
  stage,
}: {
  controls: ReactNode;
  main: ReactNode;
  aside?: ReactNode;
  stage?: ReactNode;
}) {
  const present = usePresent();
  const hasStage = stage !== undefined && stage !== null && stage !== false;
  if (present && hasStage)
    return (
      <div className={`scene-layout stage-layout${aside ? ' has-aside' : ''}`}>
        <Stage staged controls={controls}>
          {stage}
        </Stage>
        <div className="scene-main">{main}</div>
        {aside ? <div className="scene-aside">{aside}</div> : null}
      </div>
    );
  return (
    <div className={`scene-layout${aside ? ' has-aside' : ''}`}>
      <div className="scene-controls">
        <Deferred estimate={600}>{controls}</Deferred>
      </div>
      <div className="scene-main">
        {hasStage ? <Stage staged={false}>{stage}</Stage> : null}
        {main}
      </div>
      {aside ? <div className="scene-aside">{aside}</div> : null}
    </div>
  );
}
