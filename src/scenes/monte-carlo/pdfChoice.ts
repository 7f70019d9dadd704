/**
 * The sampling densities p(x) the scene offers on [a, b] (uniform, linear ramp, p ∝ f, typed),
 * built from the core's 1D pdfs, and the one the race's importance lane uses.
 */
import {
  customPdf1D,
  linearPdf1D,
  proportionalPdf1D,
  squarePdf1D,
  uniformPdf1D,
  type Pdf1D,
} from '../../core/sampling/pdf1d';
import type { Failure } from '../../core/failure';
import { formatPlain } from '../../core/format';
import { squareShift, type Fn1 } from './integral';
import type { PdfKind } from './params';

/** A usable sampling density for the scene, or the reason it cannot be used. */
export type PdfChoice =
  | {
      ok: true;
      kind: PdfKind;
      /** Sampler (for drawn samples): its pdf is the density the samples really have. */
      sampler: Pdf1D;
      /** The exact normalized density, used for given samples and the drawn curve. */
      density: Fn1;
      /** Human description, e.g. "p(x) = 3(x + 2)²/56 (closed form)". */
      label: string;
      /** A note (e.g. the tabulation, or a fallback). */
      note: string | null;
    }
  | Failure<PdfKind>;

/**
 * Build the chosen pdf on [a, b] for the integrand f:
 * - uniform: 1/(b − a);
 * - linear: the ramp through |f(a)| and |f(b)| (core `linearPdf1D`);
 * - proportional: p ∝ f, in closed form when f is (x + c)², else tabulated p ∝ |f| (4096 bins);
 * - custom: the typed pdf, validated and normalized (core `customPdf1D`).
 */
export function choosePdf(
  kind: PdfKind,
  fSrc: string,
  f: Fn1,
  a: number,
  b: number,
  custom: Fn1 | null,
): PdfChoice {
  switch (kind) {
    case 'uniform': {
      const s = uniformPdf1D(a, b);
      return {
        ok: true,
        kind,
        sampler: s,
        density: s.pdf,
        label: `p(x) = 1/(b − a) = ${formatPlain(1 / (b - a))}`,
        note: null,
      };
    }
    case 'linear': {
      const w0 = Math.abs(f(a));
      const w1 = Math.abs(f(b));
      if (!(Number.isFinite(w0) && Number.isFinite(w1) && w0 + w1 > 0)) {
        return {
          ok: false,
          kind,
          message: `The linear pdf is the ramp through |f(a)| and |f(b)|, but these are ${formatPlain(w0)} and ${formatPlain(w1)}: no ramp to sample. Choose another pdf.`,
        };
      }
      const s = linearPdf1D(a, b, w0, w1);
      return {
        ok: true,
        kind,
        sampler: s,
        density: s.pdf,
        label: `p(x) ∝ ramp from |f(a)| = ${formatPlain(w0)} to |f(b)| = ${formatPlain(w1)}`,
        note: null,
      };
    }
    case 'proportional': {
      const c = squareShift(fSrc);
      if (c !== null) {
        const s = squarePdf1D(a, b, c);
        const A = a + c;
        const B = b + c;
        const D = (b - a) * (B * B + A * B + A * A);
        const cs = c === 0 ? 'x' : `x ${c > 0 ? '+' : '−'} ${formatPlain(Math.abs(c))}`;
        return {
          ok: true,
          kind,
          sampler: s,
          density: s.pdf,
          label: `p(x) = 3(${cs})²/${formatPlain(D)} (closed form, inverted by a cube root)`,
          note: null,
        };
      }
      const r = proportionalPdf1D(f, a, b);
      if (!r.ok) return { ok: false, kind, message: `p ∝ |f| cannot be built: ${r.message}` };
      return {
        ok: true,
        kind,
        sampler: r.pdf,
        density: r.density,
        label: `p(x) = |f(x)| / ${formatPlain(r.norm)}`,
        note: 'Samples are drawn from a 4096-bin table of |f| (each bin holds the exact mass of |f| over it); the estimator divides by the tabulated density, which the samples really follow, so it stays unbiased.',
      };
    }
    case 'custom': {
      if (!custom) return { ok: false, kind, message: 'Type a pdf p(x) for the custom strategy.' };
      const r = customPdf1D(custom, a, b, f);
      if (!r.ok) return { ok: false, kind, message: `This pdf cannot be used: ${r.message}` };
      return {
        ok: true,
        kind,
        sampler: r.pdf,
        density: r.density,
        label: `p(x) = your expression / ${formatPlain(r.norm)} (normalized numerically)`,
        note: 'Samples are drawn from a 4096-bin table of your pdf (exact bin masses); the estimator divides by that tabulated density, so it stays unbiased.',
      };
    }
  }
}

/**
 * The pdf of the race's importance lane: the chosen pdf unless it is uniform, else p ∝ f (null when
 * neither is usable), with the label the race shows for it.
 */
export function importanceLane(
  choice: PdfChoice | null,
  proportional: PdfChoice | null,
): { pdf: Extract<PdfChoice, { ok: true }>; label: string; name: string } | null {
  const pdf = choice?.ok && choice.kind !== 'uniform' ? choice : proportional?.ok ? proportional : null;
  if (!pdf) return null;
  const label =
    pdf.kind === 'proportional' ? 'p ∝ f: ' + pdf.label.replace(/ \(closed form.*\)$/, '') : pdf.label;
  return { pdf, label, name: LANE_NAME[pdf.kind] };
}

/** The importance lane's pdf in a few words (the figures' descriptions). */
const LANE_NAME: Record<PdfKind, string> = {
  uniform: 'uniform',
  proportional: 'p ∝ f',
  linear: 'the linear ramp',
  custom: 'your pdf',
};
