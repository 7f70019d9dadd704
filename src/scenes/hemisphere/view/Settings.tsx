/**
 * The settings beside the figure: the sampling density (Phong exponent, typed density), the
 * Jacobian, the point set, N and the seed, and the state of the statistics run.
 */
import type { SceneProps } from '../../../kit/scene';
import { ExprField, NumberField, Select, Slider } from '../../../ui';
import type { WorkerJob } from '../../../workers';
import { MAX_N, POINT_SETS, type HemisphereParams, type HemisphereSchema, type LobeId } from '../params';

const LOBE_OPTIONS: { value: LobeId; label: string }[] = [
  { value: 'exam', label: 'exam: k cos θ eᵠ' },
  { value: 'uniform', label: 'uniform' },
  { value: 'cosine', label: 'cosine-weighted' },
  { value: 'phong', label: 'Phong cosⁿθ' },
  { value: 'custom', label: 'typed density p(θ, φ)' },
];
const JACOBIAN_OPTIONS: { value: HemisphereParams['jacobian']; label: string }[] = [
  { value: 'correct', label: 'sin θ · p(ω) (correct)' },
  { value: 'inverted', label: 'p(ω) / sin θ (as on the paper)' },
];
const POINT_OPTIONS = POINT_SETS.map((p) => ({
  value: p,
  label: p === 'halton' ? 'Halton' : p === 'sobol' ? 'Sobol (Owen-scrambled)' : p,
}));

export function Settings({
  params,
  setParams,
  pdfError,
  stats,
}: {
  params: HemisphereParams;
  setParams: SceneProps<HemisphereSchema>['setParams'];
  /** Why the typed density cannot be used (null when it can, or is not chosen). */
  pdfError: string | null;
  stats: Pick<WorkerJob<unknown, unknown>, 'result' | 'running' | 'waiting' | 'progress'>;
}) {
  return (
    <div className="hemi-controls">
      <Select
        label="Sampling density p(ω)"
        value={params.lobe}
        options={LOBE_OPTIONS}
        onChange={(v) => setParams({ lobe: v })}
        testId="lobe"
      />
      {params.lobe === 'phong' ? (
        <Slider
          label="Phong exponent n"
          value={params.exponent}
          min={0}
          max={10000}
          step={1}
          onChange={(v) => setParams({ exponent: v })}
        />
      ) : null}
      {params.lobe === 'custom' ? (
        <ExprField
          label="p(θ, φ) per steradian (need not be normalized)"
          value={params.pdf}
          onCommit={(s) => setParams({ pdf: s })}
          error={pdfError}
          hint={
            <>
              mathjs syntax in theta, phi, e.g. <code>cos(theta)^2 * (2 + cos(phi))</code>
            </>
          }
          testId="pdf-input"
        />
      ) : null}
      <Select
        label="Jacobian p(θ, φ) = …"
        value={params.jacobian}
        options={JACOBIAN_OPTIONS}
        onChange={(v) => setParams({ jacobian: v })}
        testId="jacobian"
      />
      <Select
        label="Point set (ξ₁, ξ₂)"
        value={params.points}
        options={POINT_OPTIONS}
        onChange={(v) => setParams({ points: v })}
        testId="points"
      />
      <Slider
        label="Samples N"
        value={params.n}
        min={1}
        max={MAX_N}
        log
        step={1}
        onChange={(v) => setParams({ n: Math.round(v) })}
        testId="n"
      />
      <NumberField
        label="Seed"
        value={params.seed}
        min={0}
        max={4294967295}
        step={1}
        onChange={(v) => setParams({ seed: Math.round(v) })}
      />
      <p
        className="small stats-status"
        data-testid="stats-status"
        data-state={stats.result ? 'ready' : stats.running ? 'running' : stats.waiting ? 'waiting' : 'idle'}
      >
        {stats.running
          ? `computing in a worker… ${Math.round(stats.progress * 100)} %`
          : stats.result
            ? 'statistics up to date'
            : stats.waiting
              ? 'statistics start once the page has loaded…'
              : ''}
      </p>
    </div>
  );
}
