/**
 * The exam key's worked steps with live numbers (TeX built from the model's lookups).
 */
import { memo, useLayoutEffect, useRef } from 'react';
import { keepTextParenthesesTogether, MathTex } from '../../../ui';
import type { LookupOptions, TextureGrid } from '../../../core/texture';
import type { Lookup } from '../model';
import { formatSignificant } from '../../../core/format';
import './WorkedSteps.css';

/** A number for TeX: 6 significant digits, trailing zeros trimmed, scientific form for tiny values. */
export function texNum(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return '\\text{—}';
  return formatSignificant(x, digits, 'e').replace(/e(-?\d+)$/, '\\times 10^{$1}');
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

/** The nearest-neighbour steps (i, j, the node's value), each the rows of one aligned block. */
function nearestSteps(grid: TextureGrid, q: Lookup, opts: LookupOptions): string[] {
  const n = q.near;
  const vq = opts.vflip ? `v'` : 'v';
  if (opts.align === 'corner') {
    return [
      `i &= \\operatorname{round}\\big(u\\,(N_u - 1)\\big) \\\\ &= \\operatorname{round}(${texNum(n.u)} \\cdot ${grid.width - 1}) = ${n.i}`,
      `j &= \\operatorname{round}\\big(${vq}\\,(N_v - 1)\\big) \\\\ &= \\operatorname{round}(${texNum(n.v)} \\cdot ${grid.height - 1}) = ${n.j}`,
      `T_{${n.i},${n.j}} &= ${texNum(n.value)} \\\\ &\\text{(the node at } (${texNum(n.nodeU)},\\ ${texNum(n.nodeV)})\\text{)}`,
    ];
  }
  return [
    `i &= \\lfloor u\\,N_u \\rfloor = \\lfloor ${texNum(n.u)} \\cdot ${grid.width} \\rfloor \\to ${n.i}`,
    `j &= \\lfloor ${vq}\\,N_v \\rfloor = \\lfloor ${texNum(n.v)} \\cdot ${grid.height} \\rfloor \\to ${n.j}`,
    `T_{${n.i},${n.j}} &= ${texNum(n.value)} \\\\ &\\text{(the texel centred at } (${texNum(n.nodeU)},\\ ${texNum(n.nodeV)})\\text{)}`,
  ];
}

/** The key's bilinear steps (c_u, c_l, c), each the rows of one aligned block. */
function bilinearSteps(q: Lookup, opts: LookupOptions): string[] {
  const b = q.bil;
  const s = q.steps;
  const vq = opts.vflip ? `v'` : 'v';
  // each step on rows short enough for a phone: the formula, the numbers (one product per row), the value
  const step = (
    lhs: string,
    formula: string,
    d1: string,
    f1: number,
    d2: string,
    f2: number,
    den: number,
    value: number,
  ) =>
    `${lhs} &= ${formula} \\\\ &= \\tfrac{1}{${texNum(den, 5)}}\\big(${d1} \\cdot ${fac(f1)} \\\\ &\\qquad + ${d2} \\cdot ${fac(f2)}\\big) \\\\ &= ${texNum(value)}`;
  // c_u and c_l: the same step along u, on the upper row (j1) and the lower row (j0)
  const row = (lhs: string, j: number, t0: number, t1: number, value: number) =>
    step(
      lhs,
      `\\frac{(u_1 - u)\\,T_{${b.i0},${j}} + (u - u_0)\\,T_{${b.i1},${j}}}{\\Delta u}`,
      diff(b.u1, b.u),
      t0,
      diff(b.u, b.u0),
      t1,
      b.du,
      value,
    );
  return [
    row('c_u', b.j1, b.t01, b.t11, s.cu),
    row('c_l', b.j0, b.t00, b.t10, s.cl),
    step(
      'c',
      `\\frac{(v_1 - ${vq})\\,c_l + (${vq} - v_0)\\,c_u}{\\Delta v}`,
      diff(b.v1, b.v),
      s.cl,
      diff(b.v, b.v0),
      s.cu,
      b.dv,
      s.c,
    ),
  ];
}

/**
 * A derivation's steps as display math, each step its own aligned block: side by side where the
 * column is wide enough, one under another on a phone. The box scrolls sideways when one step is
 * wider than the column (phones, classroom type) and, being scrollable, is focusable (keyboard
 * users can scroll it; axe scrollable-region-focusable). `exact`: never shows a formula other than
 * `steps` — until they are typeset they show as plain text (in the height the typeset ones had, so
 * the page does not jump); for steps whose numbers must match the answer shown beside them.
 */
export function MathSteps({
  steps,
  label,
  exact = false,
}: {
  /** Each step's TeX, an aligned block. */
  steps: readonly string[];
  label: string;
  exact?: boolean;
}) {
  const box = useRef<HTMLDivElement>(null);
  const typesetHeight = useRef(0);
  useLayoutEffect(() => {
    const el = box.current;
    if (!el || !exact) return;
    if (el.querySelector('.math-pending')) el.style.minHeight = `${typesetHeight.current}px`;
    else {
      el.style.minHeight = '';
      typesetHeight.current = el.offsetHeight;
    }
  });
  return (
    <div className="tx-math" tabIndex={0} role="group" aria-label={label} ref={box}>
      {steps.map((tex, k) => (
        <MathTex key={exact ? tex : k} display tex={tex} />
      ))}
    </div>
  );
}

/** Each step as the rows of an aligned block. */
const blocks = (steps: string[]) => steps.map((tex) => `\\begin{aligned}${tex}\\end{aligned}`);

/** The nearest-neighbour steps as display blocks (what Q3a shows and typesets ahead). */
export const nearestBlocks = (grid: TextureGrid, q: Lookup, opts: LookupOptions) =>
  blocks(nearestSteps(grid, q, opts));

/** The bilinear steps as display blocks (what Q3b shows and typesets ahead). */
export const bilinearBlocks = (q: Lookup, opts: LookupOptions) => blocks(bilinearSteps(q, opts));

/** The bilinear steps at the sphere point, in the key's form. */
export function SphereBilinear({ q, opts }: { q: Lookup; opts: LookupOptions }) {
  return <MathSteps label="Bilinear steps at the sphere point" steps={bilinearBlocks(q, opts)} />;
}

/** The nearest-neighbour steps (Q3a) for the current query. */
export const NearestWorked = memo(function NearestWorked({
  grid,
  opts,
  q,
}: {
  grid: TextureGrid;
  opts: LookupOptions;
  q: Lookup;
}) {
  return (
    <div className="tx-worked" data-testid="worked-nearest">
      <p className="tx-small">
        The nodes sit at u = {keepTextParenthesesTogether('i/(N − 1)')}, v ={' '}
        {keepTextParenthesesTogether('j/(N − 1)')} (corner nodes, the exam’s) or at the texel centres{' '}
        {keepTextParenthesesTogether('(i + ½)/N')}; nearest-neighbour lookup takes the value of the node
        closest to the query
        {opts.align === 'center' ? ' (the texel whose square holds it)' : ''}, without blending.
      </p>
      <MathSteps label="Nearest-neighbour steps" steps={nearestBlocks(grid, q, opts)} exact />
    </div>
  );
});

/** The key's bilinear steps (Q3b) for the current query: cᵤ, cₗ, c, each divided by the cell size. */
export const BilinearWorked = memo(function BilinearWorked({ opts, q }: { opts: LookupOptions; q: Lookup }) {
  const b = q.bil;
  return (
    <div className="tx-worked" data-testid="worked-query">
      <p className="tx-small">
        The query lies in the cell u₀ = {texNum(b.u0)} ≤ u ≤ u₁ = {texNum(b.u1)}, v₀ = {texNum(b.v0)} ≤{' '}
        {opts.vflip ? 'v′' : 'v'} ≤ v₁ = {texNum(b.v1)}, of size Δu = {texNum(b.du)}, Δv = {texNum(b.dv)}.
        Interpolate along u on the upper row (c<sub>u</sub>) and on the lower row (c<sub>l</sub>), then along
        v between them; each step divides by the cell size.
      </p>
      <MathSteps label="Bilinear steps" steps={bilinearBlocks(q, opts)} exact />
      <p className="tx-small">
        The same as the weighted sum of the four nodes, each weighted by the area of the sub-rectangle
        opposite to it: w₀₀ = {texNum(b.w00, 4)}, w₁₀ = {texNum(b.w10, 4)}, w₀₁ = {texNum(b.w01, 4)}, w₁₁ ={' '}
        {texNum(b.w11, 4)} (sum 1).
      </p>
    </div>
  );
});

/**
 * The spherical (u, v) of Q3c, step by step with live numbers, as display blocks: u from y/x, v
 * from z/r, then the normalization.
 */
export function sphereBlocks(p: {
  x: number;
  y: number;
  z: number;
  r: number;
  phi: number;
  theta: number;
  pole: boolean;
  u: number;
  v: number;
}): string[] {
  return blocks([
    `\\frac{y}{x} &= \\frac{r \\sin u \\sin v}{r \\cos u \\sin v} = \\tan u \\\\[3pt] u &= \\operatorname{atan2}(y, x) \\\\ &= \\operatorname{atan2}(${texNum(p.y)},\\ ${texNum(p.x)}) \\\\ &= ${texNum(p.phi)}${p.pole ? '\\quad(\\text{a pole: defined as } 0)' : ''}`,
    `r &= \\sqrt{x^2 + y^2 + z^2} = ${texNum(p.r)} \\\\[3pt] \\frac{z}{r} &= \\frac{r \\cos v}{r} = \\cos v \\\\[3pt] v &= \\arccos\\frac{z}{r} = \\arccos(${texNum(p.z / p.r)}) \\\\ &= ${texNum(p.theta)}`,
    `(u, v)_{\\text{tex}} &= \\left(\\frac{u}{2\\pi},\\ \\frac{v}{\\pi}\\right) \\\\ &= \\left(\\frac{${texNum(p.phi)}}{${texNum(2 * Math.PI)}},\\ \\frac{${texNum(p.theta)}}{${texNum(Math.PI)}}\\right) \\\\ &= (${texNum(p.u)},\\ ${texNum(p.v)})`,
  ]);
}
