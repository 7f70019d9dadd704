/**
 * Numbers as the ray–sphere page writes them: for KaTeX (`tx`, `yes`) and for running text (`fmt`).
 * Pure, no DOM.
 */
import { superscript } from '../../../ui/axis';

/** A number for TeX: 6 significant digits, e-notation as × 10^n. */
export function tx(x: number | null, digits = 6): string {
  if (x === null || !Number.isFinite(x)) return '\\text{none}';
  if (x === 0) return '0';
  const ax = Math.abs(x);
  if (ax >= 1e-3 && ax < 1e7) return String(Number(x.toPrecision(digits)));
  const [m, e] = x.toExponential(digits - 1).split('e');
  return `${Number(m)} \\times 10^{${Number(e)}}`;
}

/** A vector for TeX: (x, y, z), 4 significant digits each. */
export const txVec = (p: readonly number[]) => `(${p.map((x) => tx(x, 4)).join(',\\, ')})`;

/** Hit test for a root in TeX: a tick or a cross. */
export const yes = (b: boolean) => (b ? '\\;\\checkmark' : '\\;\\times');

/** A number for text: 6 significant digits, m × 10ⁿ for very large or small, a real minus sign. */
export function fmt(x: number | null): string {
  if (x === null || !Number.isFinite(x)) return 'none';
  if (x === 0) return '0';
  const ax = Math.abs(x);
  let out: string;
  if (ax >= 1e-3 && ax < 1e7) out = String(Number(x.toPrecision(6)));
  else {
    const [m, e] = x.toExponential(5).split('e');
    const ex = superscript(String(Number(e)));
    out = Number(m) === 1 ? `10${ex}` : `${Number(m)} × 10${ex}`;
  }
  return out.replace('-', '−');
}

/** The sweep coordinate's name (the Δ plot's axis, the transport, the readouts). */
export const sweepCoord = (mode: 'offset' | 'rotate') => (mode === 'offset' ? 'h / r' : 'ψ / α');
