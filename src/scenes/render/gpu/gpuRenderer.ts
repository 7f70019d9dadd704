/**
 * The GPU renderer's WebGL2 side: the frame program draws one path per pixel into one of two RGBA32F
 * targets, reading the running sums from the other (ping-pong: a texture cannot be read and written
 * in one pass), and the display program draws the mean to the canvas. Nothing waits for the GPU:
 * the programs link in the background where KHR_parallel_shader_compile allows, and the sums come
 * back through a pixel-pack buffer and a fence, polled, so no read blocks the page.
 */
import type { SceneUniforms } from './sceneUniforms';
import { DISPLAY_FRAGMENT_SHADER, FRAME_FRAGMENT_SHADER, FULLSCREEN_VERTEX_SHADER } from './renderShader';

/** A running GPU render on one WebGL2 context. */
export interface GpuRenderer {
  readonly gl: WebGL2RenderingContext;
  /** Samples per pixel in the sums. */
  readonly count: number;
  /** Load a scene and clear the sums (a new image of res × res pixels). */
  load(u: SceneUniforms, seed: number): void;
  /** Add one sample per pixel. */
  step(): void;
  /** Draw the mean to the canvas (its drawing buffer must be res × res). */
  display(): void;
  /** The sums now (RGBA per pixel, rows from the top), once the GPU has them; null if the context is lost. */
  readBack(): Promise<Float32Array | null>;
  dispose(): void;
}

type Linked = { program: WebGLProgram; uniforms: Map<string, WebGLUniformLocation | null> };

const COMPLETION_STATUS_KHR = 0x91b1;

function shader(gl: WebGL2RenderingContext, type: number, src: string): WebGLShader | null {
  const s = gl.createShader(type);
  if (!s) return null;
  gl.shaderSource(s, src);
  gl.compileShader(s);
  return s;
}

const nextFrame = () => new Promise<void>((r) => setTimeout(r, 16));

/** Link a program, waiting for the driver without blocking where it can say when it is done. */
async function linkProgram(gl: WebGL2RenderingContext, fs: string): Promise<Linked | string> {
  const parallel = gl.getExtension('KHR_parallel_shader_compile') !== null;
  const v = shader(gl, gl.VERTEX_SHADER, FULLSCREEN_VERTEX_SHADER);
  const f = shader(gl, gl.FRAGMENT_SHADER, fs);
  const program = gl.createProgram();
  if (!v || !f || !program) return 'could not create a shader program';
  gl.attachShader(program, v);
  gl.attachShader(program, f);
  gl.linkProgram(program);
  if (parallel)
    while (!gl.getProgramParameter(program, COMPLETION_STATUS_KHR)) {
      if (gl.isContextLost()) return 'the WebGL context was lost';
      await nextFrame();
    }
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    const log = gl.getShaderInfoLog(f) || gl.getShaderInfoLog(v) || gl.getProgramInfoLog(program) || '';
    gl.deleteProgram(program);
    return `the shader did not compile: ${log.trim().split('\n')[0] || 'no log'}`;
  }
  gl.deleteShader(v);
  gl.deleteShader(f);
  const uniforms = new Map<string, WebGLUniformLocation | null>();
  const n = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) as number;
  for (let k = 0; k < n; k++) {
    const info = gl.getActiveUniform(program, k);
    if (!info) continue;
    const name = info.name.replace(/\[0\]$/, '');
    uniforms.set(name, gl.getUniformLocation(program, name));
  }
  return { program, uniforms };
}

function floatTarget(gl: WebGL2RenderingContext, res: number): { tex: WebGLTexture; fbo: WebGLFramebuffer } {
  const tex = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, res, res, 0, gl.RGBA, gl.FLOAT, null);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  const fbo = gl.createFramebuffer()!;
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  return { tex, fbo };
}

/**
 * Compile the programs on gl (which must have EXT_color_buffer_float enabled) for res × res
 * images; a string says why not.
 */
