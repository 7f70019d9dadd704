/**
 * The sampling techniques on the GPU, in GLSL, each the core's own in float32 (core/sampling and
 * core/lights): uniform and cosine hemispheres (the latter by Shirley and Chiu's concentric disk and
 * Malley's projection), the Phong lobe in log space (its expm1 by Kahan's trick, GLSL having none),
 * the BSDF (Lambert or the modified Phong BRDF) with its sampling and density, and the emitters:
 * one picked uniformly, then a point by area or uniformly in its solid angle (Ureña, Fajardo and
 * King, EGSR 2013, as pbrt-v4's SampleSphericalRectangle writes it), or the environment by a
 * uniform direction.
 *
 * Solid-angle sampling subtracts 2π from the sum of four angles, which float32 can afford only for
 * solid angles that are neither tiny nor nearly a hemisphere: outside [3·10⁻⁴, 6.22] sr the light is
 * sampled by area and the density said to be that of area sampling, in solid angle (pbrt-v4's
 * MinSphericalSampleArea and MaxSphericalSampleArea for float; the core's float64 limit is 10⁻⁶).
 * Either way the estimator is unbiased; only its variance differs from the CPU's there. The solid
 * angle itself is Van Oosterom and Strackee's formula over two triangles (core/geometry/solidAngle).
 */
