/**
 * The exam's warps in float32, and on the GPU: the inversion formulas' float32 errors near ξ → 0
 * and ξ → 1 against float64, then 10⁶ directions made and drawn by a WebGL2 vertex shader
 * (./gpu/warpShader), read back by transform feedback and χ²-tested against the exam's pdf
 * (../gpuCheck, in the scene's worker). A lazy chunk: loaded only when its disclosure is opened;
 * the shader runs once its canvas comes on screen, and that run never waits for the GPU (its read
 * back follows a fence polled between tasks; only "Time 20 frames", a benchmark asked for, does).
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { Notice, Readout, formatNumber, keepTextParenthesesTogether } from '../../../ui';
import { EXAM_C_F32, warpF32Table } from '../../../core/sampling';
import { sidakAlpha } from '../../../core/verify';
import { useSeenOnce } from '../../../ui/useInView';
import { isCancelled, runWorkerTask } from '../../../workers';
import { makeWorker } from '../worker';
import type { GpuCheck, WarpForm } from '../gpuCheck';
import { ErrorTable } from './ErrorTable';
import { makeWarpPass, readDirections, syncGpu, type WarpPass } from './gpu/warpShader';

/** Directions per GPU pass. */
export const GPU_SAMPLES = 1_000_000;
const SIZE = 256;
/** Floats read back from the GPU per task (3 per direction). */
const READ_SLICE = 3 * 2 ** 17;
const FORMS = [
  { id: 0 as const, label: keepTextParenthesesTogether('textbook: ½ arccos(1 − 2ξ₁), ln(c ξ₂ + 1)') },
  { id: 1 as const, label: keepTextParenthesesTogether('stable: √ξ₁, √(1 − ξ₁), log1p(c ξ₂)') },
];
/** Both forms are tested: the Šidák correction is for two tests. */
const TESTS = 2;
const ALPHA = 0.01;

const xiText = (xi: number) =>
  xi > 0.5 ? `1 − ${formatNumber(1 - xi, 3)}` : xi === 0.5 ? '0.5' : formatNumber(xi, 3);

/** The float32 forms near ξ → 0 and ξ → 1 against float64. */
function Float32WarpTable() {
  const rows = useMemo(() => warpF32Table(), []);
  return (
    <ErrorTable
      label="float32 inversion errors"
      role="group"
      testId="warp-f32-table"
      caption={
        <caption className="small">
          Relative error in float32 (and in float32 ulps) against the float64 stable forms. ξ is a float32
          value.
        </caption>
      }
      columns={
        <>
          <th scope="col">{keepTextParenthesesTogether('θ = ½ arccos(1 − 2ξ)')}</th>
          <th scope="col">θ = arcsin √ξ</th>
          <th scope="col">{keepTextParenthesesTogether('φ = ln(c ξ + 1)')}</th>
          <th scope="col">φ = log1p(c ξ)</th>
        </>
      }
      rows={rows.map((r) => ({
        key: r.xi,
        lead: (
          <th scope="row" className="mono">
            {xiText(r.xi)}
          </th>
        ),
        forms: r.forms,
      }))}
      tolerance={1e-5}
    />
  );
}

/** A run on screen: the worker's check of the form and seed drawn, with the page's own timings. */
interface GpuRun extends GpuCheck {
  form: WarpForm;
  seed: number;
  msDraw: number;
  msRead: number;
}