export async function createGpuRenderer(
  gl: WebGL2RenderingContext,
  res: number,
): Promise<GpuRenderer | string> {
  const frame = await linkProgram(gl, FRAME_FRAGMENT_SHADER);
  if (typeof frame === 'string') return frame;
  const show = await linkProgram(gl, DISPLAY_FRAGMENT_SHADER);
  if (typeof show === 'string') return show;
  const vao = gl.createVertexArray();
  const targets = [floatTarget(gl, res), floatTarget(gl, res)];
  const grid = gl.createTexture();
  const pbo = gl.createBuffer();
  let current = 0;
  let count = 0;
  let seed = 0;
  const u = (p: Linked, name: string) => p.uniforms.get(name) ?? null;

  const clear = () => {
    for (const t of targets) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, t.fbo);
      gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 0]);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    count = 0;
  };
  clear();

  return {
    gl,
    get count() {
      return count;
    },
    load(s, runSeed) {
      seed = runSeed >>> 0;
      const p = frame;
      gl.useProgram(p.program);
      gl.uniform3fv(u(p, 'uEye'), s.eye);
      gl.uniform3fv(u(p, 'uFwd'), s.fwd);
      gl.uniform3fv(u(p, 'uRight'), s.right);
      gl.uniform3fv(u(p, 'uUp'), s.up);
      gl.uniform2fv(u(p, 'uScale'), s.scale);
      gl.uniform1i(u(p, 'uRes'), res);
      gl.uniform1f(u(p, 'uFloor'), s.floor);
      gl.uniform4fv(u(p, 'uSphere'), s.sphere);
      gl.uniform1f(u(p, 'uSphereAlbedo'), s.sphereAlbedo);
      gl.uniform1i(u(p, 'uTexFilter'), s.texFilter);
      gl.uniform2fv(u(p, 'uTexRange'), s.texRange);
      gl.uniform1i(u(p, 'uLightCount'), s.lights.count);
      gl.uniform4fv(u(p, 'uLightCorner'), s.lights.corner);
      gl.uniform4fv(u(p, 'uLightEx'), s.lights.ex);
      gl.uniform4fv(u(p, 'uLightEy'), s.lights.ey);
      gl.uniform4fv(u(p, 'uLightN'), s.lights.n);
      gl.uniform1i(u(p, 'uPlateCount'), s.plates.count);
      gl.uniform4fv(u(p, 'uPlateCorner'), s.plates.corner);
      gl.uniform4fv(u(p, 'uPlateEx'), s.plates.ex);
      gl.uniform4fv(u(p, 'uPlateEy'), s.plates.ey);
      gl.uniform4fv(u(p, 'uPlateN'), s.plates.n);
      gl.uniform1f(u(p, 'uEnv'), s.env);
      gl.uniform1i(u(p, 'uStrategy'), s.strategy);
      gl.uniform1i(u(p, 'uBounces'), s.bounces);
      gl.uniform1i(u(p, 'uBias'), s.bias);
      gl.uniform1f(u(p, 'uOne'), 1);
      gl.uniform1i(u(p, 'uAccum'), 0);
      gl.uniform1i(u(p, 'uTex'), 1);
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, grid);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, s.tex.width, s.tex.height, 0, gl.RED, gl.FLOAT, s.tex.values);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.activeTexture(gl.TEXTURE0);
      clear();
    },
    step() {
      const from = targets[current],
        to = targets[1 - current];
      gl.useProgram(frame.program);
      gl.uniform1ui(u(frame, 'uSeed'), seed);
      gl.uniform1ui(u(frame, 'uSample'), count);
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, grid);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, from.tex);
      gl.bindFramebuffer(gl.FRAMEBUFFER, to.fbo);
      gl.viewport(0, 0, res, res);
      gl.bindVertexArray(vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      current = 1 - current;
      count++;
    },
    display() {
      gl.useProgram(show.program);
      gl.uniform1f(u(show, 'uCount'), count);
      gl.uniform1i(u(show, 'uRes'), res);
      gl.uniform1i(u(show, 'uAccum'), 0);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, targets[current].tex);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
      gl.bindVertexArray(vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    },
    async readBack() {
      if (gl.isContextLost()) return null;
      const bytes = 16 * res * res;
      gl.bindFramebuffer(gl.FRAMEBUFFER, targets[current].fbo);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pbo);
      gl.bufferData(gl.PIXEL_PACK_BUFFER, bytes, gl.STREAM_READ);
      gl.readPixels(0, 0, res, res, gl.RGBA, gl.FLOAT, 0);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
      if (!sync) return null;
      for (;;) {
        if (gl.isContextLost()) return null;
        const st = gl.clientWaitSync(sync, 0, 0);
        if (st === gl.ALREADY_SIGNALED || st === gl.CONDITION_SATISFIED) break;
        if (st === gl.WAIT_FAILED) {
          gl.deleteSync(sync);
          return null;
        }
        await nextFrame();
      }
      gl.deleteSync(sync);
      const out = new Float32Array(4 * res * res);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pbo);
      gl.getBufferSubData(gl.PIXEL_PACK_BUFFER, 0, out);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
      return out;
    },
    dispose() {
      if (gl.isContextLost()) return;
      gl.deleteProgram(frame.program);
      gl.deleteProgram(show.program);
      for (const t of targets) {
        gl.deleteTexture(t.tex);
        gl.deleteFramebuffer(t.fbo);
      }
      gl.deleteTexture(grid);
      gl.deleteBuffer(pbo);
      gl.deleteVertexArray(vao);
    },
  };
}

/** What the page can tell without a context: WebGL2, and a canvas it can hand to a worker. */
export interface GpuSupport {
  webgl2: boolean;
  offscreen: boolean;
}

/** Ask the browser's API, without making a context (the worker makes the one it draws with). */
export function gpuSupport(): GpuSupport {
  if (typeof window === 'undefined') return { webgl2: false, offscreen: false };
  return {
    // asked with `in`, not by reading the global: Chromium builds an interface's object on its first
    // read, and WebGL2's (hundreds of constants) took 4–10 ms of the page's first render; `in`
    // answers from the global's property list without building it
    webgl2: 'WebGL2RenderingContext' in window,
    offscreen:
      typeof OffscreenCanvas !== 'undefined' &&
      typeof HTMLCanvasElement !== 'undefined' &&
      'transferControlToOffscreen' in HTMLCanvasElement.prototype,
  };
}

const SOFTWARE_GL = /swiftshader|llvmpipe|softpipe|software|basic render/i;

/** The name of a WebGL renderer that runs on the CPU (SwiftShader, llvmpipe …), else null. */
export function softwareName(renderer: string): string | null {
  const m = SOFTWARE_GL.exec(renderer);
  return m ? (/swiftshader/i.test(renderer) ? 'SwiftShader' : m[0]) : null;
}

/** A WebGL2 context for the GPU renderer on this canvas, with float targets enabled, or null. */
export function renderContext(canvas: OffscreenCanvas): WebGL2RenderingContext | null {
  const gl = canvas.getContext('webgl2', {
    alpha: false,
    antialias: false,
    depth: false,
    stencil: false,
    premultipliedAlpha: false,
    preserveDrawingBuffer: false,
  }) as WebGL2RenderingContext | null;
  return gl && gl.getExtension('EXT_color_buffer_float') ? gl : null;
}
