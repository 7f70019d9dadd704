/**
 * The error without a reference (core/render/expectedError; Celarek et al., EGSR 2019): the chosen
 * strategy renders the image K times independently in a worker; the per-pixel standard deviation
 * over the runs is drawn in viridis, and the MSE its spread predicts is set beside the MSE the
 * runs actually made against the exact reference. They agree for an unbiased estimator; a biased
 * one (`bias=`) makes more error than its spread shows.
 */
import { useMemo } from 'react';
import { Notice, Readout } from '../../../ui';
import { formatNumber } from '../../../core/format';
import { useWorkerJob } from '../../../workers';
import { makeRenderWorker } from '../jobs';
import { spreadArgs } from '../jobArgs';
import type { RenderModel } from '../model';
import { MapFigure } from './MapFigure';

export function Spread({ m }: { m: RenderModel }) {
  const args = useMemo(() => spreadArgs(m), [m]);
  const job = useWorkerJob(makeRenderWorker, 'spread', args, { delayMs: 100 });
  const r = job.result;
  const max = useMemo(() => {
    if (!r) return 0;
    let x = 0;
    for (const v of r.sd) if (v > x) x = v;
    return x;
  }, [r]);
  const ratio = r ? r.measuredMse / r.expectedMse : NaN;
  return (
    <div data-testid="spread">
      <p>
        The strategy renders the same {args.res} × {args.res} image {args.runs} times at {args.spp} samples
        per pixel, each run from its own seed. How much the runs differ, pixel by pixel, is the noise one run
        carries, measured without any reference; squared and averaged, it is the error one run is expected to
        make if the estimator is unbiased. Beside it, the error the runs made against the exact reference.
      </p>
      <p role="status" data-testid="spread-status">
        {job.error
          ? `The runs stopped: ${job.error.message}`
          : r
            ? `Done: ${args.runs} runs of ${args.spp} samples per pixel.`
            : 'Rendering the runs…'}
      </p>
      {r ? (
        <div className="render-spread">
          <MapFigure
            values={r.sd}
            res={args.res}
            max={max}
            label={`Per-pixel standard deviation over ${args.runs} runs, viridis from 0 (dark purple) to ${formatNumber(max, 3)} (yellow)`}
            caption={`standard deviation, 0 … ${formatNumber(max, 3)}`}
          />
          <div className="readouts">
            <Readout
              id="spread-expected-mse"
              label="MSE the spread predicts"
              value={r.expectedMse}
              digits={4}
              note={`mean s² over ${r.pixels} pixels with an exact reference`}
            />
            <Readout
              id="spread-measured-mse"
              label="MSE against the reference"
              value={r.measuredMse}
              digits={4}
              note="mean (x − ref)² over the same pixels and runs"
            />
          </div>
        </div>
      ) : null}
      {r && r.pixels === 0 ? (
        <Notice kind="info">
          No pixel of this view has an exact reference: only the spread can be measured.
        </Notice>
      ) : r ? (
        <p data-testid="spread-verdict">
          Their ratio is {formatNumber(ratio, 3)}.{' '}
          {ratio > 1.5
            ? 'The runs made more error than their spread predicts: the estimator is biased (its bias² adds to the variance).'
            : 'The spread predicts the error made, as it should for an unbiased estimator (the small remainder is the noise of the estimate and the pixel footprint of the reference).'}
        </p>
      ) : null}
    </div>
  );
}
