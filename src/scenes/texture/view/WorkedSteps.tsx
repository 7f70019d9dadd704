/**
 * The exam key's worked steps with live numbers (TeX built from the model's lookups).
 */
import { memo } from 'react';
import { MathTex } from '../../../ui';
import type { LookupOptions, TextureGrid } from '../../../core/texture';
import type { Lookup } from '../model';

/** A number for TeX: 6 significant digits, trailing zeros trimmed, scientific form for tiny values. */
export function texNum(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return '\\text{—}';
  if (x === 0) return '0';
  const ax = Math.abs(x);
  if (ax >= 1e-4 && ax < 1e9) {
    const s = x.toPrecision(digits);
    return s.includes('e') ? s : s.includes('.') ? s.replace(/\.?0+$/, '') : s;
  }
  const [m, e] = x.toExponential(digits - 1).split('e');
  const mt = m.includes('.') ? m.replace(/\.?0+$/, '') : m;
  return `${mt}\\times 10^{${Number(e)}}`;
}

/** A factor in a product: negatives in parentheses. */
function fac(x: number): string {
  const s = texNum(x, 5);
  return x < 0 ? `(${s})` : s;
}

/** "(a − b)" with a sign-safe subtrahend. */
function diff(a: number, b: number): string {
  return `(${texNum(a, 5)} - ${fac(b)})`;
}

export function nearestTex(grid: TextureGrid, q: Lookup, opts: LookupOptions, uName = 'u', vName = 'v'): string {
  const n = q.near;
  const vq = opts.vflip ? `${vName}'` : vName;
  if (opts.align === 'corner') {
    return [
      `i &= \\operatorname{round}\\big(${uName}\\,(N_u - 1)\\big) \\\\ &= \\operatorname{round}(${texNum(n.u)} \\cdot ${grid.width - 1}) = ${n.i}`,
      `j &= \\operatorname{round}\\big(${vq}\\,(N_v - 1)\\big) \\\\ &= \\operatorname{round}(${texNum(n.v)} \\cdot ${grid.height - 1}) = ${n.j}`,
      `T_{${n.i},${n.j}} &= ${texNum(n.value)} \\\\ &\\text{(the node at } (${texNum(n.nodeU)},\\ ${texNum(n.nodeV)})\\text{)}`,
    ].join(' \\\\ ');
  }
  return [
    `i &= \\lfloor ${uName}\\,N_u \\rfloor = \\lfloor ${texNum(n.u)} \\cdot ${grid.width} \\rfloor \\to ${n.i}`,
    `j &= \\lfloor ${vq}\\,N_v \\rfloor = \\lfloor ${texNum(n.v)} \\cdot ${grid.height} \\rfloor \\to ${n.j}`,
    `T_{${n.i},${n.j}} &= ${texNum(n.value)} \\\\ &\\text{(the texel centred at } (${texNum(n.nodeU)},\\ ${texNum(n.nodeV)})\\text{)}`,
  ].join(' \\\\ ');
}

export function bilinearTex(q: Lookup, opts: LookupOptions, uName = 'u', vName = 'v'): string {
  const b = q.bil;
  const s = q.steps;
  const vq = opts.vflip ? `${vName}'` : vName;
  return [
    `c_u &= \\frac{(u_1 - ${uName})\\,T_{${b.i0},${b.j1}} + (${uName} - u_0)\\,T_{${b.i1},${b.j1}}}{\\Delta u} \\\\ &= \\frac{${diff(b.u1, b.u)} \\cdot ${fac(b.t01)} + ${diff(b.u, b.u0)} \\cdot ${fac(b.t11)}}{${texNum(b.du, 5)}} = ${texNum(s.cu)}`,
    `c_l &= \\frac{(u_1 - ${uName})\\,T_{${b.i0},${b.j0}} + (${uName} - u_0)\\,T_{${b.i1},${b.j0}}}{\\Delta u} \\\\ &= \\frac{${diff(b.u1, b.u)} \\cdot ${fac(b.t00)} + ${diff(b.u, b.u0)} \\cdot ${fac(b.t10)}}{${texNum(b.du, 5)}} = ${texNum(s.cl)}`,
    `c &= \\frac{(v_1 - ${vq})\\,c_l + (${vq} - v_0)\\,c_u}{\\Delta v} \\\\ &= \\frac{${diff(b.v1, b.v)} \\cdot ${fac(s.cl)} + ${diff(b.v, b.v0)} \\cdot ${fac(s.cu)}}{${texNum(b.dv, 5)}} = ${texNum(s.c)}`,
  ].join(' \\\\[4pt] ');
}

interface Props {
  grid: TextureGrid;
  opts: LookupOptions;
  q: Lookup;
  isExamQuery: boolean;
}

/** Q3 (a) and (b) worked out for the current query. */
export const QueryWorked = memo(function QueryWorked({ grid, opts, q, isExamQuery }: Props) {
  const b = q.bil;
  return (
    <div className="tx-worked" data-testid="worked-query">
      <h3>Nearest neighbour</h3>
      <MathTex display tex={`\\begin{aligned}${nearestTex(grid, q, opts)}\\end{aligned}`} />
      <h3>Bilinear, in the key’s steps</h3>
      <p className="tx-small">
        The cell’s nodes are u₀ = {texNum(b.u0)}, u₁ = {texNum(b.u1)}, v₀ = {texNum(b.v0)}, v₁ = {texNum(b.v1)}; the cell size is Δu ={' '}
        {texNum(b.du)}, Δv = {texNum(b.dv)}. Interpolate along u on the upper row (c_u) and the lower row (c_l), then along v. Leaving out the
        division by the cell size (the key deducts marks for it) would scale each result by Δ.
      </p>
      <MathTex display tex={`\\begin{aligned}${bilinearTex(q, opts)}\\end{aligned}`} />
      <p className="tx-small">
        Weights (areas of the opposite sub-rectangles): w₀₀ = {texNum(b.w00, 4)}, w₁₀ = {texNum(b.w10, 4)}, w₀₁ = {texNum(b.w01, 4)}, w₁₁ ={' '}
        {texNum(b.w11, 4)} (sum 1).
        {isExamQuery ? ' These are the exam’s inputs: the computed c_u, c_l and c agree with the key’s printed 17.6, 22.6 and 17.8.' : null}
      </p>
    </div>
  );
});
