/**
 * Is there WebGL 2, and does it run on the CPU? Asked once, without three.js (so no console error).
 * On a software WebGL the probe's context is kept for the first renderer (./engine.ts adopts it).
 */
/** Renderer strings of WebGL implementations that run on the CPU (no GPU, or a blocklisted one). */
const SOFTWARE_GL = /swiftshader|llvmpipe|softpipe|software|basic render/i;
let probed: { available: boolean; software: boolean } | null = null;

/**
 * The context attributes of a renderer on a software WebGL (three.js's defaults, without
 * multisampling): the probe asks for these, so that its context can become the first renderer's.
 */
const SOFTWARE_ATTRS: WebGLContextAttributes = {
  alpha: true,
  depth: true,
  stencil: false,
  antialias: false,
  premultipliedAlpha: true,
  preserveDrawingBuffer: false,
  powerPreference: 'low-power',
  failIfMajorPerformanceCaveat: false,
};

/**
 * The probe's WebGL2 context on a software WebGL, kept for the first engine: creating a context
 * there costs tens of ms of main thread (×4 on a phone), so the page creates one, not two.
 */
let spare: { canvas: HTMLCanvasElement; gl: WebGL2RenderingContext } | null = null;

/**
 * Can the browser give a WebGL 2 context, and is it a software one (SwiftShader, llvmpipe …)?
 * Checked once, without three (so no console error). The probe context is released, except on a
 * software WebGL, where the first engine adopts it.
 */
export function probeWebGL(): { available: boolean; software: boolean } {
  if (probed) return probed;
  try {
    const c = document.createElement('canvas');
    // three.js (r163 on) draws with WebGL 2 only: without it the view is off (and three's error unlogged)
    const gl = c.getContext('webgl2', SOFTWARE_ATTRS) as WebGL2RenderingContext | null;
    if (!gl) return (probed = { available: false, software: false });
    // Chromium reports the real renderer in RENDERER; others through WEBGL_debug_renderer_info.
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    const name = `${String(gl.getParameter(gl.RENDERER) ?? '')} ${dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) ?? '') : ''}`;
    const software = SOFTWARE_GL.test(name);
    if (software) spare = { canvas: c, gl };
    else gl.getExtension('WEBGL_lose_context')?.loseContext();
    return (probed = { available: true, software });
  } catch {
    return (probed = { available: false, software: false });
  }
}

/** True when the browser can give a WebGL 2 context (checked without three, so no console error). */
export function webglAvailable(): boolean {
  return probeWebGL().available;
}

/** The probe's context if it is still unused and alive (once). */
export function takeSpare(): { canvas: HTMLCanvasElement; gl: WebGL2RenderingContext } | null {
  const s = spare;
  spare = null;
  return s && !s.gl.isContextLost() ? s : null;
}
