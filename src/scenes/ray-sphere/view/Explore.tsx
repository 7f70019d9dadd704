/**
 * "Explore further", beyond the exam, each part folded (ui/Fold: nothing in it is computed or
 * loaded until it is opened, and the link's `open=` remembers it): the same ray in 3D, the
 * precision tables (textbook, robust, double-double reference; float64 and float32), the
 * distant-sphere images, the error against distance and the GPU panel. With `ask=1` the 3D view
 * and the tables, which show the roots, wait for Reveal.
 */
import { memo, useMemo } from 'react';
import { ExploreFurther, Revealed } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import type { RaySphereModel } from '../model';
import type { Vec3 } from '../../../core/vec3';
import { LiveDescribed } from './Described';
import { describe3D } from './describe';
import { LiveView3D, type LiveProps } from './Live';
import { DistantImages, ErrorVsDistance, PrecisionTable } from './Precision';
import { PrecisionExplainer } from './PrecisionExplainer';
import { PrecisionCompare } from './Float32Panel';
import { GpuSection } from './gpu';

const PrecisionTableMemo = memo(PrecisionTable);
const PrecisionCompareMemo = memo(PrecisionCompare);

export interface RaySphereExploreProps extends LiveProps {
  /** The throttled, deferred model (the tables follow it, not every frame). */
  slow: RaySphereModel;
  /** The ends of the sweep, kept in the 3D view. */
  ends: readonly Vec3[];
  present: boolean;
  dark: boolean;
  ask: boolean;
}

/** The error plot with the current ray's Δ errors marked, and what it shows. */
const ErrorPanel = memo(function ErrorPanel({ slow }: { slow: RaySphereModel }) {
  const here = useMemo(
    () => ({
      naive: slow.rows.find((x) => x.method === 'naive')?.errDisc ?? null,
      stable: slow.rows.find((x) => x.method === 'stable')?.errDisc ?? null,
    }),
    [slow],
  );
  return (
    <>
      <ErrorVsDistance current={Number(slow.distanceRatio.toPrecision(3))} here={here} />
      <p className="rs-small">
        Median over 12 rays per distance, aimed 0.1 r … 0.95 r off the centre; the crosses are the current
        ray’s Δ errors. The textbook Δ loses digits like u·(D/r)² (u&nbsp;=&nbsp;2⁻⁵³): by D ≈ 10⁸ r nothing
        is left. The robust Δ grows only like u·(D/r), and its roots stay accurate to the last bits. In
        float32 (orange and green squares; u₃₂ = 2⁻²⁴) the same happens 10⁴ times sooner: the textbook Δ is
        noise by D ≈ 1/√u₃₂ ≈ 4·10³ r, a distance every game scene has.
      </p>
    </>
  );
});

export function RaySphereExplore({ tl, modelAt, slow, ends, present, dark, ask }: RaySphereExploreProps) {
  const live = { tl, modelAt };
  return (
    <ExploreFurther intro="Beyond the exam: the same ray in 3D, and what floating point does to the textbook formula when the sphere is far away or the ray grazes it.">
      {/* one child: the closed folds are a few lines, mounted together */}
      <>
        <Fold name="view3d" summary="The same ray and sphere in 3D, to orbit and zoom">
          <Revealed ask={ask} what="the ray and its hit in 3D" minHeight={120}>
            <LiveDescribed
              {...live}
              label="3D view of the ray and the sphere"
              describe={describe3D}
              quiet
              testId="view3d-figure"
            >
              <LiveView3D {...live} height={present ? 420 : 320} dark={dark} fitExtra={ends} />
            </LiveDescribed>
          </Revealed>
        </Fold>
        <Fold
          name="precision"
          summary="Precision: the roots by the textbook and robust forms against a double-double reference, in float64 and float32"
        >
          <Revealed ask={ask} what="the roots by each method, against the reference">
            <PrecisionTableMemo model={slow} />
            <PrecisionCompareMemo model={slow} />
          </Revealed>
          <PrecisionExplainer />
        </Fold>
        <Fold
          name="distant"
          summary="A distant sphere, one ray per pixel: where the textbook form loses hits"
        >
          <DistantImages />
        </Fold>
        <Fold name="error" summary="Error against distance: how fast each form loses digits">
          <ErrorPanel slow={slow} />
        </Fold>
        <GpuSection />
      </>
    </ExploreFurther>
  );
}
