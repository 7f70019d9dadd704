/** How a Q1 density is written: its pieces as mathjs text (typed answers) and as TeX. */
import { ratTex, type Rational } from './model';

function gcd(a: number, b: number): number {
  return b === 0 ? Math.abs(a) : gcd(b, a % b);
}
export function reduce(p: number, q: number): Rational {
  const g = (gcd(p, q) || 1) * (q < 0 ? -1 : 1); // denominator positive
  return { p: p / g + 0, q: q / g };
}
/** A rational as a coefficient in mathjs text: '' for 1, '-' for −1, '3*', '(1/2)*'. */
export function coefText(r: Rational): string {
  if (r.q === 1) return r.p === 1 ? '' : r.p === -1 ? '-' : `${r.p}*`;
  return `(${r.p}/${r.q})*`;
}
/** A rational as a coefficient in TeX: '' for 1, '-' for −1, '3', '\tfrac{1}{2}'. */
export function coefTex(r: Rational): string {
  if (r.q === 1) return r.p === 1 ? '' : r.p === -1 ? '-' : String(r.p);
  return ratTex(r);
}
/** aφ as mathjs text: phi, -phi, 2*phi, phi/2, 3*phi/2, -phi/2. */
export function argText(a: Rational): string {
  const head = a.p === 1 ? 'phi' : a.p === -1 ? '-phi' : `${a.p}*phi`;
  return a.q === 1 ? head : `${head}/${a.q}`;
}
export function argTex(a: Rational): string {
  const head = a.p === 1 ? '\\phi' : a.p === -1 ? '-\\phi' : `${a.p}\\phi`;
  return a.q === 1 ? head : `${head}/${a.q}`;
}
/** e^(aφ) for people: e^φ, e^(−φ), e^(φ/2), … */
export function expPlain(a: Rational): string {
  const t = argText(a).replace('phi', 'φ').replace('*', '').replace('-', '−');
  return a.p === 1 && a.q === 1 ? 'e^φ' : `e^(${t})`;
}
/** 2πa = cπ with c = 2a an integer for every a drawn here. */
export function twoPiA(a: Rational): { text: string; tex: string } {
  const c = (2 * a.p) / a.q;
  const head = c === 1 ? '' : c === -1 ? '-' : `${c}*`;
  return { text: `(e^(${head}pi) - 1)`, tex: `e^{${head.replace('*', '')}\\pi}-1` };
}

export function cosPowTex(m: number): string {
  return m === 0 ? '' : m === 1 ? '\\cos\\theta\\,' : `\\cos^{${m}}\\theta\\,`;
}
export function cosPowText(m: number): string {
  return m === 0 ? '' : m === 1 ? 'cos(theta)' : `cos(theta)^${m}`;
}
export function expTex(a: Rational): string {
  return `e^{${argTex(a)}}`;
}
export function expText(a: Rational): string {
  return `exp(${argText(a)})`;
}
