/**
 * The settings beside the figure: the sampling density (Phong exponent, typed density), the
 * Jacobian, the point set, N and the seed, and the state of the statistics run. On the page only N
 * and the run's state show; the rest (the exam's figure needs none of it) is folded under "More
 * settings" with the figure's own options (`more`). On the classroom stage's drawer all of it shows.
 */
import type { ReactNode } from 'react';
import type { SceneProps } from '../../../kit/scene';
import { ExprField } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { bindControls } from '../../../ui/paramControls';
import type { WorkerJob } from '../../../workers';
import {
  LOBES,
  POINT_SETS,
  schema,
  type HemisphereParams,
  type HemisphereSchema,
  type LobeId,
} from '../params';

/** Each lobe's name in the select (a lobe added to LOBES must be named here too). */
const LOBE_LABEL: Record<LobeId, string> = {
  exam: 'exam: k cos θ eᵠ',
  uniform: 'uniform',
  cosine: 'cosine-weighted',
  phong: 'Phong cosⁿθ',
  custom: 'typed density p(θ, φ)',
};
const LOBE_OPTIONS = LOBES.map((value) => ({ value, label: LOBE_LABEL[value] }));
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
  folded,
  more = null,
}: {
  params: HemisphereParams;
  setParams: SceneProps<HemisphereSchema>['setParams'];
  /** Why the typed density cannot be used (null when it can, or is not chosen). */
  pdfError: string | null;
  stats: Pick<WorkerJob<unknown, unknown>, 'result' | 'running' | 'waiting' | 'progress'>;
  /** All but N under "More settings" (the page), or every control in a column (the stage's drawer). */
  folded: boolean;
  /** The figure's own options, folded with the settings. */
  more?: ReactNode;
}) {
  const c = bindControls(schema, params, setParams);
  const density = (
    <>
      {c.select('lobe', 'Sampling density p(ω)', LOBE_OPTIONS)}
      {params.lobe === 'phong' ? c.slider('exponent', 'Phong exponent n', { step: 1 }) : null}
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
      {c.select('jacobian', 'Jacobian p(θ, φ) = …', JACOBIAN_OPTIONS)}
      {c.select('points', 'Point set (ξ₁, ξ₂)', POINT_OPTIONS)}
    </>
  );
  const samples = c.slider('n', 'Samples N', { log: true });
  const seed = c.number('seed', 'Seed');
  return (
    <div className="hemi-controls">
      {folded ? (
        <>
          {samples}
          <Fold
            name="settings"
            className="hemi-more"
            summary="More settings: density, Jacobian, point set, seed, animation"
          >
            {density}
            {seed}
            {more}
          </Fold>
        </>
      ) : (
        <>
          {density}
          {samples}
          {seed}
          {more}
        </>
      )}
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
