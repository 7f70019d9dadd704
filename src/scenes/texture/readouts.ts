/**
 * What the texture scene reports: its contract readouts, and whether the page shows the exam's own
 * question, with the figures the key prints for it (quoted only to compare with the live values).
 */
import type { LookupOptions } from '../../core/texture';
import type { GridSource, Lookup } from './model';
import type { SphereModel } from './sphere';

/** The contract readouts of the scene (numbers, or null where they do not apply). */
export interface TextureReadouts {
  nearest: number;
  bilinear: number;
  sphereU: number | null;
  sphereV: number | null;
  sphereBilinear: number | null;
}

/** The query's part of the readouts (nearest, bilinear). */
export function queryReadouts(q: Lookup): Pick<TextureReadouts, 'nearest' | 'bilinear'> {
  return { nearest: q.near.value, bilinear: q.bil.value };
}

/** The sphere's part of the readouts (u, v and the bilinear value there; null without a point). */
export function sphereReadouts(
  sphere: SphereModel,
): Pick<TextureReadouts, 'sphereU' | 'sphereV' | 'sphereBilinear'> {
  return {
    sphereU: sphere.ok ? sphere.chosen.u : null,
    sphereV: sphere.ok ? sphere.chosen.v : null,
    sphereBilinear: sphere.ok ? sphere.chosen.bil.value : null,
  };
}

export function readouts(q: Lookup, sphere: SphereModel): TextureReadouts {
  return { ...queryReadouts(q), ...sphereReadouts(sphere) };
}

/**
 * True when the sphere part is the exam's Q3(c): the exam's grid and settings, and a point whose
 * direction gives (φ, θ) = (π/4, π/4) to 1e-12. The scene then compares with the key's figures.
 */
export function isExamSphere(src: GridSource, opts: LookupOptions, sphere: SphereModel): boolean {
  return (
    src.isExam &&
    opts.align === 'corner' &&
    !opts.vflip &&
    sphere.ok &&
    Math.abs(sphere.phi - Math.PI / 4) < 1e-12 &&
    Math.abs(sphere.theta - Math.PI / 4) < 1e-12
  );
}

/**
 * The figures the exam's answer key prints for Q3 (quoted only to compare with the live
 * computation, never shown in their place), with the number of decimals the key prints.
 */
export const KEY_PRINTED = {
  nearest: { value: 18, decimals: 0 },
  cu: { value: 17.6, decimals: 1 },
  cl: { value: 22.6, decimals: 1 },
  bilinear: { value: 17.8, decimals: 1 },
  sphereU: { value: 0.125, decimals: 3 },
  sphereV: { value: 0.25, decimals: 2 },
  sphere: { value: 16.5, decimals: 1 },
  sphereRaw: { value: 8.44, decimals: 2 },
} as const;

/** Does the computed value, rounded as the key rounds, equal the key's printed figure? */
export function agreesWithKey(computed: number, printed: { value: number; decimals: number }): boolean {
  return Number(computed.toFixed(printed.decimals)) === printed.value;
}

/** True when the query is the exam's Q3 (a)/(b): the exam's grid and settings at (0.4, 0.24). */
export function isExamQuery(src: GridSource, opts: LookupOptions, u: number, v: number): boolean {
  return src.isExam && opts.align === 'corner' && !opts.vflip && u === 0.4 && v === 0.24;
}
