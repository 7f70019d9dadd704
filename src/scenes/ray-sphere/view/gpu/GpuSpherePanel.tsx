/**
 * "What the GPU sees": the sphere rendered by a WebGL2 fragment shader in the GPU's float32, one
 * ray per pixel, with the textbook and the robust test, beside the JavaScript float32 emulation
 * and a float64 reference of the same rays. Loaded only when its panel is opened (a lazy chunk).
 */
import { useEffect, useMemo, useRef } from 'react';
import { Notice, Readout, type ReadoutProps } from '../../../../ui';
import { useLogDistance } from '../useLogDistance';
import { IMAGE_BG, IMAGE_FG, IMAGE_HOLE, type Rgb } from '../imageColours';
import {
  countHitMismatch,
  countUlpMismatch,
  renderSphereF32,
  renderSphereReference,
  sphereImageSetup,
  ulpErrors,
  ulpF32,
} from '../../../../core/geometry';
import { getGl2, renderSphereGpu, type GpuSphereImage } from './sphereShader';
import { SelfIntersectionF32 } from './SelfIntersectionF32';
import { ImageMeasure } from '../../../../ui/ImageMeasure';
import type { ImageSet } from '../../../../ui/imageMeasure';
import { relMseRgba8 } from '../../../../core/image/relMse';

/** Image size: one ray per pixel, as the distant-sphere images above. */
const W = 96;
/** Shader and emulation agree when their t differ by at most this many float32 ulps. */
export const MISMATCH_ULPS = 2;

const PRESETS = [
  { exp: 1, label: 'D/r = 10' },
  { exp: 2, label: '10²' },
  { exp: 3, label: '10³' },
  { exp: 4, label: '10⁴: textbook holes', id: 'far' },
];

const INVENTED: Rgb = [120, 200, 255];

/** A false-colour ramp for errors in ulps on a log scale: 0 dark blue … ≥ 2¹⁰ ulps red. */
function ulpColour(u: number): Rgb {
  if (u === 0) return [20, 40, 110];
  const x = Math.min(1, Math.log2(1 + u) / 10);
  const stops: Rgb[] = [
    [20, 40, 110],
    [30, 140, 200],
    [60, 190, 90],
    [240, 220, 40],
    [240, 130, 30],
    [210, 30, 30],
  ];
  const f = x * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(f));
  const w = f - i;
  return [0, 1, 2].map((k) => stops[i][k] + w * (stops[i + 1][k] - stops[i][k])) as Rgb;
}

/** The W × W RGBA8 pixels of a per-pixel colour (what the canvases show and the measurement reads). */
function pixelsOf(colour: (i: number) => Rgb): Uint8ClampedArray<ArrayBuffer> {
  const d = new Uint8ClampedArray(4 * W * W);
  for (let i = 0; i < W * W; i++) {
    const c = colour(i);
    d[4 * i] = c[0];
    d[4 * i + 1] = c[1];
    d[4 * i + 2] = c[2];
    d[4 * i + 3] = 255;
  }
  return d;
}

function paint(cv: HTMLCanvasElement | null, pixels: Uint8ClampedArray<ArrayBuffer>): void {
  cv?.getContext('2d')?.putImageData(new ImageData(pixels, W, W), 0, 0);
}

/** Hit/miss with depth shading; holes (reference hits, this misses) pink, invented hits light blue. */
function hitColour(t: ArrayLike<number>, ref: ArrayLike<number> | null, tMin: number): (i: number) => Rgb {
  return (i) => {
    const hit = t[i] !== Infinity;
    const refHit = ref ? ref[i] !== Infinity : hit;
    if (!hit) return refHit ? IMAGE_HOLE : IMAGE_BG;
    if (!refHit) return INVENTED;
    const cos = Math.min(1, Math.max(0, 1 - (t[i] - tMin)));
    const s = 0.3 + 0.7 * cos;
    return [IMAGE_FG[0] * s, IMAGE_FG[1] * s, IMAGE_FG[2] * s];
  };
}

