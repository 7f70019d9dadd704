/**
 * The estimator on the GPU, in GLSL: core/render/directLight's direct-light sample by the seven
 * strategies (MIS by the sample index's parity, each term 2 w f L cos θ / p, every pdf in solid
 * angle), its biased variants (core/render/bias), and core/render/pathTrace's path: next-event
 * estimation at every vertex, continued by a BSDF sample, Russian roulette from the third vertex
 * with q = min(1, β). One path per pixel per frame, through a uniformly jittered point of the
 * pixel (core/render/camera's convention: column i, row j from the top, x = 2(i + sx)/res − 1,
 * y = 1 − 2(j + sy)/res).
 *
 * The frame adds the sample to the pixel's running sums in an RGBA32F target: R the naive float32
 * sum, G Kahan's compensated sum and B its compensation term (core/render/f32Sum), A the sum of
 * squares (the pixel's variance). `uOne` is 1 at run time; multiplying by it keeps a compiler from
 * simplifying (t − s) − y to 0, which would turn Kahan's sum back into the naive one (GLSL ES 3.0
 * has no `precise`).
 */
export const GLSL_ESTIMATOR = `
uniform int uStrategy;
uniform int uBounces;
uniform int uBias;
uniform uint uSeed;
uniform uint uSample;
uniform float uOne;
uniform highp sampler2D uAccum;

const float SHADOW_EPS = 1e-4;
const float CLAMP_MAX = 0.5;
const int T_UNIFORM = 0;
const int T_COSINE = 1;
const int T_BSDF = 2;
const int T_AREA = 3;
const int T_SOLID = 4;
const int T_MIS_BALANCE = 5;

float misWeight(bool balance, float pa, float pb) {
  if (!(pa > 0.0)) return 0.0;
  if (!(pb > 0.0)) return 1.0;
  if (balance) return pa / (pa + pb);
  float m = max(pa, pb);
  float a = pa / m;
  float b = pb / m;
  return (a * a) / (a * a + b * b);
}

float directSample(Vtx v, int index) {
  bool mis = uStrategy >= T_MIS_BALANCE;
  int t = mis ? (index % 2 == 0 ? T_BSDF : T_SOLID) : uStrategy;
  float f = 0.0;
  float L = 0.0;
  float cosT = 0.0;
  float pdfW = 0.0;
  float cosL = 0.0;
  int light = -2;
  vec3 d = vec3(0.0, 0.0, 1.0);
  vec3 lp = vec3(0.0);
  if (t == T_AREA || t == T_SOLID) {
    float u0 = emitterCount() > 1 ? rand() : 0.0;
    float u1 = rand();
    float u2 = rand();
    int k;
    vec3 x;
    float pdf;
    if (sampleEmitter(v.p, t == T_AREA, u0, u1, u2, k, x, pdf)) {
      float dist = INF;
      bool facing = true;
      if (k < 0) {
        d = x;
        pdfW = pdf;
      } else {
        vec3 r = x - v.p;
        float r2 = dot(r, r);
        dist = sqrt(r2);
        d = r / dist;
        cosL = -dot(d, uLightN[k].xyz);
        lp = x;
        pdfW = t == T_AREA ? (cosL != 0.0 ? pdf * r2 / abs(cosL) : 0.0) : pdf;
        facing = cosL > 0.0;
      }
      if (facing) {
        cosT = dot(d, v.n);
        if (cosT > 0.0 && pdfW > 0.0) {
          f = bsdfEval(v, d);
          if (f > 0.0) {
            Hit h = closestHit(v.origin, d, k < 0 ? INF : dist * (1.0 - SHADOW_EPS), k);
            if (h.kind == NONE) {
              L = k < 0 ? uEnv : uLightCorner[k].w;
              light = k;
            }
          }
        }
      }
    }
  } else {
    float u1 = rand();
    float u2 = rand();
    if (t == T_BSDF) {
      float lz;
      d = bsdfSample(v, u1, u2, lz);
      cosT = v.glossy ? dot(d, v.n) : lz;
      pdfW = v.glossy ? bsdfPdf(v, d) : (lz > 0.0 ? lz * INV_PI : 0.0);
    } else {
      vec3 l = t == T_UNIFORM ? uniformHemisphere(u1, u2) : cosineHemisphere(u1, u2);
      cosT = l.z;
      d = toWorld(v.nt, v.nb, v.n, l);
      pdfW = t == T_UNIFORM ? INV_TWO_PI : (cosT > 0.0 ? cosT * INV_PI : 0.0);
    }
    f = cosT > 0.0 ? bsdfEval(v, d) : 0.0;
    if (f > 0.0 && pdfW > 0.0) {
      Hit h = closestHit(v.origin, d, INF, -1);
      if (h.kind == NONE) {
        if (uEnv > 0.0) {
          L = uEnv;
          light = -1;
        }
      } else if (h.kind == LIGHT) {
        lp = h.p;
        cosL = -dot(d, h.n);
        if (cosL > 0.0) {
          L = uLightCorner[h.index].w;
          light = h.index;
        }
      }
    }
  }
  float contrib = f * L;
  if (!(contrib > 0.0) || !(pdfW > 0.0)) return 0.0;
  float factor = 1.0;
  if (mis) {
    float other = t == T_BSDF ? lightPdf(v.p, light, lp) : bsdfPdf(v, d);
    factor = 2.0 * misWeight(uStrategy == T_MIS_BALANCE, pdfW, other);
  }
  float term = factor * contrib * cosT / pdfW;
  if (uBias == 2) term = min(term, CLAMP_MAX);
  else if (uBias == 1 && t == T_AREA && cosL > 0.0) term = term / cosL;
  return term;
}

float radiance(vec3 o, vec3 d, int index) {
  Hit h = closestHit(o, d, INF, -1);
  if (h.kind == NONE) return uEnv;
  if (h.kind == LIGHT) return dot(h.n, d) < 0.0 ? uLightCorner[h.index].w : 0.0;
  Vtx v = shade(h, d);
  float L = 0.0;
  float beta = 1.0;
  for (int depth = 1; depth <= 8; depth++) {
    L += beta * directSample(v, index);
    if (depth >= uBounces) break;
    float u1 = rand();
    float u2 = rand();
    float lz;
    vec3 w = bsdfSample(v, u1, u2, lz);
    float c = dot(w, v.n);
    float f = bsdfEval(v, w);
    float pdf = bsdfPdf(v, w);
    if (!(f > 0.0 && c > 0.0 && pdf > 0.0)) break;
    beta *= f * c / pdf;
    if (depth >= 3) {
      float q = min(1.0, beta);
      if (!(rand() < q)) break;
      beta /= q;
    }
    Hit next = closestHit(v.origin, w, INF, -1);
    if (next.kind == NONE || next.kind == LIGHT) break;
    v = shade(next, w);
  }
  return L;
}

out vec4 sums;

void main() {
  ivec2 fc = ivec2(gl_FragCoord.xy);
  // the target's row j is the image's row j from the top: read back, it is the CPU's row-major order
  rngInit(uint(fc.y * uRes + fc.x), uSample, uSeed);
  float sx = rand();
  float sy = rand();
  float res = float(uRes);
  float x = (2.0 * (float(fc.x) + sx) / res - 1.0) * uScale.x;
  float y = (1.0 - 2.0 * (float(fc.y) + sy) / res) * uScale.y;
  vec3 d = normalize(uFwd + x * uRight + y * uUp);
  float L = radiance(uEye, d, int(uSample));
  vec4 prev = texelFetch(uAccum, fc, 0);
  float yk = L - prev.b;
  float t = prev.g + yk;
  float c = (t - prev.g * uOne) - yk;
  sums = vec4(prev.r + L, t, c, prev.a + L * L);
}
`;
