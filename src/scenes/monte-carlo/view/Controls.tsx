/**
 * The scene's side panel: the integral (f, a, b) and the sampling pdf, which the exam's figure
 * needs, then the rest of the sampling (sequence, N, seed, given samples) folded under "More
 * settings"; each field writes its URL parameter.
 */
import type { ParamValues } from '../../../kit/params';
import type { SceneProps } from '../../../kit/scene';
import { Notice, NumberField, Panel } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { bindControls } from '../../../ui/paramControls';
import { EXAM_F } from '../exam';
import { schema, type McSchema, type PdfKind, type Strategy } from '../params';
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
  fError,
  limitsMessage,
  pdfExprError,
}: {
  params: ParamValues<McSchema>;
  setParams: SceneProps<McSchema>['setParams'];
  fError: string | null;
  limitsMessage: string | null;
  pdfExprError: string | null;
}) {
  const bound = bindControls(schema, params, setParams);
  // the limits step by halves (the schema's range, but not a whole-number parameter)
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
  // a typed expression, committed on Enter or blur (f and the custom pdf)
  const expression = (key: 'f' | 'pdfexpr', label: string, error: string | null, hint?: string) => (
    <FnField
      label={label}
      value={params[key]}
      error={error}
      onCommit={(s) => setParams(key === 'f' ? { f: s } : { pdfexpr: s })}
      testId={`${key}-input`}
      hint={hint}
    />
  );
  return (
    <>
      <Panel title="Integral">
        {expression('f', 'f(x) =', fError ? `${fError} — using ${EXAM_F}` : null)}
        <div className="mc-limits">
          {limit('a')}
          {limit('b')}
        </div>
        {limitsMessage ? <Notice kind="warn">{limitsMessage}</Notice> : null}
      </Panel>
      <Panel title="Sampling">
        {bound.select('pdf', 'pdf p(x)', PDF_OPTIONS, { testId: 'pdf-select' })}
        {params.pdf === 'custom'
          ? expression('pdfexpr', 'p(x) ∝', pdfExprError, 'any positive multiple; normalized numerically')
          : null}
        <Fold name="settings" summary="More settings: sequence, N, seed, given samples">
          {bound.select('strategy', 'sequence', SEQ_OPTIONS, { testId: 'strategy-select' })}
          {/* N of the estimate ⟨I⟩ (b) and of the convergence plots; the race has its own fixed
              length (RACE_MAX), said on its transport: the exam fixes neither */}
          {bound.slider('n', 'samples N of the estimate', { log: true, digits: 8, testId: 'n-slider' })}
          {bound.number('seed', 'seed', { testId: 'seed-input' })}
          <SamplesField value={params.samples} onCommit={(s) => setParams({ samples: s })} />
        </Fold>
      </Panel>
    </>
  );
}
