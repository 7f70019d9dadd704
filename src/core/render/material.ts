/**
 * The shading point and its BSDF: the Lambertian floor and sphere (f = albedo/π; the sphere's
 * albedo from its texture) and the glossy plates (the modified Phong BRDF of Lafortune & Willems
 * 1994, f = ks (e + 2)/(2π) cosᵉα, α the angle between ωᵢ and the mirror direction of ωₒ; energy
 * conserving for ks ≤ 1). Each BSDF has its sampling technique (`bsdf`): the cosine lobe about the
 * normal for Lambert, the Phong lobe cosᵉα about the mirror direction for the plates; their pdfs
 * are per unit solid angle. Source: pbrt-v4 ch. 9 (BSDFs) and §13.1 (sampling the BSDF).
 */
import { bilinear } from '../texture/bilinear';
import { nearest } from '../texture/nearest';
import { EXAM_LOOKUP } from '../texture/lookupOptions';
import { sphericalUV } from '../texture/spherical';
import { cosineHemispherePdf, sampleCosineHemisphere } from '../sampling/cosineHemisphere';
import { phongLobePdf, samplePhongLobe } from '../sampling/phongLobe';
import { frameAround, newFrame, toWorld, type Frame } from './frame';
import { offsetOrigin, type Hit } from './intersect';
import { texelAlbedo, type RenderScene } from './scene';

const INV_PI = 1 / Math.PI;
const INV_TWO_PI = 1 / (2 * Math.PI);

/** A shading point: where, which way it faces, what it is made of. Filled in place per vertex. */
export interface Vertex {
  px: number;
  py: number;
  pz: number;
  /** Shading normal, turned towards the outgoing direction ωₒ (so both sides of a surface shade). */
  nx: number;
  ny: number;
  nz: number;
  /** ωₒ: the unit direction back along the incoming ray. */
  wox: number;
  woy: number;
  woz: number;
  glossy: boolean;
  /** Lambertian albedo (0 for a plate). */
  albedo: number;
  /** Phong exponent and specular albedo (plates). */
  exponent: number;
  ks: number;
  /** Frames about the normal and about the mirror direction of ωₒ. */
  frameN: Frame;
  frameR: Frame;
  /** The origin of rays leaving the point (p nudged along n). */
  origin: Float64Array;
  /** Texture coordinates and looked-up value on the sphere (NaN elsewhere). */
  u: number;
  v: number;
  texel: number;
}

export function newVertex(): Vertex {
  return {
    px: 0,
    py: 0,
    pz: 0,
    nx: 0,
    ny: 0,
    nz: 1,
    wox: 0,
    woy: 0,
    woz: 1,
    glossy: false,
    albedo: 0,
    exponent: 0,
    ks: 0,
    frameN: newFrame(),
    frameR: newFrame(),
    origin: new Float64Array(3),
    u: NaN,
    v: NaN,
    texel: NaN,
  };
}

/**
 * Make `v` the shading point of a surface hit (floor, sphere or plate) seen along the unit ray
 * direction d. Lights and misses are not shading points: their radiance is the emitted one.
 */
export function shadeVertex(
  scene: RenderScene,
  hit: Hit,
  dx: number,
  dy: number,
  dz: number,
  v: Vertex,
): void {
  v.px = hit.px;
  v.py = hit.py;
  v.pz = hit.pz;
  v.wox = -dx;
  v.woy = -dy;
  v.woz = -dz;
  const flip = hit.nx * dx + hit.ny * dy + hit.nz * dz > 0 ? -1 : 1;
  v.nx = flip * hit.nx;
  v.ny = flip * hit.ny;
  v.nz = flip * hit.nz;
  v.u = NaN;
  v.v = NaN;
  v.texel = NaN;
  v.glossy = hit.kind === 'plate';
  v.albedo = 0;
  v.exponent = 0;
  v.ks = 0;
  if (hit.kind === 'plate') {
    const plate = scene.plates[hit.index];
    v.exponent = plate.exponent;
    v.ks = plate.ks;
  } else if (hit.kind === 'floor') {
    v.albedo = scene.floorAlbedo ?? 0;
  } else if (hit.kind === 'sphere' && scene.sphere) {
    const s = scene.sphere;
    v.albedo = s.albedo;
    if (s.texture) {
      const uv = sphericalUV(hit.px - s.center[0], hit.py - s.center[1], hit.pz - s.center[2]);
      if (uv.ok) {
        v.u = uv.u;
        v.v = uv.v;
        v.texel =
          s.filter === 'nearest'
            ? nearest(s.texture, uv.u, uv.v, EXAM_LOOKUP)
            : bilinear(s.texture, uv.u, uv.v, EXAM_LOOKUP);
        v.albedo = texelAlbedo(v.texel, s.texMin, s.texMax);
      }
    }
  }
  frameAround(v.nx, v.ny, v.nz, v.frameN);
  const c = v.nx * v.wox + v.ny * v.woy + v.nz * v.woz;
  frameAround(2 * c * v.nx - v.wox, 2 * c * v.ny - v.woy, 2 * c * v.nz - v.woz, v.frameR);
  offsetOrigin(v.px, v.py, v.pz, v.nx, v.ny, v.nz, v.origin);
}

/** cos of the angle between ωᵢ and the mirror direction (the Phong lobe's axis). */
function cosMirror(v: Vertex, x: number, y: number, z: number): number {
  return x * v.frameR.nx + y * v.frameR.ny + z * v.frameR.nz;
}

/** The BSDF f(ωₒ, ωᵢ) for the unit direction ωᵢ; 0 below the surface. */
export function bsdfEval(v: Vertex, x: number, y: number, z: number): number {
  if (!(x * v.nx + y * v.ny + z * v.nz > 0)) return 0;
  if (!v.glossy) return v.albedo * INV_PI;
  const ca = cosMirror(v, x, y, z);
  return ca > 0 ? v.ks * (v.exponent + 2) * INV_TWO_PI * Math.pow(ca, v.exponent) : 0;
}

/** The density of {@link bsdfSample} per unit solid angle at the unit direction ωᵢ. */
export function bsdfPdf(v: Vertex, x: number, y: number, z: number): number {
  if (!v.glossy) return cosineHemispherePdf(0, 0, x * v.nx + y * v.ny + z * v.nz);
  return phongLobePdf(0, 0, cosMirror(v, x, y, z), v.exponent);
}

/**
 * Sample ωᵢ by the material's lobe (cosine about n, or Phong about the mirror direction) from
 * (u1, u2) ∈ [0, 1)², into out[0..2]; returns the local z of the sample in its own frame (its cos
 * to the lobe's axis). A Phong sample can fall below the surface: then f = 0 there.
 */
export function bsdfSample(v: Vertex, u1: number, u2: number, out: Float64Array): number {
  const f = v.glossy ? v.frameR : v.frameN;
  if (v.glossy) samplePhongLobe(u1, u2, v.exponent, out);
  else sampleCosineHemisphere(u1, u2, out);
  const lz = out[2];
  toWorld(f, out[0], out[1], lz, out);
  return lz;
}