export const GLSL_SAMPLING = `
const float SPH_MIN = 3e-4;
const float SPH_MAX = 6.22;
const float ONE_MINUS_EPS = 0.99999994;

vec3 uniformHemisphere(float u1, float u2) {
  float z = u1;
  float r = sqrt(max(0.0, (1.0 - z) * (1.0 + z)));
  float phi = TWO_PI * u2;
  return vec3(r * cos(phi), r * sin(phi), z);
}

vec3 cosineHemisphere(float u1, float u2) {
  float ox = 2.0 * u1 - 1.0;
  float oy = 2.0 * u2 - 1.0;
  vec2 d = vec2(0.0);
  if (ox != 0.0 || oy != 0.0) {
    float r;
    float th;
    if (abs(ox) > abs(oy)) {
      r = ox;
      th = 0.25 * PI * (oy / ox);
    } else {
      r = oy;
      th = 0.5 * PI - 0.25 * PI * (ox / oy);
    }
    d = r * vec2(cos(th), sin(th));
  }
  float l = length(d);
  return vec3(d, sqrt(max(0.0, (1.0 - l) * (1.0 + l))));
}

float expm1f(float x) {
  float u = exp(x);
  if (u == 1.0) return x;
  float um = u - 1.0;
  if (um == -1.0) return -1.0;
  return um * x / log(u);
}

vec3 phongLobe(float u1, float u2, float e) {
  float lc = log(max(u1, 1e-30)) / (max(e, 0.0) + 1.0);
  float c = exp(lc);
  float s = sqrt(max(0.0, -expm1f(2.0 * lc)));
  float phi = TWO_PI * u2;
  return vec3(s * cos(phi), s * sin(phi), c);
}

float phongPdf(float c, float e) {
  return c > 0.0 ? (max(e, 0.0) + 1.0) * INV_TWO_PI * pow(c, max(e, 0.0)) : 0.0;
}

float bsdfEval(Vtx v, vec3 w) {
  if (!(dot(w, v.n) > 0.0)) return 0.0;
  if (!v.glossy) return v.albedo * INV_PI;
  float ca = dot(w, v.r);
  return ca > 0.0 ? v.ks * (v.expo + 2.0) * INV_TWO_PI * pow(ca, v.expo) : 0.0;
}

float bsdfPdf(Vtx v, vec3 w) {
  if (!v.glossy) {
    float z = dot(w, v.n);
    return z > 0.0 ? z * INV_PI : 0.0;
  }
  return phongPdf(dot(w, v.r), v.expo);
}

// the lobe's own z (cos to its axis) comes back in lz
vec3 bsdfSample(Vtx v, float u1, float u2, out float lz) {
  vec3 l = v.glossy ? phongLobe(u1, u2, v.expo) : cosineHemisphere(u1, u2);
  lz = l.z;
  return v.glossy ? toWorld(v.rt, v.rb, v.r, l) : toWorld(v.nt, v.nb, v.n, l);
}

float triangleSolidAngle(vec3 a, vec3 e1, vec3 e2) {
  vec3 b = a + e1;
  vec3 c = a + e2;
  float num = abs(dot(a, cross(e1, e2)));
  if (!(num > 0.0)) return 0.0;
  float la = length(a);
  float lb = length(b);
  float lc = length(c);
  float den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2.0 * atan(num, den);
}

float angleBetween(vec3 a, vec3 b) {
  if (dot(a, b) < 0.0) return PI - 2.0 * asin(min(1.0, length(a + b) / 2.0));
  return 2.0 * asin(min(1.0, length(a - b) / 2.0));
}

struct SphRect {
  vec3 p;
  vec3 z;
  float x0;
  float x1;
  float y0;
  float y1;
  float z0;
  float b0;
  float b1;
  float g0;
  float g1;
  float g2;
  float g3;
  float omega;
};

SphRect sphRect(int k, vec3 p) {
  SphRect q;
  vec3 ex = uLightEx[k].xyz;
  vec3 ey = uLightEy[k].xyz;
  float w = uLightEx[k].w;
  float h = uLightEy[k].w;
  vec3 z = cross(ex, ey);
  vec3 d = uLightCorner[k].xyz - p;
  q.p = p;
  q.x0 = dot(d, ex);
  q.y0 = dot(d, ey);
  q.z0 = dot(d, z);
  if (q.z0 > 0.0) {
    q.z0 = -q.z0;
    z = -z;
  }
  q.z = z;
  q.x1 = q.x0 + w;
  q.y1 = q.y0 + h;
  vec3 a = w * ex;
  vec3 b = h * ey;
  q.omega = w * h > 0.0 ? min(TWO_PI, triangleSolidAngle(d, a, a + b) + triangleSolidAngle(d, a + b, b)) : 0.0;
  float l0 = length(vec2(q.z0, q.y0));
  float l1 = length(vec2(q.z0, q.x1));
  float l2 = length(vec2(q.z0, q.y1));
  float l3 = length(vec2(q.z0, q.x0));
  q.g0 = 0.0;
  q.g1 = 0.0;
  q.g2 = 0.0;
  q.g3 = 0.0;
  q.b0 = 0.0;
  q.b1 = 0.0;
  if (q.omega > 0.0 && l0 > 0.0 && l1 > 0.0 && l2 > 0.0 && l3 > 0.0) {
    vec3 n0 = vec3(0.0, q.z0 / l0, -q.y0 / l0);
    vec3 n1 = vec3(-q.z0 / l1, 0.0, q.x1 / l1);
    vec3 n2 = vec3(0.0, -q.z0 / l2, q.y1 / l2);
    vec3 n3 = vec3(q.z0 / l3, 0.0, -q.x0 / l3);
    q.g0 = angleBetween(-n0, n1);
    q.g1 = angleBetween(-n1, n2);
    q.g2 = angleBetween(-n2, n3);
    q.g3 = angleBetween(-n3, n0);
    q.b0 = n0.z;
    q.b1 = n2.z;
  }
  return q;
}

bool sphRectByArea(SphRect q) {
  return !(q.omega >= SPH_MIN) || q.omega > SPH_MAX;
}

vec3 sampleSphRect(SphRect q, int k, float u1, float u2) {
  vec3 ex = uLightEx[k].xyz;
  vec3 ey = uLightEy[k].xyz;
  if (sphRectByArea(q)) return uLightCorner[k].xyz + u1 * uLightEx[k].w * ex + u2 * uLightEy[k].w * ey;
  float au = u1 * (q.g0 + q.g1 - TWO_PI) + (u1 - 1.0) * (q.g2 + q.g3);
  float fu = (cos(au) * q.b0 - q.b1) / sin(au);
  float cu = (fu < 0.0 ? -1.0 : 1.0) / sqrt(fu * fu + q.b0 * q.b0);
  cu = clamp(cu, -ONE_MINUS_EPS, ONE_MINUS_EPS);
  if (isnan(cu)) cu = 0.0;
  float xu = -(cu * q.z0) / sqrt((1.0 - cu) * (1.0 + cu));
  if (!(xu >= q.x0)) xu = q.x0;
  else if (xu > q.x1) xu = q.x1;
  float dd2 = xu * xu + q.z0 * q.z0;
  float dd = sqrt(dd2);
  float h0 = q.y0 / sqrt(dd2 + q.y0 * q.y0);
  float h1 = q.y1 / sqrt(dd2 + q.y1 * q.y1);
  float hv = h0 + u2 * (h1 - h0);
  float den = (1.0 - hv) * (1.0 + hv);
  float yv = den > 0.0 ? (hv * dd) / sqrt(den) : q.y1;
  if (!(yv >= q.y0)) yv = q.y0;
  else if (yv > q.y1) yv = q.y1;
  return q.p + xu * ex + yv * ey + q.z0 * q.z;
}

// density per steradian of sampleSphRect at the point x of light k (0 off the light)
float sphRectPdf(SphRect q, int k, vec3 x) {
  if (!(q.omega > 0.0)) return 0.0;
  vec3 s = x - uLightCorner[k].xyz;
  float w = uLightEx[k].w;
  float h = uLightEy[k].w;
  vec3 c = abs(uLightCorner[k].xyz);
  float tol = 1e-5 * max(max(1.0, max(w, h)), max(abs(q.z0), max(c.x, max(c.y, c.z))));
  float a = dot(s, uLightEx[k].xyz);
  float b = dot(s, uLightEy[k].xyz);
  float e = dot(s, uLightN[k].xyz);
  if (!(abs(e) <= tol && a >= -tol && a <= w + tol && b >= -tol && b <= h + tol)) return 0.0;
  if (!sphRectByArea(q)) return 1.0 / q.omega;
  vec3 r = x - q.p;
  float r2 = dot(r, r);
  float rl = sqrt(r2);
  float cosL = rl > 0.0 ? abs(dot(r, uLightN[k].xyz)) / rl : 0.0;
  return cosL > 0.0 ? r2 / (uLightN[k].w * cosL) : 0.0;
}

int emitterCount() {
  return uLightCount + (uEnv > 0.0 ? 1 : 0);
}

// pick an emitter with u0 and a point on it (by area, or by solid angle from p) with u1, u2;
// light = -1 is the environment (x then the direction); pdf in the technique's own measure
bool sampleEmitter(vec3 p, bool byArea, float u0, float u1, float u2, out int light, out vec3 x, out float pdf) {
  int kk = emitterCount();
  light = -2;
  x = vec3(0.0);
  pdf = 0.0;
  if (kk == 0) return false;
  int k = min(kk - 1, int(floor(u0 * float(kk))));
  if (k == uLightCount) {
    float z = 1.0 - 2.0 * u1;
    float r = sqrt(max(0.0, (1.0 - z) * (1.0 + z)));
    float phi = TWO_PI * u2;
    light = -1;
    x = vec3(r * cos(phi), r * sin(phi), z);
    pdf = INV_FOUR_PI / float(kk);
    return true;
  }
  light = k;
  if (byArea) {
    x = uLightCorner[k].xyz + u1 * uLightEx[k].w * uLightEx[k].xyz + u2 * uLightEy[k].w * uLightEy[k].xyz;
    pdf = uLightN[k].w > 0.0 ? 1.0 / (float(kk) * uLightN[k].w) : 0.0;
  } else {
    SphRect q = sphRect(k, p);
    x = sampleSphRect(q, k, u1, u2);
    pdf = sphRectPdf(q, k, x) / float(kk);
  }
  return true;
}

// density per steradian of the solid-angle light technique at light k's point x (k = -1: the environment)
float lightPdf(vec3 p, int k, vec3 x) {
  int kk = emitterCount();
  if (kk == 0) return 0.0;
  if (k < 0) return uEnv > 0.0 ? INV_FOUR_PI / float(kk) : 0.0;
  return sphRectPdf(sphRect(k, p), k, x) / float(kk);
}
`;