export function GpuWarpPanel({ seed }: { seed: number }) {
  const canvas = useRef<HTMLCanvasElement>(null);
  const pass = useRef<WarpPass | null>(null);
  const captureBuf = useRef<WebGLBuffer | null>(null);
  const [form, setForm] = useState<WarpForm>(1);
  const seen = useSeenOnce(canvas);
  const [error, setError] = useState<string | null>(null);
  const [lastRun, setRun] = useState<GpuRun | null>(null);
  // the run of the form and seed on screen (never the previous one's, in the render before the
  // effect below starts the new run)
  const run = lastRun && lastRun.form === form && lastRun.seed === seed ? lastRun : null;
  const [bench, setBench] = useState<{ median: number; frames: number } | null>(null);
  const [renderer, setRenderer] = useState('');

  useEffect(() => {
    const cv = canvas.current;
    if (!cv) return;
    let gl: WebGL2RenderingContext | null = null;
    try {
      gl = cv.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
    } catch {
      gl = null;
    }
    if (!gl) {
      setError(
        'This browser offers no WebGL2 (it may be turned off, or the GPU is blocklisted), so the vertex shader cannot run here. The float32 table above is computed in JavaScript and still holds.',
      );
      return;
    }
    const p = makeWarpPass(gl, EXAM_C_F32);
    if (typeof p === 'string') {
      setError(`The GPU refused the shader: ${p}`);
      return;
    }
    pass.current = p;
    const buf = gl.createBuffer();
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, buf);
    gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, GPU_SAMPLES * 12, gl.STREAM_READ);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    captureBuf.current = buf;
    const ext = gl.getExtension('WEBGL_debug_renderer_info');
    setRenderer(String(ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)));
    return () => {
      p.dispose();
      gl.deleteBuffer(buf);
      pass.current = null;
    };
  }, []);

  // Draw and capture once the canvas is on screen, then test in the scene's worker (binning 10⁶
  // directions takes a few hundred ms). The page never waits for the GPU: the draw is followed by a
  // fence whose status is polled between tasks, and the 12 MB read back comes in slices.
  useEffect(() => {
    const p = pass.current;
    const buf = captureBuf.current;
    if (!seen || !p || !buf) return;
    setRun(null);
    const gl = p.gl;
    const ctrl = new AbortController();
    let timer = 0;
    const t0 = performance.now();
    p.draw(GPU_SAMPLES, seed, form, buf);
    let sync: WebGLSync | null = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    const drop = () => {
      if (sync) gl.deleteSync(sync);
      sync = null;
    };
    const dirs = new Float32Array(GPU_SAMPLES * 3);
    let msDraw = 0;
    let msRead = 0;
    let from = 0;
    const test = () =>
      runWorkerTask(
        makeWorker,
        'gpuCheck',
        { dirs, seed, form, alpha: ALPHA, tests: TESTS },
        { signal: ctrl.signal, transfer: [dirs.buffer] },
      ).then(
        (c) => setRun({ ...c, form, seed, msDraw, msRead }),
        (err: unknown) => {
          if (!isCancelled(err))
            setError(
              `The χ² test of the GPU’s directions did not run: ${err instanceof Error ? err.message : String(err)}`,
            );
        },
      );
    // the read back, READ_SLICE floats a task (all 12 MB at once took over 100 ms on a software GPU)
    const readSlice = () => {
      const r0 = performance.now();
      const to = Math.min(dirs.length, from + READ_SLICE);
      readDirections(gl, buf, dirs, from, to);
      msRead += performance.now() - r0;
      from = to;
      if (from < dirs.length) timer = window.setTimeout(readSlice, 0);
      else void test();
    };
    const poll = () => {
      // SYNC_STATUS, not clientWaitSync: in Chromium a client wait is a synchronous round trip to
      // the GPU process, which answers only once the draw is done, and the page would stall for it
      if (sync && gl.getSyncParameter(sync, gl.SYNC_STATUS) !== gl.SIGNALED) {
        timer = window.setTimeout(poll, 8);
        return;
      }
      drop();
      msDraw = performance.now() - t0;
      readSlice();
    };
    timer = window.setTimeout(poll, 0);
    return () => {
      window.clearTimeout(timer);
      ctrl.abort();
      drop();
    };
  }, [seen, seed, form]);

  const timeFrames = useCallback(() => {
    const p = pass.current;
    if (!p) return;
    const frames = 20;
    const ms: number[] = [];
    p.draw(GPU_SAMPLES, seed, form);
    syncGpu(p.gl); // warm-up
    for (let f = 0; f < frames; f++) {
      const t0 = performance.now();
      p.draw(GPU_SAMPLES, seed + f + 1, form);
      syncGpu(p.gl);
      ms.push(performance.now() - t0);
    }
    p.draw(GPU_SAMPLES, seed, form); // leave the tested image on screen
    ms.sort((a, b) => a - b);
    setBench({ median: ms[frames >> 1], frames });
  }, [seed, form]);

  return (
    <div className="gpu-warp" data-testid="gpu-warp-panel">
      <Float32WarpTable />
      <p className="small">
        In float32 {keepTextParenthesesTogether('(u₃₂ = 2⁻²⁴ ≈ 6·10⁻⁸)')} the failures the double table shows
        at ξ ≈ 10⁻¹⁶ come at ξ ≈ 10⁻⁷: 1 − 2ξ₁ rounds to 1 below ξ₁ = 2⁻²⁵ (θ = 0 for a sample whose θ is √ξ₁
        ≈ 10⁻⁴), c ξ₂ + 1 swallows c ξ₂, and near ξ₁ → 1 arcsin magnifies the rounding of √ξ₁ a thousandfold.
        A GPU’s random numbers have 24 bits {keepTextParenthesesTogether('(ξ = k·2⁻²⁴)')}, so the first
        failures are samples it really draws.
      </p>
      <h3>10⁶ directions from a vertex shader</h3>
      <p className="small">
        Each vertex makes its own direction from gl_VertexID (a PCG hash of the index and the seed gives ξ₁,
        ξ₂), draws it as a point (the hemisphere seen from above: brightness k e<sup>φ</sup> per projected
        area, so it grows with φ only), and writes it by transform feedback to a buffer that is read back for
        a χ² test against the exam’s pdf (10 × 20 bins of equal solid angle). No sample passes through the CPU
        on its way to the screen.
      </p>
      <div className="gpu-warp-row">
        <canvas
          ref={canvas}
          width={SIZE}
          height={SIZE}
          className="gpu-warp-canvas"
          aria-label="10⁶ GPU directions seen from above"
          data-testid="gpu-warp-canvas"
        />
        <div>
          <fieldset className="gpu-warp-forms">
            <legend>Form in the shader</legend>
            {FORMS.map((f) => (
              <label key={f.id}>
                <input
                  type="radio"
                  name="gpu-warp-form"
                  checked={form === f.id}
                  onChange={() => setForm(f.id)}
                  data-testid={`gpu-warp-form-${f.id}`}
                />{' '}
                {f.label}
              </label>
            ))}
          </fieldset>
          {error ? (
            <Notice kind="warn" testId="gpu-warp-unavailable">
              {error}
            </Notice>
          ) : null}
          <div className="readouts">
            <Readout
              id="gpu-chi2-p"
              label={`χ² p-value (${GPU_SAMPLES.toLocaleString('en')} GPU samples)`}
              value={run ? run.p : null}
              digits={4}
              note={
                run
                  ? `χ² = ${formatNumber(run.statistic, 5)}, ${run.dof} dof`
                  : error
                    ? 'no shader ran'
                    : 'testing…'
              }
            />
            <Readout
              id="gpu-chi2-threshold"
              label={`Šidák threshold (α = ${ALPHA}, ${TESTS} tests)`}
              value={sidakAlpha(ALPHA, TESTS)}
              digits={4}
            />
            <Readout
              id="gpu-chi2-pass"
              label="consistent with the pdf"
              value={run ? (run.pass ? 'yes' : 'no') : null}
            />
            <Readout
              id="gpu-warp-max-diff"
              label="GPU vs float32 emulation, first 4096 directions (largest difference)"
              value={run ? run.maxDiff : null}
              digits={3}
              note={run ? `${formatNumber(run.maxDiff / 2 ** -24, 3)} u₃₂` : undefined}
            />
            <Readout
              id="gpu-warp-frame-ms"
              label={`frame: draw ${GPU_SAMPLES.toLocaleString('en')} points (median ms)`}
              value={bench ? bench.median : null}
              digits={3}
              note={bench ? `${bench.frames} frames` : 'press “Time 20 frames”'}
            />
          </div>
          <button type="button" onClick={timeFrames} disabled={!!error} data-testid="gpu-warp-time">
            Time 20 frames
          </button>
          {run ? (
            <p className="small" data-testid="gpu-warp-times">
              {renderer ? (
                <>
                  On <span data-testid="gpu-warp-renderer">{renderer}</span>:{' '}
                </>
              ) : null}
              draw and capture {run.msDraw.toFixed(1)} ms (until its fence was seen), read back{' '}
              {run.msRead.toFixed(1)} ms, χ² in a worker {run.ms.toFixed(0)} ms.
            </p>
          ) : null}
        </div>
      </div>
      <p className="small">
        The GPU’s sin, cos, acos and log are not correctly rounded: GLSL ES 3.00 leaves their precision
        unspecified, and fast polynomial approximations are common (SwiftShader’s sin and cos are off by about
        2·10⁻⁴, thousands of float32 ulps; its log by a few ulps). So the comparison with the emulation is a
        difference to read, not an equality; the emulation assumes correctly rounded functions. The χ² test
        cannot see float32 rounding (10⁶ samples resolve densities to about 10⁻³), only a wrong warp.
      </p>
    </div>
  );
}
