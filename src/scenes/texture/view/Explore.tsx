/**
 * "Explore further", beyond the exam: the whole texture under both filters with the bilinear
 * creases, and what the spherical mapping does at its seam and poles.
 */
import { useMemo, useRef, type ComponentProps } from 'react';
import { keepTextParenthesesTogether, Panel, useAnimFrame, useStillT } from '../../../ui';
import type { LookupOptions } from '../../../core/texture';
import { creases } from '../creases';
import type { SphereModel } from '../sphere';
import type { AnimContext } from './anim';
import { Reconstruction } from './Reconstruction';
import { SphereBilinear } from './WorkedSteps';
import './Explore.css';

type Range = { min: number; max: number };

/** The whole texture under both filters, with the bilinear creases (computed when this part mounts). */
export function ReconstructionPanel({
  ctx,
  range,
  isExam,
  showChecker,
}: {
  ctx: AnimContext;
  range: Range;
  isExam: boolean;
  /** Offered when the grid has no crease (null: the checkerboard is already shown). */
  showChecker: (() => void) | null;
}) {
  const { grid, opts } = ctx;
  const crease = useMemo(() => creases(grid, opts), [grid, opts]);
  return (
    <Panel title="The whole texture, reconstructed">
      <AnimReconstruction ctx={ctx} range={range} creases={crease.list} />
      <p className="tx-small" data-testid="crease-caption">
        Both images show [0, 1]² {opts.vflip ? '(in the flipped frame v′) ' : ''}magnified; the cross is the
        query. Nearest copies the closest value, so it is blocky. Bilinear is continuous, and linear along u
        and along v inside each cell, so its slope can change only across node lines — and only where the
        values do not continue linearly across the line (a non-zero second difference).{' '}
        {creaseSentence(crease.creased, crease.lines, isExam)}
        {crease.creased === 0 && showChecker ? (
          <>
            {' '}
            <button type="button" onClick={showChecker} data-testid="show-checker">
              Show the checkerboard
            </button>
          </>
        ) : null}
      </p>
    </Panel>
  );
}

function creaseSentence(creased: number, lines: number, isExam: boolean): string {
  if (lines === 0) return 'This grid has no interior node lines.';
  if (creased === 0)
    return (
      `On this grid none of the ${lines} interior node lines is a crease: the values change linearly ` +
      `across every one${isExam ? ' (the exam’s grid is the linear function 21 + 4u − 20v)' : ''}, ` +
      'so bilinear reproduces a smooth (here planar) surface.'
    );
  if (creased === lines)
    return `On this grid all ${lines} of the ${lines} interior node lines are creases (dashed on the bilinear image).`;
  return (
    `On this grid ${creased} of the ${lines} interior node lines ` +
    `${creased === 1 ? 'is a crease' : 'are creases'} (dashed on the bilinear image); ` +
    'across the others the values continue linearly and the surface is smooth.'
  );
}

/** The reconstructions with the query's cross at position t (the images are memoized inside). */
function AnimReconstruction({
  ctx,
  range,
  creases,
}: {
  ctx: AnimContext;
  range: Range;
  creases: ComponentProps<typeof Reconstruction>['creases'];
}) {
  const t = useStillT(ctx.store);
  const { dq } = ctx.frame(t);
  const draw = useRef<((qu: number, qv: number) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => {
    const d = ctx.frame(x).dq;
    draw.current?.(d.bil.u, d.bil.v);
  });
  return (
    <Reconstruction
      grid={ctx.grid}
      opts={ctx.opts}
      range={range}
      qu={dq.bil.u}
      qv={dq.bil.v}
      creases={creases}
      drawRef={draw}
    />
  );
}

/** Where u jumps (the seam) and where it is undefined (the poles), with the sphere point's steps. */
export function SeamPanel({
  sphere,
  opts,
  normalize,
}: {
  sphere: SphereModel;
  opts: LookupOptions;
  normalize: boolean;
}) {
  return (
    <Panel title="The sphere’s seam and poles">
      <p className="tx-small">
        <strong>Seam.</strong> atan2 returns angles in (−π, π]; adding 2π to the negative ones puts φ in [0,
        2π), so u runs from 0 at +x all the way round to just below 1. The meridian φ = 0 (red) is where u
        jumps from 1 back to 0: u = 1 is never produced, so the seam belongs to u = 0. Unless the texture’s
        left and right columns match (or the lookup repeats with texel centres), the picture jumps there.
      </p>
      <p className="tx-small">
        <strong>Poles.</strong> On the z axis {keepTextParenthesesTogether('(x = y = 0)')} every φ names the
        same point, so u is undefined; we define u = 0. θ is computed as{' '}
        <span className="tx-formula">{keepTextParenthesesTogether('atan2(√(x² + y²), z)')}</span>, which
        equals arccos(z/r) but keeps full precision near the poles.
      </p>
      {sphere.ok ? (
        <details className="tx-details">
          <summary>
            Bilinear steps for the sphere point ({normalize ? 'normalized' : 'not normalized'})
          </summary>
          <SphereBilinear q={sphere.chosen} opts={opts} />
        </details>
      ) : null}
    </Panel>
  );
}
