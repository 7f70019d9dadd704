/**
 * Compiling and linking a WebGL2 program from GLSL sources, for the views that run their own
 * shaders beside three.js (the float32 warps and ray tests on the GPU). Every failure comes back as
 * a string for the page (the compiler's log), never as an exception.
 */

function compile(gl: WebGL2RenderingContext, type: number, src: string): WebGLShader | string {
  const sh = gl.createShader(type);
  if (!sh) return 'could not create a shader';
  gl.shaderSource(sh, src);
  gl.compileShader(sh);
  if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(sh) ?? '';
    gl.deleteShader(sh);
    return log || 'shader compile failed';
  }
  return sh;
}

/** Link a program from GLSL sources; a string is the error. */
export function makeProgram(gl: WebGL2RenderingContext, vs: string, fs: string, feedback?: string[]) {
  const v = compile(gl, gl.VERTEX_SHADER, vs);
  if (typeof v === 'string') return `vertex shader: ${v}`;
  const f = compile(gl, gl.FRAGMENT_SHADER, fs);
  if (typeof f === 'string') return `fragment shader: ${f}`;
  const p = gl.createProgram();
  if (!p) return 'could not create a program';
  gl.attachShader(p, v);
  gl.attachShader(p, f);
  if (feedback) gl.transformFeedbackVaryings(p, feedback, gl.INTERLEAVED_ATTRIBS);
  gl.linkProgram(p);
  gl.deleteShader(v);
  gl.deleteShader(f);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return gl.getProgramInfoLog(p) || 'link failed';
  return p;
}
