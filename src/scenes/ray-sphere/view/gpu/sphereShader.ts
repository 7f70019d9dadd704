/**
 * The ray–sphere test on the GPU: a WebGL2 fragment shader (raw WebGL2, GLSL ES 3.00, highp)
 * traces one ray per pixel against one sphere with the textbook and the robust forms in the
 * GPU's float32, and writes both t-hits' bit patterns to an integer render target
 * (RGBA32UI: core WebGL2, no float-render extension needed), read back with readPixels.
 *
 * The shader's arithmetic is written in the same order as the JavaScript emulation
 * (core/geometry/raySphereF32.ts, tHitF32), one scalar operation at a time, so that a GPU doing
 * IEEE single precision without fusing reproduces it bit for bit. GLSL ES does not promise that:
 * a compiler may contract a·b + c into one fused multiply–add (rounded once, not twice), and
 * division and sqrt are allowed a few ulps of error (GLSL ES 3.00 §4.5.1). Where that happens
 * the panel counts and shows the pixels.
 */
import { makeProgram } from '../../../../three/glProgram';

export const VERTEX_SHADER = `#version 300 es
void main() {
  // one triangle covering the viewport
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}`;

export const FRAGMENT_SHADER = `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D uDirs;   // RGBA32F: unit ray direction per pixel (xyz)
uniform vec3 uCentre;      // sphere centre (the eye is at the origin)
uniform float uR2;         // r² rounded to float32
out uvec4 outT;

// nearest t >= 0, or -1.0 for none; the operations of tHitF32 in the same order
float tHit(vec3 d, bool stable) {
  float fx = 0.0 - uCentre.x;
  float fy = 0.0 - uCentre.y;
  float fz = 0.0 - uCentre.z;
  float a = d.x * d.x;
  a = a + d.y * d.y;
  a = a + d.z * d.z;
  float beta = fx * d.x;
  beta = beta + fy * d.y;
  beta = beta + fz * d.z;
  float ff = fx * fx;
  ff = ff + fy * fy;
  ff = ff + fz * fz;
  float cc = ff - uR2;
  // the textbook form's b (a doubling: exact) and the discriminant whose sign decides a hit:
  // a (r² − |l|²) = Δ/4 by the robust form, b² − 4ac by the textbook one
  float b = 2.0 * beta;
  float disc;
  if (stable) {
    float k = beta / a;
    float lx = fx - k * d.x;
    float ly = fy - k * d.y;
    float lz = fz - k * d.z;
    float ll = lx * lx;
    ll = ll + ly * ly;
    ll = ll + lz * lz;
    disc = a * (uR2 - ll);
  } else {
    disc = b * b - (4.0 * a) * cc;
  }
  if (!(disc >= 0.0)) return -1.0;
  float t0;
  float t1;
  if (disc == 0.0) {
    t0 = -beta / a;
    t1 = t0;
  } else if (stable) {
    float sq = sqrt(disc);
    float q = -(beta + (beta >= 0.0 ? sq : -sq));
    float ra = cc / q;
    float rb = q / a;
    t0 = min(ra, rb);
    t1 = max(ra, rb);
  } else {
    float s = sqrt(disc);
    float twoA = 2.0 * a;
    t0 = (-b - s) / twoA;
    t1 = (-b + s) / twoA;
  }
  return t0 >= 0.0 ? t0 : (t1 >= 0.0 ? t1 : -1.0);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  // texture row y holds image row y (top first); framebuffer row 0 is read back first
  vec3 d = texelFetch(uDirs, px, 0).xyz;
  float tn = tHit(d, false);
  float ts = tHit(d, true);
  uint flags = (tn >= 0.0 ? 1u : 0u) | (ts >= 0.0 ? 2u : 0u);
  outT = uvec4(floatBitsToUint(max(tn, 0.0)), floatBitsToUint(max(ts, 0.0)), flags, 1u);
}`;

