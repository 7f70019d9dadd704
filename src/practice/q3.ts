/**
 * Q3 variants: a square N × N texel grid (N ∈ {3, 4, 5}) with the exam's conventions (corner-aligned
 * nodes at i/(N − 1), v up, clamp), a query point (u, v), and a point on a sphere of radius r.
 * Every expected value comes from the core's texture routines, the ones the texture scene uses:
 * nearestStencil, bilinearStencil + bilinearSteps (the key's c_u, c_l, c), sphericalUV, bilinear.
 *
 * Accepted convention: the grid read with v′ = 1 − v (the key accepts it when stated), only on the
 * grid's v axis: nearest, bilinear and sphere-bilinear with the flip are correct, with a note, as long
 * as every answer of the variant uses the same reading (session.ts names a mix). The sphere's
 * v = θ/π is unambiguous and has no flipped form.
 * Classic mistakes: the division by the cell size missing (×Δ or ×Δ²), the weights swapped, the
 * lower-left node taken for the nearest, (u, v) not normalized by (2π, π), u = arctan(y/x) without
 * the quadrant (atan2).
 */
import { formatSignificant } from '../core/format';
import { Rng } from '../core/random';
import {
  EXAM_LOOKUP,
  bilinear,
  bilinearStencil,
  bilinearSteps,
  formatGrid,
  makeGrid,
  nearestStencil,
  sphericalUV,
  type LookupOptions,
  type TextureGrid,
} from '../core/texture';
import { intIn, numberAnswer, pick, query } from './build';
import { closeTo, ownNumber } from './follow';
import { assembleSolution, roundTo, tn, tp, type Part, type SolutionStep, type Variant } from './model';

const FLIP: LookupOptions = { ...EXAM_LOOKUP, vflip: true };

export interface Q3Params {
  grid: TextureGrid;
  u: number;
  v: number;
  /** Sphere point (rounded to 4 decimals: the givens are exactly these numbers). */
  x: number;
  y: number;
  z: number;
}

function wellPlaced(t: number, n: number): boolean {
  const s = t * (n - 1);
  const f = s - Math.floor(s);
  return f > 0.04 && f < 0.96 && Math.abs(f - 0.5) > 0.04;
}

export function q3Params(seed: number): Q3Params {
  const rng = new Rng(seed, 0x5103);
  const n = pick(rng, [3, 4, 5, 5]);
  let grid: TextureGrid;
  if (rng.nextFloat() < 0.5) {
    // the exam's kind: value(i, j) = b − s j + i (rows differ by s, columns by 1)
    const s = n;
    const b = intIn(rng, 0, 5) + s * (n - 1) + 1;
    grid = makeGrid(n, n, (i, j) => b - s * j + i);
  } else {
    grid = makeGrid(n, n, () => intIn(rng, 0, 20));
  }
  let u = 0;
  let v = 0;
  for (let k = 0; k < 200; k++) {
    u = intIn(rng, 2, 98) / 100;
    v = intIn(rng, 2, 98) / 100;
    if (wellPlaced(u, n) && wellPlaced(v, n) && wellPlaced(1 - v, n)) break;
  }
  const r = pick(rng, [1, 2, 3]);
  const phi =
    (pick(rng, [1, 2, 3, 4, 5, 7, 8, 9, 10, 11]) * Math.PI) / 6 + (rng.nextFloat() < 0.3 ? Math.PI / 12 : 0);
  const theta = (pick(rng, [1, 2, 3, 4, 5]) * Math.PI) / 6;
  const x = roundTo(r * Math.cos(phi) * Math.sin(theta), 4);
  const y = roundTo(r * Math.sin(phi) * Math.sin(theta), 4);
  const z = roundTo(r * Math.cos(theta), 4);
  return { grid, u, v, x, y, z };
}

