/**
 * The exam's warps in float32, and on the GPU: the inversion formulas' float32 errors near ξ → 0
 * and ξ → 1 against float64, then 10⁶ directions made and drawn by a WebGL2 vertex shader
 * (./gpu/warpShader), read back by transform feedback and χ²-tested against the exam's pdf.
 * A lazy chunk: loaded only when its disclosure is opened.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { Notice, Readout, formatNumber, keepTextParenthesesTogether } from '../../../ui';
import {
  EXAM_C_F32,
  examLobePdf,
  gpuXi,
  thetaAcosF32,
  phiLnF32,
  phiLog1pF32,
  warpF32Table,
} from '../../../core/sampling';
import { hemisphereChi2, sidakAlpha } from '../../../core/verify';
import { ErrorTable } from './ErrorTable';
import { makeWarpPass, readDirections, syncGpu, type WarpPass } from './gpu/warpShader';

/** Directions per GPU pass. */
export const GPU_SAMPLES = 1_000_000;
const SIZE = 256;
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
          <th scope="col">θ = ½ arccos(1 − 2ξ)</th>
          <th scope="col">θ = arcsin √ξ</th>
          <th scope="col">φ = ln(c ξ + 1)</th>
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

interface GpuRun {
  form: 0 | 1;
  seed: number;
  p: number;
  statistic: number;
  dof: number;
  threshold: number;
  pass: boolean;
  /** Largest |GPU − emulation| over the first 4096 directions' components (absolute). */
  maxDiff: number;
  msDraw: number;
  msRead: number;
  msChi2: number;
}

/** The float32 emulation of sample i (the vertex shader's arithmetic, correctly rounded built-ins). */
function emulate(i: number, seed: number, form: 0 | 1): [number, number, number] {
  const fr = Math.fround;
  const [x1, x2] = gpuXi(i, seed);
  let s: number;
  let c: number;
  let phi: number;
  if (form === 0) {
    const th = thetaAcosF32(x1);
    s = fr(Math.sin(th));
    c = fr(Math.cos(th));
    phi = phiLnF32(x2);
  } else {
    s = fr(Math.sqrt(x1));
    c = fr(Math.sqrt(fr(1 - x1)));
    phi = phiLog1pF32(x2);
  }
  phi = Math.min(phi, fr(6.283185));
  return [fr(s * fr(Math.cos(phi))), fr(s * fr(Math.sin(phi))), c];
}

export function GpuWarpPanel({ seed }: { seed: number }) {
  const canvas = useRef<HTMLCanvasElement>(null);
  const pass = useRef<WarpPass | null>(null);
  const captureBuf = useRef<WebGLBuffer | null>(null);
  const [form, setForm] = useState<0 | 1>(1);
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

  // Draw and capture, then test (the χ² binning and quadrature take a few hundred ms: after a paint).
  useEffect(() => {
    const p = pass.current;
    const buf = captureBuf.current;
    if (!p || !buf) return;
    setRun(null);
    const t0 = performance.now();
    p.draw(GPU_SAMPLES, seed, form, buf);
    syncGpu(p.gl);
    const t1 = performance.now();
    const dirs = readDirections(p.gl, buf, GPU_SAMPLES);
    const t2 = performance.now();
    const id = setTimeout(() => {
      const t3 = performance.now();
      const d64 = Float64Array.from(dirs);
      const res = hemisphereChi2(d64, GPU_SAMPLES, examLobePdf, {
        cosThetaBins: 10,
        phiBins: 20,
        alpha: ALPHA,
        tests: TESTS,
      });
      let maxDiff = 0;
      for (let i = 0; i < 4096; i++) {
        const e = emulate(i, seed, form);
        for (let k = 0; k < 3; k++) maxDiff = Math.max(maxDiff, Math.abs(dirs[3 * i + k] - e[k]));
      }
      setRun({
        form,
        seed,
        p: res.pValue,
        statistic: res.statistic,
        dof: res.dof,
        threshold: res.sidakAlpha,
        pass: res.pass,
        maxDiff,
        msDraw: t1 - t0,
        msRead: t2 - t1,
        msChi2: performance.now() - t3,
      });
    }, 30);
    return () => clearTimeout(id);
  }, [seed, form]);

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
        In float32 (u₃₂ = 2⁻²⁴ ≈ 6·10⁻⁸) the failures the double table shows at ξ ≈ 10⁻¹⁶ come at ξ ≈ 10⁻⁷: 1
        − 2ξ₁ rounds to 1 below ξ₁ = 2⁻²⁵ (θ = 0 for a sample whose θ is √ξ₁ ≈ 10⁻⁴), c ξ₂ + 1 swallows c ξ₂,
        and near ξ₁ → 1 arcsin magnifies the rounding of √ξ₁ a thousandfold. A GPU’s random numbers have 24
        bits {keepTextParenthesesTogether('(ξ = k·2⁻²⁴)')}, so the first failures are samples it really draws.
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
              draw and capture {run.msDraw.toFixed(1)} ms, read back {run.msRead.toFixed(1)} ms, χ² on the CPU{' '}
              {run.msChi2.toFixed(0)} ms.
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
