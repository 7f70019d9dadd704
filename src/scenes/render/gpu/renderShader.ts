/**
 * The GPU renderer's programs, assembled from their parts: the frame that adds one path per pixel
 * to the running sums (./glslRandom, ./glslScene, ./glslSampling, ./glslEstimator), and the display
 * pass that draws each pixel's mean to the visible canvas exactly as the CPU's image is drawn
 * (../pixels copyPixels: the Kahan mean clipped to [0, 1], the sRGB transfer curve of IEC 61966-2-1,
 * rounded to the nearest of 256 levels; the image's row 0 at the top). Both draw one triangle that
 * covers the viewport.
 */
import { GLSL_ESTIMATOR } from './glslEstimator';
import { GLSL_RANDOM } from './glslRandom';
import { GLSL_SAMPLING } from './glslSampling';
import { GLSL_SCENE } from './glslScene';

const HEADER = `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
`;

export const FULLSCREEN_VERTEX_SHADER = `#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}`;

export const FRAME_FRAGMENT_SHADER = HEADER + GLSL_RANDOM + GLSL_SCENE + GLSL_SAMPLING + GLSL_ESTIMATOR;

export const DISPLAY_FRAGMENT_SHADER = `${HEADER}
uniform sampler2D uAccum;
uniform float uCount;
uniform int uRes;
out vec4 colour;
void main() {
  ivec2 fc = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(uAccum, ivec2(fc.x, uRes - 1 - fc.y), 0);
  float x = clamp(uCount > 0.0 ? a.g / uCount : 0.0, 0.0, 1.0);
  float s = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
  float b = floor(255.0 * s + 0.5) / 255.0;
  colour = vec4(b, b, b, 1.0);
}`;
