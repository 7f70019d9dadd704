/**
 * The scene's side panel: the integral (f, a, b) and the sampling (pdf, sequence, N, seed, given
 * samples), each field writing its URL parameter.
 */
import type { ParamValues } from '../../../kit/params';
import type { SceneProps } from '../../../kit/scene';
import { Notice, NumberField, Panel, Select, Slider } from '../../../ui';
import { EXAM_F } from '../model';
import { MAX_N, type McSchema, type PdfKind, type Strategy } from '../params';
import { FnField, SamplesField } from './Fields';

const PDF_OPTIONS: { value: PdfKind; label: string }[] = [
  { value: 'uniform', label: 'uniform, p = 1/(b − a)' },
  { value: 'linear', label: 'linear ramp through |f(a)|, |f(b)|' },
  { value: 'proportional', label: 'proportional to f' },
  { value: 'custom', label: 'custom (type p(x))' },
];
const SEQ_OPTIONS: { value: Strategy; label: string }[] = [
  { value: 'independent', label: 'independent (i.i.d.)' },
  { value: 'stratified', label: 'stratified (jittered)' },
  { value: 'halton', label: 'Halton (Owen-scrambled)' },
  { value: 'sobol', label: 'Sobol (Owen-scrambled)' },
];

export function McControls({
  params,
  setParams,
  n,
  fError,
  limitsMessage,
  pdfExprError,
}: {
  params: ParamValues<McSchema>;
  setParams: SceneProps<McSchema>['setParams'];
  /** N as used (rounded, clamped). */
  n: number;
  fError: string | null;
  limitsMessage: string | null;
  pdfExprError: string | null;
}) {
  const limit = (key: 'a' | 'b') => (
    <NumberField
      label={key}
      value={params[key]}
      min={-1000}
      max={1000}
      step={0.5}
      onChange={(v) => setParams(key === 'a' ? { a: v } : { b: v })}
      testId={`${key}-input`}
    />
  );
  return (
    <>
      <Panel title="Integral">
        <FnField
          label="f(x) ="
          value={params.f}
          error={fError ? `${fError} — using ${EXAM_F}` : null}
          onCommit={(s) => setParams({ f: s })}
          testId="f-input"
        />
        <div className="mc-limits">
          {limit('a')}
          {limit('b')}
        </div>
        {limitsMessage ? <Notice kind="warn">{limitsMessage}</Notice> : null}
      </Panel>
      <Panel title="Sampling">
        <Select
          label="pdf p(x)"
          value={params.pdf}
          options={PDF_OPTIONS}
          onChange={(v) => setParams({ pdf: v })}
          testId="pdf-select"
        />
        {params.pdf === 'custom' ? (
          <FnField
            label="p(x) ∝"
            value={params.pdfexpr}
            error={pdfExprError}
            onCommit={(s) => setParams({ pdfexpr: s })}
            testId="pdfexpr-input"
            hint="any positive multiple; normalized numerically"
          />
        ) : null}
        <Select
          label="sequence"
          value={params.strategy}
          options={SEQ_OPTIONS}
          onChange={(v) => setParams({ strategy: v })}
          testId="strategy-select"
        />
        <Slider
          label="samples N"
          value={n}
          min={1}
          max={MAX_N}
          step={1}
          log
          onChange={(v) => setParams({ n: Math.round(v) })}
          digits={8}
          testId="n-slider"
        />
        <NumberField
          label="seed"
          value={params.seed}
          min={0}
          max={4294967295}
          step={1}
          onChange={(v) => setParams({ seed: Math.round(v) })}
          testId="seed-input"
        />
        <SamplesField value={params.samples} onCommit={(s) => setParams({ samples: s })} />
      </Panel>
    </>
  );
}
