/**
 * The exam's Q4 as the scene shows it: its integrand, limits and four samples, the figures its
 * key prints (only to say where the live computation differs), and the live numbers of the
 * derivations of Q4(a) and Q4(c).
 */
import { formatPlain } from '../../core/format';
import { EXAM_A, EXAM_B, squareShift } from './integral';
import type { SampleTable } from './sampleTable';

/** The exam's four samples (Q4(b)). */
export const EXAM_SAMPLES: readonly number[] = [1.16, 1.98, 0.54, 1.26];
/** The exam's integrand and limits. */
export const EXAM_F = '(x+2)^2';
/**
 * Figures as PRINTED in the answer key for Q4(b) (not used for any computation: only to say where
 * the live computation differs from what the key prints).
 */
export const KEY_PRINTED = { f: [9.98, 18.84, 6.45, 10.26], estimate: 21.45 } as const;

/** Round half away from zero to `d` decimals (how a student writes 9.9856 → 9.99). */
export function roundTo(x: number, d: number): number {
  const k = 10 ** d;
  return (Math.sign(x) * Math.round(Math.abs(x) * k)) / k;
}

/** One comparison of a printed figure with the computed one. */
export interface KeyNote {
  what: string;
  printed: number;
  computed: number;
  /** The computed value rounded the way the key prints (2 decimals). */
  rounded: number;
  agrees: boolean;
}

/**
 * Compare the key's printed Q4(b) figures with the live computation (only when the scene shows the
 * exam's own problem: f = (x + 2)², [0, 2], the exam's four samples in order). Returns [] otherwise.
 */
export function keyComparison(
  fSrc: string,
  a: number,
  b: number,
  xs: readonly number[],
  table: SampleTable,
): KeyNote[] {
  if (!isExamConfig(squareShift(fSrc), a, b, xs)) return [];
  const notes: KeyNote[] = table.rows.map((r, i) => {
    const printed = KEY_PRINTED.f[i];
    const rounded = roundTo(r.f, 2);
    return { what: `f(${formatPlain(r.x)})`, printed, computed: r.f, rounded, agrees: rounded === printed };
  });
  const est = table.uniform.estimate;
  notes.push({
    what: '⟨I⟩ uniform',
    printed: KEY_PRINTED.estimate,
    computed: est,
    rounded: roundTo(est, 2),
    agrees: roundTo(est, 2) === KEY_PRINTED.estimate,
  });
  return notes;
}

/** Whether the page shows the exam's own Q4: f = (x + 2)², [0, 2] and the exam's four samples in order. */
export function isExamConfig(shift: number | null, a: number, b: number, xs: readonly number[]): boolean {
  return (
    shift === 2 &&
    a === EXAM_A &&
    b === EXAM_B &&
    xs.length === EXAM_SAMPLES.length &&
    xs.every((x, i) => x === EXAM_SAMPLES[i])
  );
}

/**
 * Q4(a) for f = (x + c)² on [a, b]: expansion x² + 2c x + c², antiderivative
 * F(x) = x³/3 + c x² + c² x, and F(b) − F(a) term by term.
 */
export function squareAntiderivative(c: number, a: number, b: number) {
  const F = (x: number) => ({ cube: (x * x * x) / 3, lin2: c * x * x, lin: c * c * x });
  const Fb = F(b);
  const Fa = F(a);
  const total = (v: { cube: number; lin2: number; lin: number }) => v.cube + v.lin2 + v.lin;
  return {
    twoC: 2 * c,
    c2: c * c,
    Fb,
    Fa,
    valueB: total(Fb),
    valueA: total(Fa),
    value: total(Fb) - total(Fa),
  };
}

/** Q4(c): the normalization of p ∝ (x + c)² on [a, b]: p = 3(x + c)² / D with D = 3∫f = (b + c)³ − (a + c)³. */
export function squareNormalizer(c: number, a: number, b: number): number {
  return (b + c) ** 3 - (a + c) ** 3;
}
