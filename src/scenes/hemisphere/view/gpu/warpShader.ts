/**
 * The exam's warp on the GPU: a WebGL2 vertex shader makes one direction per vertex from
 * gl_VertexID alone (a PCG hash of the index and the seed gives ξ₁, ξ₂; core/sampling/warpsF32
 * emulates it), draws it as a point, and at the same time writes it to a buffer by transform
 * feedback, which is read back for the χ² test. No sample passes through the CPU on its way to
 * the screen.
 *
 * Two forms: the key's textbook one, θ = ½ arccos(1 − 2ξ₁), φ = ln(c ξ₂ + 1), and the stable one,
 * sin θ = √ξ₁, cos θ = √(1 − ξ₁), φ = log1p(c ξ₂) (GLSL has no log1p: Kahan's
 * log(w)·u/(w − 1) with w = 1 + u). c = e^{2π} − 1.
 */
import { makeProgram } from '../../../../three/glProgram';

export const WARP_VERTEX_SHADER = `#version 300 es
precision highp float;
precision highp int;
uniform uint uSeed;
uniform int uForm;     // 0: textbook (arccos, ln), 1: stable (sqrt, log1p)
uniform float uC;      // e^{2π} − 1
out vec3 vDir;

uint pcg(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

void main() {
  uint h1 = pcg(uint(gl_VertexID) ^ pcg(uSeed));
  uint h2 = pcg(h1);
  float xi1 = float(h1 >> 8u) * (1.0 / 16777216.0);
  float xi2 = float(h2 >> 8u) * (1.0 / 16777216.0);
  float sinT;
  float cosT;
  float phi;
  if (uForm == 0) {
    float th = 0.5 * acos(1.0 - 2.0 * xi1);
    sinT = sin(th);
    cosT = cos(th);
    phi = log(uC * xi2 + 1.0);
  } else {
    sinT = sqrt(xi1);
    cosT = sqrt(1.0 - xi1);
    float u = uC * xi2;
    float w = 1.0 + u;
    phi = w == 1.0 ? u : log(w) * (u / (w - 1.0));
  }
  phi = min(phi, 6.2831850);
  vDir = vec3(sinT * cos(phi), sinT * sin(phi), cosT);
  // seen from above (orthographic): the disc is the hemisphere, density k e^φ per projected area
  gl_Position = vec4(vDir.xy * 0.96, 0.0, 1.0);
  gl_PointSize = 1.0;
}`;

export const WARP_FRAGMENT_SHADER = `#version 300 es
precision highp float;
uniform float uGain;
out vec4 colour;
void main() {
  colour = vec4(uGain, 0.75 * uGain, 0.45 * uGain, 1.0);
}`;

/** A compiled warp pass on one canvas's context. */
export interface WarpPass {
  gl: WebGL2RenderingContext;
  program: WebGLProgram;
  /** Draw `count` directions (and capture them when `capture` is given: a buffer of count·3 floats). */
  draw(count: number, seed: number, form: 0 | 1, capture?: WebGLBuffer | null): void;
  dispose(): void;
}

/** Compile and link the warp program (with transform feedback of vDir), or say why not. */
export function makeWarpPass(gl: WebGL2RenderingContext, c: number): WarpPass | string {
  const program = makeProgram(gl, WARP_VERTEX_SHADER, WARP_FRAGMENT_SHADER, ['vDir']);
  if (typeof program === 'string') return program;
  const loc = {
    seed: gl.getUniformLocation(program, 'uSeed'),
    form: gl.getUniformLocation(program, 'uForm'),
    c: gl.getUniformLocation(program, 'uC'),
    gain: gl.getUniformLocation(program, 'uGain'),
  };
  const tf = gl.createTransformFeedback();
  const vao = gl.createVertexArray();
  return {
    gl,
    program,
    draw(count, seed, form, capture) {
      gl.useProgram(program);
      gl.bindVertexArray(vao);
      gl.uniform1ui(loc.seed, seed >>> 0);
      gl.uniform1i(loc.form, form);
      gl.uniform1f(loc.c, c);
      // about 40 points per pixel land in the brightest pixels at 10⁶ points on 256²
      gl.uniform1f(loc.gain, Math.min(1, 6000 / Math.max(1, count)));
      gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
      gl.clearColor(0.07, 0.08, 0.1, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.ONE, gl.ONE);
      if (capture) {
        gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, tf);
        gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, capture);
        gl.beginTransformFeedback(gl.POINTS);
      }
      gl.drawArrays(gl.POINTS, 0, count);
      if (capture) {
        gl.endTransformFeedback();
        gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
        gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, null);
      }
      gl.disable(gl.BLEND);
      gl.bindVertexArray(null);
    },
    dispose() {
      gl.deleteTransformFeedback(tf);
      gl.deleteVertexArray(vao);
      gl.deleteProgram(program);
    },
  };
}

/** Read the captured floats [from, to) (xyz per direction) of a transform feedback buffer into `out`. */
export function readDirections(
  gl: WebGL2RenderingContext,
  buf: WebGLBuffer,
  out: Float32Array,
  from = 0,
  to = out.length,
): void {
  gl.bindBuffer(gl.COPY_READ_BUFFER, buf);
  gl.getBufferSubData(gl.COPY_READ_BUFFER, from * 4, out, from, to - from);
  gl.bindBuffer(gl.COPY_READ_BUFFER, null);
}

/** Wait for the GPU: a one-pixel read back forces every queued command to finish. */
export function syncGpu(gl: WebGL2RenderingContext): void {
  const px = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
}
