/**
 * Q1's figure panel as the scene places it: the figure on the timeline, what it shows when there is
 * nothing to sample, and the followed stratum read from and written to the URL (`cell=i,j`), with a
 * notice when the link's value had to be changed.
 */
import { useCallback, useMemo, type ComponentProps, type ReactNode } from 'react';
import type { SceneProps } from '../../../kit/scene';
import { Notice, Panel } from '../../../ui';
import type { Lobe } from '../lobe';
import type { HemisphereSchema } from '../params';
import { cellFromParam, type Cell } from '../stratum';
import { Figure } from './Figure';

/** Why a typed density cannot be sampled: what went wrong, and the parser's or the check's message. */
export interface DensityProblem {
  what: string;
  message: string;
}

export function Q1Figure({
  lobe,
  densityProblem,
  children: settings,
  chi2,
  ...scene
}: SceneProps<HemisphereSchema> & {
  /** The density sampled (null when there is none: a bad typed density, or the paper's Jacobian). */
  lobe: Lobe | null;
  /** Why the typed density cannot be sampled (null when it can, or is not chosen). */
  densityProblem: DensityProblem | null;
  /** The settings, beside the figure (in the classroom stage's drawer), with the figure's options. */
  children: (more: ReactNode) => ReactNode;
  chi2: ComponentProps<typeof Figure>['chi2'];
}) {
  const { params, setParams } = scene;
  const inverted = params.jacobian === 'inverted';
  const cellKey = params.cell ? params.cell.join(',') : '';
  const { cell, problem } = useMemo(
    () => cellFromParam(cellKey ? cellKey.split(',').map(Number) : null),
    [cellKey],
  );
  const onPickCell = useCallback((c: Cell | null) => setParams({ cell: c ? [c.i, c.j] : null }), [setParams]);
  const body = (
    <>
      {problem ? (
        <Notice kind="warn" testId="cell-problem">
          {problem}.
        </Notice>
      ) : null}
      <Figure
        {...scene}
        lobe={lobe}
        problem={
          inverted ? (
            <Notice kind="warn" testId="figure-no-density">
              No directions to show: with the identity as printed on the paper, p(θ, φ) = k cot θ e
              <sup>φ</sup> is not a density (its θ-integral diverges; see (b)). Choose &ldquo;sin θ ·
              p(ω)&rdquo; under Jacobian to sample the exam&apos;s lobe.
            </Notice>
          ) : densityProblem ? (
            <Notice kind="error" testId="custom-error">
              {densityProblem.what}: {densityProblem.message}. Nothing is sampled until it is fixed.
            </Notice>
          ) : (
            <Notice kind="warn">No valid density to sample yet.</Notice>
          )
        }
        settings={settings}
        cell={cell}
        onPickCell={onPickCell}
        chi2={chi2}
        noLobeText={
          inverted
            ? 'with the identity as printed on the paper, p(θ, φ) = k cot θ eᵠ is not a density (its θ-integral diverges at the pole).'
            : densityProblem
              ? `the typed density cannot be used: ${densityProblem.message}.`
              : 'there is no valid density to sample yet.'
        }
      />
    </>
  );
  // on the classroom stage the figure stands on its own, first on the page
  return scene.mode.present ? body : <Panel className="hemi-figure-panel">{body}</Panel>;
}
