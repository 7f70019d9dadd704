/**
 * The two renderers side by side (`open=compare`): the page's settings rendered by the GPU's float32
 * shader and by the core's float64 renderer in a worker, each at COMPARE_SPP samples per pixel with
 * every pixel's standard error, and their difference as a map of z = (a − b)/√(se_a² + se_b²)
 * (core/render/rendererCompare, which explains the test). Also the price of float32: how far the
 * naive float32 sum of the GPU's samples is from its Kahan-compensated sum, beside the bound on the
 * CPU's float64 naive sum at the same count.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { keepTextParenthesesTogether, Notice, Readout } from '../../../ui';
import { formatNumber } from '../../../core/format';
import { buildScene } from '../../../core/render/scene';
import {
  COMPARE_ALPHA,
  compareRenderers,
  momentsFromSums,
  ROUNDING_ULPS,
  type PixelMoments,
} from '../../../core/render/rendererCompare';
import { F64_UNIT_ROUNDOFF, naiveSumBound, naiveSumError } from '../../../core/render/f32Sum';
import { useWorkerJob } from '../../../workers';
import { makeRenderWorker } from '../jobs';
import { COMPARE_SPP, momentsArgs } from '../jobArgs';
import type { RenderModel } from '../model';
import { copyMeans } from '../pixels';
import type { GpuSupport } from '../gpu/gpuRenderer';
import type { FromGpuWorker, ToGpuWorker } from '../gpu/gpuProtocol';
import { makeGpuWorker } from '../jobs';
import { sceneUniforms } from '../gpu/sceneUniforms';
import { renderKey } from '../useProgressiveRender';
import { CanvasFigure, MapFigure } from './MapFigure';

/** The GPU side: the same settings, COMPARE_SPP frames in a worker of its own, read back once. */
interface GpuSide {
  moments: PixelMoments;
  /** Mean over the image of |naive − Kahan| / Kahan. */
  naiveError: number;
}

function useGpuMoments(m: RenderModel, enabled: boolean): { result: GpuSide | null; error: string | null } {
  const key = renderKey(m);
  const res = m.res;
  const [state, setState] = useState<{ key: string; result: GpuSide | null; error: string | null }>({
    key: '',
    result: null,
    error: null,
  });
  const [worker, setWorker] = useState<Worker | null>(null);
  const latest = useRef({ m, key });
  latest.current = { m, key };
  const image = useRef({ id: 0, key: '' });

  // one worker for the fold at this size: a new image reloads it, without compiling the shader again
  useEffect(() => {
    if (!enabled) return;
    const w = makeGpuWorker();
    w.onmessage = (e: MessageEvent<FromGpuWorker>) => {
      const msg = e.data;
      if (msg.kind === 'failed') setState({ key: latest.current.key, result: null, error: msg.why });
      else if (msg.kind === 'ready') setWorker(w);
      else if (msg.kind === 'sums' && msg.id === image.current.id && msg.count === COMPARE_SPP) {
        const n = msg.rgba.length / 4;
        const sum = new Float64Array(n);
        const sumSq = new Float64Array(n);
        for (let k = 0; k < n; k++) {
          sum[k] = msg.rgba[4 * k + 1];
          sumSq[k] = msg.rgba[4 * k + 3];
        }
        const moments = momentsFromSums(sum, sumSq, COMPARE_SPP);
        setState({
          key: image.current.key,
          result: { moments, naiveError: naiveSumError(msg.rgba) },
          error: null,
        });
      }
    };
    w.postMessage({ kind: 'init', res, canvas: null } satisfies ToGpuWorker);
    return () => {
      w.terminate();
      setWorker(null);
    };
  }, [enabled, res]);

  useEffect(() => {
    if (!worker) return;
    const model = latest.current.m;
    image.current = { id: image.current.id + 1, key };
    const uniforms = sceneUniforms(buildScene(model.spec), model.view, model.res, model.trace);
    const send = (msg: ToGpuWorker) => worker.postMessage(msg);
    send({ kind: 'load', id: image.current.id, uniforms, seed: model.seed });
    send({ kind: 'run', target: COMPARE_SPP });
  }, [worker, key]);

  return state.key === key ? state : { result: null, error: null };
}

function GreyFigure({
  means,
  res,
  label,
  caption,
}: {
  means: ArrayLike<number>;
  res: number;
  label: string;
  caption: string;
}) {
  const paint = useCallback((rgba: Uint8ClampedArray) => copyMeans(means, rgba), [means]);
  return <CanvasFigure res={res} paint={paint} label={label} caption={caption} />;
}

