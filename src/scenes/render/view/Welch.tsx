/**
 * Two estimators, pixel by pixel (core/verify/welchMap; Jung, Hanika and Dachsbacher, JCGT 2020):
 * the page's estimator (its strategy, and its bias if one is chosen) and another strategy, unbiased,
 * each render the image K times in a worker (both strategies that sample the light: runs of the others
 * are too far from normal for the test); every pixel gets a Welch t-test of the two means, and
 * the images agree when no pixel's p falls below the Šidák-corrected level, so that an unbiased
 * pair raises a false alarm anywhere in the image with probability α only. The map shows each
 * pixel's −log₁₀ p in viridis, yellow at the corrected level and beyond.
 */
import { useMemo } from 'react';
import { Notice, Readout } from '../../../ui';
import { formatNumber } from '../../../core/format';
import type { Strategy } from '../../../core/render/directLight';
import { useWorkerJob } from '../../../workers';
import { makeRenderWorker } from '../jobs';
import { SPREAD_SPP, welchArgs } from '../jobArgs';
import type { RenderModel } from '../model';
import { LIGHT_SAMPLING, welchOther, type RenderParams } from '../params';
import { MapFigure } from './MapFigure';

/**
 * The fold. `vs` is the link's choice of the other strategy (`auto`: see {@link welchOther});
 * choosing another writes it into the link.
 */
export function Welch({
  m,
  vs,
  onVs,
}: {
  m: RenderModel;
  vs: RenderParams['vs'];
  onVs: (vs: RenderParams['vs']) => void;
}) {
  const other = welchOther(vs, m.trace.strategy);
  const testable = (LIGHT_SAMPLING as readonly Strategy[]).includes(m.trace.strategy);
  const args = useMemo(() => (testable ? welchArgs(m, other) : null), [m, other, testable]);
  const job = useWorkerJob(makeRenderWorker, 'welch', args, { delayMs: 100 });
  const r = args ? job.result : undefined;
  const res = args?.res ?? 0;
  const top = r ? -Math.log10(r.sidakAlpha) : 1;
  const score = useMemo(
    () => (r ? r.pValues.map((p) => (Number.isFinite(p) ? -Math.log10(Math.max(p, 1e-300)) : 0)) : null),
    [r],
  );
  const mine = `${m.trace.strategy}${m.trace.bias && m.trace.bias !== 'none' ? ` (bias ${m.trace.bias})` : ''}`;
  if (!args)
    return (
      <div data-testid="welch">
        <Notice kind="info" testId="welch-not-testable">
          {m.trace.strategy} sampling finds the small light only now and then: in runs of {SPREAD_SPP} samples
          most pixels see it never or once, so a run&apos;s pixel value is far from normal and Welch&apos;s
          test would raise false alarms. Choose a strategy that samples the light (area, solid-angle or MIS)
          to compare whole images, or test one pixel against its exact value with the pixel inspector&apos;s
          t-test, over as many samples as its <code>pn</code> asks.
        </Notice>
      </div>
    );
  return (
    <div data-testid="welch">
      <p>
        The page&apos;s estimator, {mine}, and another, unbiased, each render the same {args.res} × {args.res}{' '}
        image {args.runs} times at {args.spp} samples per pixel. Each pixel&apos;s two means are compared by
        Welch&apos;s t-test; the images agree when no pixel is below the level that keeps the chance of a
        false alarm anywhere in the image at α = {r ? r.alpha : 0.01} (Šidák&apos;s correction over the pixels
        tested). The test takes each run&apos;s pixel value to be nearly normal, which holds for the
        strategies that sample the light itself, offered here.
      </p>
      <label>
        Compare with{' '}
        <select
          value={other}
          onChange={(e) => onVs(e.currentTarget.value as RenderParams['vs'])}
          data-testid="welch-other"
        >
          {LIGHT_SAMPLING.map((s) => (
            <option key={s} value={s}>
              {s}
            </option>
          ))}
        </select>
      </label>
      <p role="status" data-testid="welch-status">
        {job.error
          ? `The comparison stopped: ${job.error.message}`
          : r
            ? `Done: ${args.runs} runs of each, ${r.tested} pixels tested.`
            : 'Rendering both estimators…'}
      </p>
      {r ? (
        <div className="render-spread">
          <MapFigure
            values={score ?? new Float64Array(0)}
            res={res}
            max={top}
            label={`Welch t-test of ${mine} against ${other}, pixel by pixel: −log10 p in viridis, from 0 (dark purple) to the corrected level ${formatNumber(top, 3)} and beyond (yellow); ${r.rejected} of ${r.tested} pixels below it`}
            caption={`−log₁₀ p, 0 … ${formatNumber(top, 3)}`}
          />
          <div className="readouts">
            <Readout id="welch-min-p" label="smallest p" value={r.minP} digits={3} />
            <Readout
              id="welch-sidak-alpha"
              label="corrected level"
              value={r.sidakAlpha}
              digits={3}
              note={`1 − (1\u00a0−\u00a0${r.alpha}) to the power 1/${r.tested}`}
            />
            <Readout id="welch-rejected" label="pixels below it" value={r.rejected} digits={6} />
          </div>
        </div>
      ) : null}
      {r ? (
        <p data-testid="welch-verdict" data-value={r.pass ? 'pass' : 'fail'}>
          {r.pass
            ? `No pixel differs: ${mine} and ${other} converge to the same image, as two unbiased estimators must.`
            : `${r.rejected} pixel${r.rejected === 1 ? '' : 's'} differ beyond chance: ${mine} and ${other} do not converge to the same image, so one of them is biased.`}
        </p>
      ) : null}
    </div>
  );
}