export function q3Variant(seed: number): Variant {
  const P = q3Params(seed);
  const { grid, u, v, x, y, z } = P;
  const n = grid.width;
  const d = 1 / (n - 1);
  const near = nearestStencil(grid, u, v, EXAM_LOOKUP);
  const nearF = nearestStencil(grid, u, v, FLIP);
  const st = bilinearStencil(grid, u, v, EXAM_LOOKUP);
  const steps = bilinearSteps(st);
  const bil = st.value;
  const bilF = bilinear(grid, u, v, FLIP);
  const floorNode = grid.values[Math.floor(v * (n - 1)) * n + Math.floor(u * (n - 1))];
  // weights swapped: (u − u0) on the left texel, (v − v0) on the lower row
  const swapped =
    st.fv * (st.fu * st.t00 + (1 - st.fu) * st.t10) + (1 - st.fv) * (st.fu * st.t01 + (1 - st.fu) * st.t11);
  const sp = sphericalUV(x, y, z);
  if (!sp.ok) throw new Error(sp.message); // unreachable: the point is never the origin
  const sBil = bilinear(grid, sp.u, sp.v, EXAM_LOOKUP);
  const sBilF = bilinear(grid, sp.u, sp.v, FLIP);
  const sBilRaw = bilinear(grid, sp.phi, sp.theta, EXAM_LOOKUP);
  const sSt = bilinearStencil(grid, sp.u, sp.v, EXAM_LOOKUP);
  const sSteps = bilinearSteps(sSt);
  const atanU = Math.atan(y / x);

  const noDiv =
    'The division by the cell size Δ = 1/(N − 1) is missing (the key deducts for it): each interpolation step is ((u₁ − u) t₀ + (u − u₀) t₁)/Δ.';
  const flipMsg =
    'you read the grid with v′ = 1 − v (v = 0 on the top row). The key accepts this convention when it is stated and used for every lookup; the exam’s has v = 0 at the bottom row.';
  const answers = {
    nearest: numberAnswer(
      'nearest',
      'nearest',
      near.value,
      [{ value: nearF.value, message: flipMsg, convention: 'v-flip' }],
      [
        {
          id: 'floor-not-round',
          value: floorNode,
          message:
            'That is the lower-left node of the cell (indices rounded down); nearest rounds each index to the closer node.',
        },
      ],
    ),
    bilinear: numberAnswer(
      'bilinear',
      'bilinear',
      bil,
      [{ value: bilF, message: flipMsg, convention: 'v-flip' }],
      [
        { id: 'no-cell-division', value: bil * d * d, message: noDiv },
        { id: 'no-cell-division', value: bil * d, message: noDiv },
        {
          id: 'swapped-weights',
          value: swapped,
          message:
            'The weights are swapped: the texel nearer the query gets the larger weight, (u₁ − u)/Δ on the left texel and (u − u₀)/Δ on the right.',
        },
        {
          id: 'nearest-for-bilinear',
          value: near.value,
          message: 'That is the nearest-neighbour value; bilinear blends the four surrounding texels.',
        },
      ],
    ),
    sphereU: numberAnswer(
      'sphere-u',
      'sphere u',
      sp.u,
      [],
      [
        {
          id: 'no-normalization',
          value: sp.phi,
          message: 'That is the angle φ in radians: normalize by 2π, u = φ/(2π).',
        },
        {
          id: 'atan-quadrant',
          value: atanU / (2 * Math.PI),
          message:
            'arctan(y/x) only covers (−π/2, π/2): with x < 0 (or y < 0) the quadrant is lost. Use atan2(y, x), then add 2π if negative.',
        },
        {
          id: 'atan-quadrant',
          value: (atanU + 2 * Math.PI) / (2 * Math.PI),
          message:
            'arctan(y/x) only covers (−π/2, π/2): with x < 0 the quadrant is lost. Use atan2(y, x), then add 2π if negative.',
        },
      ],
    ),
    sphereV: numberAnswer(
      'sphere-v',
      'sphere v',
      sp.v,
      [], // v = θ/π on the sphere is unambiguous: the grid's flipped reading does not apply here
      [
        {
          id: 'no-normalization',
          value: sp.theta,
          message: 'That is the angle θ = arccos(z/r) in radians: normalize by π, v = θ/π.',
        },
        {
          id: 'flipped-v',
          value: 1 - sp.v,
          message:
            'That is 1 − θ/π. On the sphere v = θ/π = arccos(z/r)/π is unambiguous: the flipped v′ = 1 − v the key accepts is a way of reading the grid, not of the sphere’s angle.',
        },
      ],
    ),
    sphereBil: numberAnswer(
      'sphere-bilinear',
      'sphere bilinear',
      sBil,
      [{ value: sBilF, message: flipMsg, convention: 'v-flip' }],
      [
        {
          id: 'no-normalization',
          value: sBilRaw,
          message:
            'That is the lookup at the raw angles (φ, θ) in radians (clamped to [0, 1]); the key deducts for the missing normalization by (2π, π).',
        },
        { id: 'no-cell-division', value: sBil * d * d, message: noDiv },
        { id: 'no-cell-division', value: sBil * d, message: noDiv },
      ],
    ),
  };

  const gridText = formatGrid(grid);
  const rows = gridText.split(';').map((r) => r.split(','));
  const gridTex = `\\begin{array}{c|${'c'.repeat(n)}} ${rows.map((r, k) => `v=${formatSignificant(1 - k * d, 3, 'e')} & ${r.join(' & ')}`).join(' \\\\ ')} \\\\ \\hline & ${Array.from({ length: n }, (_, i) => `u=${formatSignificant(i * d, 3, 'e')}`).join(' & ')} \\end{array}`;
  const stepTex = (s: typeof st, sv: typeof steps, uu: number, vv: number) => [
    `c_u = \\frac{(${tn(s.u1)} - ${tn(uu)})\\cdot ${tp(s.t01)} + (${tn(uu)} - ${tn(s.u0)})\\cdot ${tp(s.t11)}}{${tn(s.du)}} = ${tn(sv.cu)}`,
    `c_l = \\frac{(${tn(s.u1)} - ${tn(uu)})\\cdot ${tp(s.t00)} + (${tn(uu)} - ${tn(s.u0)})\\cdot ${tp(s.t10)}}{${tn(s.du)}} = ${tn(sv.cl)}`,
    `c = \\frac{(${tn(s.v1)} - ${tn(vv)})\\cdot ${tp(sv.cl)} + (${tn(vv)} - ${tn(s.v0)})\\cdot ${tp(sv.cu)}}{${tn(s.dv)}} = ${tn(sv.c)}`,
  ];
  const intro: SolutionStep[] = [
    {
      text: `The nodes sit at u, v = i/${n - 1} (cell size Δ = ${formatSignificant(d, 4, 'e')}), v = 0 at the bottom row:`,
    },
    { tex: gridTex },
  ];
  const cellText = (s: typeof st) =>
    `the cell [${formatSignificant(s.u0, 4, 'e')}, ${formatSignificant(s.u1, 4, 'e')}] × [${formatSignificant(s.v0, 4, 'e')}, ${formatSignificant(s.v1, 4, 'e')}]`;
  const uvTex = `u = \\frac{\\operatorname{atan2}(y, x)}{2\\pi} = \\frac{${tn(sp.phi)}}{2\\pi} = ${tn(sp.u)}, \\qquad v = \\frac{\\arccos(z/r)}{\\pi} = \\frac{${tn(sp.theta)}}{\\pi} = ${tn(sp.v)}`;
  const parts: Part[] = [
    {
      id: 'a',
      prompt: `(a) Nearest-neighbour value at (${u}, ${v}).`,
      answers: [answers.nearest],
      hint: [
        {
          text: `Scale to node indices: u·${n - 1} = ${formatSignificant(u * (n - 1), 4, 'e')} and v·${n - 1} = ${formatSignificant(v * (n - 1), 4, 'e')} (v counted from the bottom row); round each to the nearest whole number.`,
        },
      ],
      steps: [
        {
          text: `(a) Nearest: u·${n - 1} = ${formatSignificant(u * (n - 1), 4, 'e')} and v·${n - 1} = ${formatSignificant(v * (n - 1), 4, 'e')} round to the node (${formatSignificant(near.nodeU, 4, 'e')}, ${formatSignificant(near.nodeV, 4, 'e')}), value ${formatSignificant(near.value, 6, 'e')}.`,
        },
      ],
    },
    {
      id: 'b',
      prompt: `(b) Bilinear value at (${u}, ${v}).`,
      answers: [answers.bilinear],
      hint: [
        {
          text: `(${u}, ${v}) lies in ${cellText(st)}. Interpolate along u on its lower row (texels ${formatSignificant(st.t00, 6, 'e')}, ${formatSignificant(st.t10, 6, 'e')}) and its upper row (${formatSignificant(st.t01, 6, 'e')}, ${formatSignificant(st.t11, 6, 'e')}), dividing by Δ = ${formatSignificant(d, 4, 'e')}:`,
        },
        { tex: stepTex(st, steps, u, v)[1] },
      ],
      steps: [
        {
          text: `(b) Bilinear: ${cellText(st)}; along u on the upper and lower rows, then along v:`,
        },
        ...stepTex(st, steps, u, v).map((tex) => ({ tex })),
        {
          text: `Read with v′ = 1 − v (the key accepts this flipped grid convention when it is stated and used throughout) the values of (a) and (b) are ${formatSignificant(nearF.value, 6, 'e')} and ${formatSignificant(bilF, 6, 'e')}.`,
        },
      ],
    },
    {
      id: 'c',
      prompt: '(c) The sphere point’s normalized (u, v) and the bilinear value there.',
      answers: [answers.sphereU, answers.sphereV, answers.sphereBil],
      hint: [
        {
          text: `First r = √(x² + y² + z²) = ${formatSignificant(sp.r, 5, 'e')}; then the angles φ = atan2(y, x) (in [0, 2π)) and θ = arccos(z/r), normalized:`,
        },
        { tex: `u = \\frac{\\varphi}{2\\pi}, \\qquad v = \\frac{\\theta}{\\pi}` },
      ],
      steps: [
        { text: `(c) The point (${x}, ${y}, ${z}) has r = ${formatSignificant(sp.r, 5, 'e')}:` },
        { tex: uvTex },
        {
          text: `Bilinear lookup at (${formatSignificant(sp.u, 6, 'e')}, ${formatSignificant(sp.v, 6, 'e')}), in ${cellText(sSt)}:`,
        },
        ...stepTex(sSt, sSteps, sSt.u, sSt.v).map((tex) => ({ tex })),
        {
          text: `Without the normalization (the angles in radians, clamped to [0, 1]) the lookup would give ${formatSignificant(sBilRaw, 6, 'e')}; the key deducts for it.`,
        },
      ],
    },
  ];
  answers.sphereBil.follow = [
    {
      from: ['sphere-u', 'sphere-v'],
      matches: (own, val) => {
        const us = ownNumber(own, 'sphere-u');
        const vs = ownNumber(own, 'sphere-v');
        if (typeof us !== 'number' || typeof vs !== 'number') return false;
        return (
          closeTo(val, bilinear(grid, us, vs, EXAM_LOOKUP)) || closeTo(val, bilinear(grid, us, vs, FLIP))
        );
      },
    },
  ];
  answers.nearest.tex = `\\text{nearest} = ${tn(near.value)}`;
  answers.bilinear.tex = `\\text{bilinear} = ${tn(bil)}`;
  answers.sphereU.tex = `u = \\frac{${tn(sp.phi)}}{2\\pi} = ${tn(sp.u)}`;
  answers.sphereV.tex = `v = \\frac{${tn(sp.theta)}}{\\pi} = ${tn(sp.v)}`;
  answers.sphereBil.tex = `\\text{bilinear at }(u, v) = ${tn(sBil)}`;
  return {
    question: 'q3',
    seed,
    title: 'Texture lookup',
    statement: `A ${n} × ${n} texture has values at corner-aligned nodes (u, v) = (i/${n - 1}, j/${n - 1}), v growing upward (the top row printed first is v = 1). (a) Nearest-neighbour value at (u, v) = (${u}, ${v}). (b) Bilinear value there. (c) The point (x, y, z) = (${x}, ${y}, ${z}) lies on a sphere around the origin, x = r cos u sin v, y = r sin u sin v, z = r cos v: find its (u, v) normalized to [0, 1] by (2π, π), and the bilinear value there.`,
    givens: [
      {
        name: 'grid',
        label: 'grid (rows top to bottom)',
        value: gridText,
        display: rows.map((r) => r.join(' ')).join(' / '),
        tex: gridTex,
      },
      { name: 'u', label: 'u', value: String(u), display: String(u) },
      { name: 'v', label: 'v', value: String(v), display: String(v) },
      { name: 'x', label: 'x', value: String(x), display: String(x) },
      { name: 'y', label: 'y', value: String(y), display: String(y) },
      { name: 'z', label: 'z', value: String(z), display: String(z) },
    ],
    parts,
    intro,
    solution: assembleSolution(intro, parts),
    sceneHref: `#/texture?${query({ grid: gridText, u, v, x, y, z })}`,
    sceneLabel: 'Open this grid and these points in the texture scene',
    notes: [],
  };
}