export default function Compare({ m, support }: { m: RenderModel; support: GpuSupport }) {
  const gpuOk = support.webgl2 && support.offscreen;
  const cpu = useWorkerJob(makeRenderWorker, 'moments', momentsArgs(m), { delayMs: 100 });
  const gpu = useGpuMoments(m, gpuOk);
  const cmp = useMemo(
    () => (gpu.result && cpu.result ? compareRenderers(gpu.result.moments, cpu.result) : null),
    [gpu.result, cpu.result],
  );
  const absZ = useMemo(() => (cmp ? cmp.z.map((z) => (Number.isFinite(z) ? Math.abs(z) : 0)) : null), [cmp]);
  // the pixel the inspector looks at, else the image's centre
  const [pi, pj] = m.px ?? [m.res >> 1, m.res >> 1];
  const pk = pj * m.res + pi;
  if (!gpuOk)
    return (
      <Notice kind="info" testId="compare-unavailable">
        This browser cannot run the GPU renderer (it needs WebGL2 with EXT_color_buffer_float), so there is no
        float32 image to compare with the CPU&apos;s.
      </Notice>
    );
  const at = (p: PixelMoments | null | undefined) => (p ? p.mean[pk] : null);
  return (
    <div data-testid="compare">
      <p>
        Both renderers draw the page&apos;s image, {m.res} × {m.res}, at {COMPARE_SPP} samples per pixel from
        different random streams, and keep each pixel&apos;s sum of squares, so each pixel is a mean a with
        its standard error se. Where the two compute the same estimator, z ={' '}
        {keepTextParenthesesTogether('(a_GPU − a_CPU) / √(se_GPU² + se_CPU²)')} is centred on 0 at every pixel
        (float32 rounding counts as {ROUNDING_ULPS} ulps of noise). The test: T = Σz / √(Σz²) over the pixels
        with noise, which is no wider than a standard normal when each z is symmetric about 0, as it is when
        the two sides could be swapped, however far from normal the pixels are (Efron 1969); T² against χ²
        with one degree of freedom gives p. A renderer too bright or too dark over the image fails at α ={' '}
        {COMPARE_ALPHA}; pixels with no noise on either side (the white furnace under cosine sampling) must
        agree to float32 rounding.
      </p>
      <p role="status" data-testid="compare-status">
        {gpu.error || cpu.error
          ? `The comparison stopped: ${gpu.error ?? cpu.error?.message}`
          : cmp
            ? `Done: ${COMPARE_SPP} samples per pixel on each renderer, ${cmp.noisy} pixels with noise, ${cmp.quiet} without.`
            : 'Rendering on both…'}
      </p>
      {cmp && gpu.result && cpu.result ? (
        <>
          <div className="render-spread">
            <GreyFigure
              means={gpu.result.moments.mean}
              res={m.res}
              label={`The GPU's float32 image at ${COMPARE_SPP} samples per pixel`}
              caption="GPU, float32"
            />
            <GreyFigure
              means={cpu.result.mean}
              res={m.res}
              label={`The CPU's float64 image at ${COMPARE_SPP} samples per pixel`}
              caption="CPU, float64"
            />
            <MapFigure
              values={absZ ?? new Float64Array(0)}
              res={m.res}
              max={4}
              label={`|z| of the two images pixel by pixel in viridis, from 0 (dark purple) to 4 and beyond (yellow); the largest ${formatNumber(cmp.maxAbsZ, 3)}`}
              caption="|z|, 0 … 4"
            />
          </div>
          <div className="readouts">
            <Readout
              id="compare-chi2-p"
              label="p of T² (χ², 1 degree of freedom)"
              value={cmp.p}
              digits={3}
              note={`T = ${formatNumber(cmp.t, 3)} over ${cmp.noisy} pixels`}
            />
            <Readout id="compare-max-abs-z" label="largest |z|" value={cmp.maxAbsZ} digits={3} />
            <Readout
              id="compare-f32-naive-error"
              label="float32: mean |naive − Kahan| / Kahan"
              value={gpu.result.naiveError}
              digits={3}
              note={`the GPU's sums of ${COMPARE_SPP} samples`}
            />
            <Readout
              id="compare-f64-naive-bound"
              label="float64: bound on the naive sum's relative error"
              value={naiveSumBound(COMPARE_SPP, F64_UNIT_ROUNDOFF)}
              digits={3}
              note={`Higham’s γ for n = ${COMPARE_SPP} terms, u = 2⁻⁵³: the CPU’s sums`}
            />
            <Readout
              id="compare-pixel-gpu"
              label={`pixel ${pi},${pj} on the GPU`}
              value={at(gpu.result.moments)}
            />
            <Readout id="compare-pixel-cpu" label={`pixel ${pi},${pj} on the CPU`} value={at(cpu.result)} />
            <Readout id="compare-pixel-z" label={`z at pixel ${pi},${pj}`} value={cmp.z[pk]} digits={3} />
          </div>
          <p data-testid="compare-verdict" data-value={cmp.pass ? 'pass' : 'fail'}>
            {cmp.pass
              ? `The GPU's float32 image agrees with the CPU's float64 one within its noise (p = ${formatNumber(cmp.p, 3)} ≥ ${COMPARE_ALPHA}${cmp.quiet ? `; ${cmp.quiet} noiseless pixels equal to float32 rounding` : ''}).`
              : cmp.quietMismatches > 0
                ? `${cmp.quietMismatches} pixels without noise differ by more than float32 rounding: the renderers do not compute the same image.`
                : `The images differ beyond their noise (p = ${formatNumber(cmp.p, 3)} < ${COMPARE_ALPHA}): one renderer is brighter than the other.`}
          </p>
        </>
      ) : null}
    </div>
  );
}
