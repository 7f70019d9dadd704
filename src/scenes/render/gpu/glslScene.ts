/**
 * The scene on the GPU, in GLSL: its uniforms (packed by ./sceneUniforms), the closest hit of a ray
 * among the floor, the sphere, the lights and the plates, and the shading point with its frames and
 * its texture lookup. The same arithmetic as the core's float64 code, in float32:
 * core/render/intersect (the floor, the sphere by the stable quadratic of Ray Tracing Gems ch. 7,
 * the rectangles by their plane and edges), core/render/material (the shading normal turned towards
 * the eye, the Phong lobe's mirror frame), core/render/frame (Duff et al.'s branch-free basis) and
 * core/texture (the exam's spherical (u, v), its corner-aligned nodes under clamp, bilinear or
 * nearest with ties up, the texel grid read texel by texel with texelFetch: the core's own lookup,
 * not the GPU's sampler). Secondary rays start 10⁻⁴ · max(1, |p|∞) off the surface, not the CPU's
 * 10⁻⁹: float32 carries about 7 digits.
 */
export const GLSL_SCENE = `
const float PI = 3.14159265358979;
const float TWO_PI = 6.28318530717959;
const float INV_PI = 0.318309886183791;
const float INV_TWO_PI = 0.159154943091895;
const float INV_FOUR_PI = 0.0795774715459477;
const float INF = 1e30;
const float RAY_OFFSET = 1e-4;
const int NONE = 0;
const int FLOOR = 1;
const int SPHERE = 2;
const int LIGHT = 3;
const int PLATE = 4;

uniform vec3 uEye;
uniform vec3 uFwd;
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec2 uScale;
uniform int uRes;
uniform float uFloor;
uniform vec4 uSphere;
uniform float uSphereAlbedo;
uniform int uTexFilter;
uniform vec2 uTexRange;
uniform highp sampler2D uTex;
uniform int uLightCount;
uniform vec4 uLightCorner[4];
uniform vec4 uLightEx[4];
uniform vec4 uLightEy[4];
uniform vec4 uLightN[4];
uniform int uPlateCount;
uniform vec4 uPlateCorner[4];
uniform vec4 uPlateEx[4];
uniform vec4 uPlateEy[4];
uniform vec4 uPlateN[4];
uniform float uEnv;

struct Hit {
  int kind;
  int index;
  float t;
  vec3 p;
  vec3 n;
};

float hitRect(vec4 corner, vec4 ex, vec4 ey, vec4 n, vec3 o, vec3 d) {
  if (!(ex.w * ey.w > 0.0)) return INF;
  float dn = dot(d, n.xyz);
  if (dn == 0.0) return INF;
  float t = dot(corner.xyz - o, n.xyz) / dn;
  if (!(t > 0.0)) return INF;
  vec3 q = o + t * d - corner.xyz;
  float a = dot(q, ex.xyz);
  float b = dot(q, ey.xyz);
  if (a < 0.0 || a > ex.w || b < 0.0 || b > ey.w) return INF;
  return t;
}

float hitSphere(vec3 o, vec3 d) {
  if (!(uSphere.w > 0.0)) return INF;
  vec3 f = o - uSphere.xyz;
  float bh = dot(f, d);
  vec3 l = f - bh * d;
  float r2 = uSphere.w * uSphere.w;
  float disc = r2 - dot(l, l);
  if (disc < 0.0) return INF;
  float q = -bh - (bh >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
  if (q == 0.0) return 0.0;
  float t0 = (dot(f, f) - r2) / q;
  float t1 = q;
  if (t0 > t1) {
    float s = t0;
    t0 = t1;
    t1 = s;
  }
  if (t1 < 0.0) return INF;
  return t0 >= 0.0 ? t0 : t1;
}

// the closest hit before tMax; light number \`skip\` is left out (a shadow ray towards it: a flat
// light cannot shade itself, and the ray's offset origin may sit a little beyond its plane)
Hit closestHit(vec3 o, vec3 d, float tMax, int skip) {
  Hit h;
  h.kind = NONE;
  h.index = 0;
  h.t = tMax;
  h.p = vec3(0.0);
  h.n = vec3(0.0, 0.0, 1.0);
  if (uFloor >= 0.0 && d.z != 0.0) {
    float t = -o.z / d.z;
    if (t >= 0.0 && t < h.t) {
      h.t = t;
      h.kind = FLOOR;
    }
  }
  float ts = hitSphere(o, d);
  if (ts < h.t) {
    h.t = ts;
    h.kind = SPHERE;
  }
  for (int k = 0; k < 4; k++) {
    if (k >= uLightCount) break;
    if (k == skip) continue;
    float t = hitRect(uLightCorner[k], uLightEx[k], uLightEy[k], uLightN[k], o, d);
    if (t < h.t) {
      h.t = t;
      h.kind = LIGHT;
      h.index = k;
    }
  }
  for (int k = 0; k < 4; k++) {
    if (k >= uPlateCount) break;
    float t = hitRect(uPlateCorner[k], uPlateEx[k], uPlateEy[k], uPlateN[k], o, d);
    if (t < h.t) {
      h.t = t;
      h.kind = PLATE;
      h.index = k;
    }
  }
  if (h.kind == NONE) return h;
  h.p = o + h.t * d;
  if (h.kind == FLOOR) {
    h.p.z = 0.0;
  } else if (h.kind == SPHERE) {
    h.n = normalize((h.p - uSphere.xyz) / uSphere.w);
  } else if (h.kind == LIGHT) {
    h.n = uLightN[h.index].xyz;
  } else {
    h.n = uPlateN[h.index].xyz;
  }
  return h;
}

struct Vtx {
  vec3 p;
  vec3 n;
  vec3 wo;
  bool glossy;
  float albedo;
  float expo;
  float ks;
  vec3 nt;
  vec3 nb;
  vec3 r;
  vec3 rt;
  vec3 rb;
  vec3 origin;
};

void frameAround(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 toWorld(vec3 t, vec3 b, vec3 n, vec3 l) {
  return l.x * t + l.y * b + l.z * n;
}

float texelAt(int i, int j) {
  return texelFetch(uTex, ivec2(i, j), 0).r;
}

float textureAlbedo(vec3 q) {
  float phi = (q.x == 0.0 && q.y == 0.0) ? 0.0 : atan(q.y, q.x);
  if (phi < 0.0) phi += TWO_PI;
  if (phi >= TWO_PI) phi = 0.0;
  float u = phi / TWO_PI;
  if (u >= 1.0) u = 0.0;
  float v = atan(length(q.xy), q.z) / PI;
  ivec2 size = textureSize(uTex, 0);
  float su = clamp(u, 0.0, 1.0) * float(size.x - 1);
  float sv = clamp(v, 0.0, 1.0) * float(size.y - 1);
  float value;
  if (uTexFilter == 2) {
    value = texelAt(int(floor(su + 0.5)), int(floor(sv + 0.5)));
  } else {
    int i0 = min(int(floor(su)), size.x - 2);
    int j0 = min(int(floor(sv)), size.y - 2);
    float fu = su - float(i0);
    float fv = sv - float(j0);
    float lower = (1.0 - fu) * texelAt(i0, j0) + fu * texelAt(i0 + 1, j0);
    float upper = (1.0 - fu) * texelAt(i0, j0 + 1) + fu * texelAt(i0 + 1, j0 + 1);
    value = (1.0 - fv) * lower + fv * upper;
  }
  float t = uTexRange.y > uTexRange.x ? (value - uTexRange.x) / (uTexRange.y - uTexRange.x) : 0.5;
  return 0.2 + 0.6 * clamp(t, 0.0, 1.0);
}

Vtx shade(Hit h, vec3 d) {
  Vtx v;
  v.p = h.p;
  v.wo = -d;
  v.n = dot(h.n, d) > 0.0 ? -h.n : h.n;
  v.glossy = h.kind == PLATE;
  v.albedo = 0.0;
  v.expo = 0.0;
  v.ks = 0.0;
  if (h.kind == PLATE) {
    v.expo = uPlateCorner[h.index].w;
    v.ks = uPlateN[h.index].w;
  } else if (h.kind == FLOOR) {
    v.albedo = uFloor;
  } else if (h.kind == SPHERE) {
    v.albedo = uTexFilter > 0 ? textureAlbedo(h.p - uSphere.xyz) : uSphereAlbedo;
  }
  frameAround(v.n, v.nt, v.nb);
  float c = dot(v.n, v.wo);
  v.r = 2.0 * c * v.n - v.wo;
  frameAround(v.r, v.rt, v.rb);
  float e = RAY_OFFSET * max(1.0, max(abs(v.p.x), max(abs(v.p.y), abs(v.p.z))));
  v.origin = v.p + e * v.n;
  return v;
}
`;