/** What the GPU returned: both t images (+∞ for none) and what ran them. */
export interface GpuSphereImage {
  naive: Float32Array;
  stable: Float32Array;
  /** The renderer string (e.g. SwiftShader, or the GPU's name when the browser tells it). */
  renderer: string;
  /** Milliseconds from upload to the end of readPixels (includes the wait for the GPU). */
  ms: number;
}

/** Why the GPU path did not run; `message` is written for the page. */
export interface GpuFailure {
  ok: false;
  message: string;
}

/** The renderer's name (unmasked where the browser allows it). */
export function rendererName(gl: WebGL2RenderingContext): string {
  const ext = gl.getExtension('WEBGL_debug_renderer_info');
  const name = ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  return String(name ?? 'unknown');
}

/** A WebGL2 context on an offscreen canvas, or the reason there is none. */
export function getGl2(canvas?: HTMLCanvasElement): WebGL2RenderingContext | GpuFailure {
  let gl: WebGL2RenderingContext | null = null;
  try {
    const cv = canvas ?? document.createElement('canvas');
    gl = cv.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false });
  } catch {
    gl = null;
  }
  if (!gl) {
    return {
      ok: false,
      message:
        'This browser offers no WebGL2 (it may be turned off, or the GPU is blocklisted), so the shader cannot run here. The float32 emulation in JavaScript is shown instead.',
    };
  }
  return gl;
}

/**
 * Run the ray–sphere shader on a width × height image. `dirs` holds a float32 unit direction per
 * pixel (xyz, row-major, top row first), the eye is at the origin. Returns the two t images
 * (index = row · width + column, as `dirs`), or why the GPU could not do it.
 */
export function renderSphereGpu(
  gl: WebGL2RenderingContext,
  width: number,
  height: number,
  dirs: Float32Array,
  centre: readonly [number, number, number],
  r: number,
  now: () => number,
): GpuSphereImage | GpuFailure {
  const t0 = now();
  const prog = makeProgram(gl, VERTEX_SHADER, FRAGMENT_SHADER);
  if (typeof prog === 'string') return { ok: false, message: `The GPU refused the shader: ${prog}` };
  const rgba = new Float32Array(width * height * 4);
  for (let i = 0; i < width * height; i++) {
    rgba[4 * i] = dirs[3 * i];
    rgba[4 * i + 1] = dirs[3 * i + 1];
    rgba[4 * i + 2] = dirs[3 * i + 2];
  }
  const tex = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, rgba);
  const target = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32UI, width, height, 0, gl.RGBA_INTEGER, gl.UNSIGNED_INT, null);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  const cleanup = () => {
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fb);
    gl.deleteTexture(target);
    gl.deleteTexture(tex);
    gl.deleteProgram(prog);
  };
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) {
    cleanup();
    return { ok: false, message: 'The GPU cannot render to a 32-bit integer target here.' };
  }
  gl.viewport(0, 0, width, height);
  gl.useProgram(prog);
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.uniform1i(gl.getUniformLocation(prog, 'uDirs'), 0);
  gl.uniform3f(gl.getUniformLocation(prog, 'uCentre'), centre[0], centre[1], centre[2]);
  gl.uniform1f(gl.getUniformLocation(prog, 'uR2'), Math.fround(r * r));
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const out = new Uint32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA_INTEGER, gl.UNSIGNED_INT, out);
  cleanup();
  const err = gl.getError();
  if (err !== gl.NO_ERROR)
    return { ok: false, message: `WebGL error 0x${err.toString(16)} while rendering.` };
  const bits = new Float32Array(out.buffer);
  const naive = new Float32Array(width * height);
  const stable = new Float32Array(width * height);
  for (let i = 0; i < width * height; i++) {
    const flags = out[4 * i + 2];
    naive[i] = flags & 1 ? bits[4 * i] : Infinity;
    stable[i] = flags & 2 ? bits[4 * i + 1] : Infinity;
  }
  return { naive, stable, renderer: rendererName(gl), ms: now() - t0 };
}