interface Result {
  ref: Float64Array;
  emu: { naive: Float32Array; stable: Float32Array };
  gpu: GpuSphereImage | null;
  gpuError: string | null;
  errNaive: Float32Array;
  errStable: Float32Array;
  wrongNaive: number;
  wrongStable: number;
  emuWrongNaive: number;
  emuWrongStable: number;
  mismatchNaive: number;
  mismatchStable: number;
  maxUlpStable: number;
  tMin: number;
}

export function GpuSpherePanel() {
  const { exp, setExp, dist, slider } = useLogDistance(3, {
    label: 'Distance, log₁₀(D\u00a0/\u00a0r)',
    max: 6,
    testId: 'gpu-exp',
  });
  const glRef = useRef<WebGL2RenderingContext | { ok: false; message: string } | null>(null);
  const res = useMemo<Result>(() => {
    const s = sphereImageSetup(dist, W, W);
    const ref = renderSphereReference(s);
    const emu = renderSphereF32(s);
    if (!glRef.current) glRef.current = getGl2();
    const gl = glRef.current;
    let gpu: GpuSphereImage | null = null;
    let gpuError: string | null = null;
    if ('ok' in gl) gpuError = gl.message;
    else if (gl.isContextLost())
      gpuError = 'The WebGL2 context was lost (the GPU was reset); reload the page.';
    else {
      const g = renderSphereGpu(gl, W, W, s.dirs, s.centre, s.r, () => performance.now());
      if ('ok' in g) gpuError = g.message;
      else gpu = g;
    }
    const shown = gpu ?? { ...emu, renderer: '', ms: 0 };
    const errNaive = ulpErrors(shown.naive, ref, new Float32Array(W * W));
    const errStable = ulpErrors(shown.stable, ref, new Float32Array(W * W));
    let maxUlpStable = 0;
    for (let i = 0; i < W * W; i++)
      if (Number.isFinite(errStable[i])) maxUlpStable = Math.max(maxUlpStable, errStable[i]);
    let tMin = Infinity;
    for (let i = 0; i < W * W; i++) if (ref[i] < tMin) tMin = ref[i];
    return {
      ref,
      emu,
      gpu,
      gpuError,
      errNaive,
      errStable,
      wrongNaive: countHitMismatch(shown.naive, ref),
      wrongStable: countHitMismatch(shown.stable, ref),
      emuWrongNaive: countHitMismatch(emu.naive, ref),
      emuWrongStable: countHitMismatch(emu.stable, ref),
      mismatchNaive: gpu ? countUlpMismatch(gpu.naive, emu.naive, MISMATCH_ULPS) : 0,
      mismatchStable: gpu ? countUlpMismatch(gpu.stable, emu.stable, MISMATCH_ULPS) : 0,
      maxUlpStable,
      tMin,
    };
  }, [dist]);

  const cRef = useRef<HTMLCanvasElement>(null);
  const cNaive = useRef<HTMLCanvasElement>(null);
  const cStable = useRef<HTMLCanvasElement>(null);
  const cErrN = useRef<HTMLCanvasElement>(null);
  const cErrS = useRef<HTMLCanvasElement>(null);
  const cMis = useRef<HTMLCanvasElement>(null);
  // the float64 reference and the two float32 images as pixels: painted, and measured by FLIP
  const shownPx = useMemo(() => {
    const shown = res.gpu ?? res.emu;
    return {
      ref: pixelsOf(hitColour(res.ref, null, res.tMin)),
      naive: pixelsOf(hitColour(shown.naive, res.ref, res.tMin)),
      stable: pixelsOf(hitColour(shown.stable, res.ref, res.tMin)),
    };
  }, [res]);
  const measured = useMemo<ImageSet>(() => {
    const where = res.gpu ? 'GPU' : 'emulated';
    const image = (id: 'naive' | 'stable', label: string) => ({
      id,
      label,
      pixels: shownPx[id],
      relMse: relMseRgba8(shownPx[id], shownPx.ref),
    });
    return {
      width: W,
      height: W,
      reference: shownPx.ref,
      referenceLabel: 'float64',
      images: [image('naive', `textbook, ${where} float32`), image('stable', `robust, ${where} float32`)],
      relMseOf: 'the linear RGB of the shown pixels',
      fileStem: `ray-sphere-D${dist}`,
    };
  }, [res, shownPx, dist]);
  useEffect(() => {
    paint(cRef.current, shownPx.ref);
    paint(cNaive.current, shownPx.naive);
    paint(cStable.current, shownPx.stable);
    const errCol = (e: Float32Array) => (i: number) =>
      res.ref[i] === Infinity && e[i] === 0 ? IMAGE_BG : e[i] === Infinity ? IMAGE_HOLE : ulpColour(e[i]);
    paint(cErrN.current, pixelsOf(errCol(res.errNaive)));
    paint(cErrS.current, pixelsOf(errCol(res.errStable)));
    const g = res.gpu;
    paint(
      cMis.current,
      pixelsOf((i) => {
        if (!g) return IMAGE_BG;
        const bad = (x: number, y: number) =>
          x !== y &&
          (x === Infinity ||
            y === Infinity ||
            Math.abs(x - y) > MISMATCH_ULPS * Math.max(2 ** -149, ulpF32(y)));
        const n = bad(g.naive[i], res.emu.naive[i]);
        const s = bad(g.stable[i], res.emu.stable[i]);
        return n && s
          ? [255, 255, 255]
          : n
            ? [240, 130, 30]
            : s
              ? [60, 190, 90]
              : res.ref[i] === Infinity
                ? IMAGE_BG
                : [55, 60, 72];
      }),
    );
  }, [res, shownPx]);

  // each image is named by its caption and says, briefly, what it shows in numbers
  const figure = (
    ref: React.RefObject<HTMLCanvasElement | null>,
    caption: string,
    testId: string,
    says: string,
  ) => (
    <figure>
      <canvas
        ref={ref}
        width={W}
        height={W}
        className="rs-canvas rs-gpu-canvas"
        role="img"
        aria-label={`${caption}: ${says}`}
        data-testid={testId}
      />
      <figcaption>{caption}</figcaption>
    </figure>
  );
  const mismatch = res.mismatchNaive + res.mismatchStable;
  const readouts: ReadoutProps[] = [
    {
      id: 'image-wrong-naive',
      label: 'textbook: pixels wrong (hit/miss ≠ reference)',
      value: res.wrongNaive,
    },
    { id: 'image-wrong-stable', label: 'robust: pixels wrong', value: res.wrongStable },
    {
      id: 'image-shader-mismatch',
      label: `pixels where shader and emulation differ by > ${MISMATCH_ULPS} ulps`,
      value: res.gpu ? mismatch : null,
      note: res.gpu ? `textbook ${res.mismatchNaive}, robust ${res.mismatchStable}` : 'no shader ran',
    },
    {
      id: 'image-max-ulps-stable',
      label: 'robust: largest t error (ulps)',
      value: res.maxUlpStable,
      digits: 3,
    },
    { id: 'emu-wrong-naive', label: 'emulation, textbook: pixels wrong', value: res.emuWrongNaive },
    { id: 'emu-wrong-stable', label: 'emulation, robust: pixels wrong', value: res.emuWrongStable },
  ];
  return (
    <div className="rs-gpu" data-testid="gpu-panel" data-dist={dist}>
      <p className="rs-small">
        A WebGL2 fragment shader traces one ray per pixel ({W}×{W}) from a pinhole camera at the origin to a
        sphere D radii away, with both tests in the GPU’s 32-bit floats (<code>highp</code>). The same float32
        rays go through the JavaScript float32 emulation (every operation rounded by <code>Math.fround</code>)
        and a float64 reference.
      </p>
      <div className="rs-presets" role="group" aria-label="Distance presets for the GPU images">
        {PRESETS.map((p) => (
          <button
            key={p.exp}
            type="button"
            aria-pressed={exp === p.exp}
            data-testid={p.id ? `gpu-preset-${p.id}` : `gpu-preset-${p.exp}`}
            onClick={() => setExp(p.exp)}
          >
            {p.label}
          </button>
        ))}
      </div>
      {slider}
      {res.gpuError ? (
        <Notice kind="warn" testId="gpu-unavailable">
          {res.gpuError}
        </Notice>
      ) : null}
      <div className="rs-images rs-gpu-images">
        {figure(cRef, 'float64 reference', 'gpu-img-ref', `the sphere ${dist} radii away, ${W}×${W} pixels`)}
        {figure(
          cNaive,
          `textbook, ${res.gpu ? 'GPU' : 'emulated'} float32`,
          'gpu-img-naive',
          `${res.wrongNaive} of ${W * W} pixels wrong`,
        )}
        {figure(
          cStable,
          `robust, ${res.gpu ? 'GPU' : 'emulated'} float32`,
          'gpu-img-stable',
          `${res.wrongStable} of ${W * W} pixels wrong`,
        )}
        {figure(cErrN, 'textbook: error in t (ulps)', 'gpu-err-naive', 'false colour, log scale')}
        {figure(
          cErrS,
          'robust: error in t (ulps)',
          'gpu-err-stable',
          `largest error ${res.maxUlpStable.toPrecision(3)} ulps`,
        )}
        {figure(
          cMis,
          'shader ≠ emulation',
          'gpu-mismatch',
          res.gpu ? `${mismatch} pixels differ by more than ${MISMATCH_ULPS} ulps` : 'no shader ran',
        )}
      </div>
      <p className="rs-small rs-gpu-legend" aria-hidden="true">
        Error colours (float32 ulps of the reference t, log scale):{' '}
        {[0, 1, 4, 32, 1024].map((u) => {
          const c = ulpColour(u);
          return (
            <span key={u} className="rs-swatch-wrap">
              <span className="rs-swatch" style={{ background: `rgb(${c.join(',')})` }} />{' '}
              {u === 1024 ? '≥ 1024' : u}
            </span>
          );
        })}{' '}
        <span className="rs-hole">pink</span>: hit lost; light blue: hit invented.
      </p>
      <div className="readouts">
        {readouts.map((r) => (
          <Readout key={r.id} {...r} />
        ))}
      </div>
      <p className="rs-small" data-testid="gpu-note">
        {res.gpu ? (
          <>
            Ran on <span data-testid="gpu-renderer">{res.gpu.renderer}</span> in {res.gpu.ms.toFixed(1)} ms
            (compile, upload, draw and read back).{' '}
          </>
        ) : null}
        The shader is written in the emulation’s order, one operation at a time, so a GPU that rounds every
        operation as IEEE 754 says reproduces it bit for bit (SwiftShader, the software GPU of headless
        browsers, does). Real GPUs need not: GLSL lets the compiler fuse a·b + c into one multiply–add
        (rounded once instead of twice, usually <em>more</em> accurate, but different in the last bits), and
        allows division and square root an error of a few ulps. Those pixels are marked in the last image:
        orange for the textbook test, where a last-bit change of b² or 4ac moves the cancelled Δ, green for
        the robust one. Near the sphere’s rim, where Δ ≈ 0, even one ulp can turn a hit into a miss.
      </p>
      <p className="rs-small">
        At D = 10⁴ r the textbook Δ = b² − 4ac cancels two numbers of size 4·10⁸ whose float32 spacing is 32:
        its relative error u₃₂(D/r)² ≈ 6 swamps the answer, so hits are lost and invented all over the disc.
        The robust form’s error grows only like u₃₂·D/r ≈ 6·10⁻⁴: at this resolution no pixel centre lies that
        close to the rim (on larger images a few rim pixels can flip, and beyond 10⁵ r they do).
      </p>
      <ImageMeasure
        set={measured}
        summary="Measure the float32 images against float64: FLIP, relMSE, error map, PNG downloads"
      />
      <SelfIntersectionF32 />
    </div>
  );
}
