/**
 * Q6 variants: a rectangular area light over a floor point p (normal +z, Lambertian, f = ρ/π), as in
 * the area-light scene (`makeRectLight`: centre lc, size w × h, tilt about its x axis, emitting
 * normal (0, sin t, −cos t)).
 * (a) A small square patch on the light (position pu, pv on it, side s, extra tilt): r, cos θ_l and
 *     dω ≈ dA cos θ_l / r² (core `patchSolidAngleApprox`, as the scene's patch panel).
 * (b) The area-sampling estimator of L_o from three given points on the light (core
 *     `areaLightTerms` with strategy 'area', fed the given positions as its uniforms):
 *     ⟨L_o⟩ = (|A|/N) Σ f L cos θ cos θ_l / r².
 * Classic mistakes: dω without cos θ_l; r not squared; the receiver's cos θ in place of cos θ_l;
 * the estimator without |A| (p_A = 1/|A|), without cos θ_l, or with f = ρ instead of ρ/π.
 */
import { add, scale, type Vec3 } from '../core/vec3';
import { formatSignificant } from '../core/format';
import { Rng } from '../core/random';
import { patchSolidAngleApprox } from '../core/geometry';
import { areaLightTerms, makeRectLight, type AreaLightSetup, type RectLight } from '../core/lights';
import { intIn, numberAnswer, pick, query } from './build';
import { closeTo, ownNumber } from './follow';
import { assembleSolution, tn, vecDisplay, vecValue, type Part, type Variant } from './model';

export interface Q6Params {
  p: Vec3;
  lc: Vec3;
  ls: [number, number];
  tilt: number;
  L: number;
  rho: number;
  pu: number;
  pv: number;
  psize: number;
  ptilt: number;
  /** Positions of the given sample points on the light, as fractions (s, t) of its edges. */
  uv: [number, number][];
}

export function q6Geometry(P: Q6Params) {
  const light = makeRectLight(P.lc, P.ls[0], P.ls[1], P.tilt);
  const centre = add(add(light.corner, scale(light.edgeX, P.pu)), scale(light.edgeY, P.pv));
  const patch = makeRectLight(centre, P.psize, P.psize, P.tilt + P.ptilt);
  const dx = centre[0] - P.p[0],
    dy = centre[1] - P.p[1],
    dz = centre[2] - P.p[2];
  const r = Math.hypot(dx, dy, dz);
  const n = patch.normal;
  const cosL = -(dx * n[0] + dy * n[1] + dz * n[2]) / r;
  const cosRecv = dz / r;
  const dOmega = patchSolidAngleApprox(patch.area, cosL, r);
  return { light, centre, patch, r, cosL, cosRecv, dOmega };
}

function pointTerms(light: RectLight, P: Q6Params) {
  return P.uv.map(([s, t]) => {
    const x = add(add(light.corner, scale(light.edgeX, s)), scale(light.edgeY, t));
    const dx = x[0] - P.p[0],
      dy = x[1] - P.p[1],
      dz = x[2] - P.p[2];
    const r2 = dx * dx + dy * dy + dz * dz;
    const r = Math.sqrt(r2);
    const nl = light.normal;
    return { x, r2, cosT: dz / r, cosL: -(dx * nl[0] + dy * nl[1] + dz * nl[2]) / r };
  });
}

/** The estimate by the core's area-sampling kernel, fed the given points' (s, t) as its uniforms. */
export function q6Estimate(P: Q6Params, light: RectLight): { estimate: number; terms: Float64Array } {
  const setup: AreaLightSetup = {
    light,
    occluder: null,
    px: P.p[0],
    py: P.p[1],
    pz: P.p[2],
    L: P.L,
    rho: P.rho,
  };
  const n = P.uv.length;
  const u = new Float64Array(2 * n);
  P.uv.forEach(([s, t], i) => {
    u[2 * i] = s;
    u[2 * i + 1] = t;
  });
  const terms = new Float64Array(n);
  areaLightTerms(setup, 'area', u, n, terms);
  return { estimate: terms.reduce((s, x) => s + x, 0) / n, terms };
}

/** One random draw of a variant's parameters from the stream `rng`. */
function drawQ6Params(rng: Rng): Q6Params {
  return {
    p: [pick(rng, [0, 0, 0.5, -0.5]), pick(rng, [0, 0, 0.5, -0.5]), 0],
    lc: [pick(rng, [0, 0, 0.5, -0.5, 1]), pick(rng, [0, 0, 0.5, -0.5, 1]), pick(rng, [1, 1.5, 2, 2.5, 3])],
    ls: [pick(rng, [0.5, 1, 1.5, 2]), pick(rng, [0.5, 1, 1.5, 2])],
    tilt: pick(rng, [0, 0, 0, 20, 30, -30]),
    L: pick(rng, [1, 2, 5, 10]),
    rho: pick(rng, [0.5, 0.8, 1]),
    pu: intIn(rng, 1, 9) / 10,
    pv: intIn(rng, 1, 9) / 10,
    psize: pick(rng, [0.05, 0.1, 0.2]),
    ptilt: pick(rng, [0, 15, 30, 45, -30, -45]),
    uv: [0, 1, 2].map(() => [intIn(rng, 1, 19) / 20, intIn(rng, 1, 19) / 20] as [number, number]),
  };
}

/** A draw makes a fair variant when the patch and every given point see the floor point clearly. */
export function q6Acceptable(P: Q6Params): boolean {
  const g = q6Geometry(P);
  if (!(g.cosL > 0.05) || !(g.cosRecv > 0.05)) return false;
  return pointTerms(g.light, P).every((q) => q.cosT > 0.05 && q.cosL > 0.05);
}

/** The seed whose first draw is the fallback variant (the tests check that it is acceptable). */
const FALLBACK_SEED = 1;

/**
 * The parameters of variant `seed`: the first acceptable draw of its stream. Should a thousand draws
 * fail, the first draw of variant {@link FALLBACK_SEED}'s stream.
 */
export function q6Params(seed: number): Q6Params {
  const rng = new Rng(seed, 0x5106);
  for (let k = 0; k < 1000; k++) {
    const P = drawQ6Params(rng);
    if (q6Acceptable(P)) return P;
  }
  return q6FallbackParams();
}

/** The variant a seed gets when none of its draws is acceptable. */
export function q6FallbackParams(): Q6Params {
  return drawQ6Params(new Rng(FALLBACK_SEED, 0x5106));
}

export function q6Variant(seed: number): Variant {
  const P = q6Params(seed);
  const g = q6Geometry(P);
  const { estimate, terms } = q6Estimate(P, g.light);
  const pts = pointTerms(g.light, P);
  const A = g.light.area;
  const dA = g.patch.area;
  const f = P.rho / Math.PI;
  const n = pts.length;
  const mean = (xs: number[]) => xs.reduce((s, x) => s + x, 0) / xs.length;
  const answers = [
    numberAnswer(
      'r',
      'r',
      g.r,
      [],
      [{ id: 'r-squared', value: g.r * g.r, message: 'That is r²; r is the distance |x − p|.' }],
    ),
    numberAnswer(
      'cos-theta-l',
      'cos θ_l',
      g.cosL,
      [],
      [
        {
          id: 'receiver-cosine',
          value: g.cosRecv,
          message:
            'That is cos θ at the receiver (against the floor normal +z). θ_l is measured at the patch, against the patch’s own normal n_l.',
        },
      ],
    ),
    numberAnswer(
      'd-omega',
      'dω',
      g.dOmega,
      [],
      [
        {
          id: 'no-cos',
          value: dA / (g.r * g.r),
          message:
            'dω = dA cos θ_l / r²: only the patch’s projection perpendicular to the line of sight counts (the cos θ_l is missing).',
        },
        {
          id: 'r-not-squared',
          value: (dA * g.cosL) / g.r,
          message: 'Solid angle falls off with the square of the distance: divide by r², not r.',
        },
        {
          id: 'receiver-cosine',
          value: (dA * g.cosRecv) / (g.r * g.r),
          message:
            'The cosine in dω is the one at the patch, cos θ_l (against n_l), not the receiver’s cos θ.',
        },
      ],
    ),
    numberAnswer(
      'estimate',
      '⟨L_o⟩',
      estimate,
      [],
      [
        {
          id: 'no-area',
          value: estimate / A,
          message: `Sampling the light uniformly has p_A = 1/|A|, so the sum is multiplied by |A| = ${formatSignificant(A, 6, 'e')}.`,
        },
        {
          id: 'no-cos-l',
          value: mean(pts.map((q) => (A * f * P.L * q.cosT) / q.r2)),
          message: 'The Jacobian from dω to dA is cos θ_l / r²: the cos θ_l is missing.',
        },
        {
          id: 'rho-not-over-pi',
          value: estimate * Math.PI,
          message: 'The Lambertian BRDF is f = ρ/π, not ρ.',
        },
      ],
    ),
  ];
  const rows = pts.map(
    (q, i) =>
      `${vecDisplay(q.x, 4)} & ${tn(q.cosT, 5)} & ${tn(q.cosL, 5)} & ${tn(q.r2, 5)} & ${tn(terms[i], 5)}`,
  );
  const xp = g.centre.map((c, k) => c - P.p[k]);
  const parts: Part[] = [
    {
      id: 'a',
      prompt: '(a) The patch: distance r, cos θ_l, and dω.',
      answers: answers.slice(0, 3),
      hint: [
        { text: 'Start from the vector from p to the patch centre; its length is r:' },
        { tex: `x - p = ${vecDisplay(xp, 5)}` },
      ],
      steps: [
        {
          text: `(a) The patch centre is x = ${vecDisplay(g.centre, 5)} and its normal n_l = ${vecDisplay(g.patch.normal, 5)}; from p = ${vecDisplay(P.p)}:`,
        },
        { tex: `x - p = ${vecDisplay(xp, 5)}, \\qquad r = |x - p| = ${tn(g.r)}` },
        { tex: `\\cos\\theta_l = \\frac{-n_l\\cdot(x - p)}{r} = ${tn(g.cosL)}` },
        {
          tex: `d\\omega \\approx \\frac{dA\\,\\cos\\theta_l}{r^2} = \\frac{${tn(dA)}\\cdot ${tn(g.cosL)}}{${tn(g.r * g.r)}} = ${tn(g.dOmega)}\\ \\text{sr}`,
        },
      ],
    },
    {
      id: 'b',
      prompt: '(b) The area-sampling estimate ⟨L_o⟩ = (|A|/N) Σ f L cos θ cos θ_l / r².',
      answers: answers.slice(3),
      hint: [
        {
          text: `Sampling the light uniformly by area has p_A = 1/|A| with |A| = ${formatSignificant(A, 6, 'e')}. The solid angle of each sample’s area is dω = dA cos θ_l / r², so each term is:`,
        },
        {
          tex: `\\frac{f\\,L\\cos\\theta\\,\\cos\\theta_l / r^2}{p_A} = |A|\\,\\frac{\\rho}{\\pi}\\,L\\,\\frac{\\cos\\theta\\,\\cos\\theta_l}{r^2}`,
        },
      ],
      steps: [
        {
          text: `(b) Uniform area sampling, p_A = 1/|A| with |A| = ${formatSignificant(A, 6, 'e')}, f = ρ/π = ${formatSignificant(f, 6, 'e')}, L = ${P.L}. Per point: cos θ (floor normal +z), cos θ_l (light normal ${vecDisplay(g.light.normal, 4)}), r², and the term |A| f L cos θ cos θ_l / r²:`,
        },
        {
          tex: `\\begin{array}{ccccc} x_i & \\cos\\theta & \\cos\\theta_l & r^2 & \\text{term} \\\\ \\hline ${rows.join(' \\\\ ')} \\end{array}`,
        },
        {
          tex: `\\begin{aligned} \\langle L_o\\rangle &= \\frac{|A|}{N}\\sum_i f L\\,\\cos\\theta_i\\,\\frac{\\cos\\theta_{l,i}}{r_i^2} \\\\ &= \\frac{1}{${n}}\\,(${Array.from(terms, (t) => tn(t, 5)).join(' + ')}) \\\\ &= ${tn(estimate)} \\end{aligned}`,
        },
      ],
    },
  ];
  // follow-through: dω from the student's own r and cos θ_l; the estimate with their own dω formula
  answers[2].follow = [
    {
      from: ['r', 'cos-theta-l'],
      matches: (own, x) => {
        const r = ownNumber(own, 'r');
        const c = ownNumber(own, 'cos-theta-l');
        return typeof r === 'number' && typeof c === 'number' && r !== 0 && closeTo(x, (dA * c) / (r * r));
      },
    },
  ];
  const perPoint = (term: (q: (typeof pts)[number]) => number) =>
    mean(pts.map((q) => A * f * P.L * q.cosT * term(q)));
  const ownFormulas: [number, number][] = [
    [dA / (g.r * g.r), perPoint((q) => 1 / q.r2)], // no cos θ_l
    [(dA * g.cosL) / g.r, perPoint((q) => q.cosL / Math.sqrt(q.r2))], // r not squared
    [(dA * g.cosRecv) / (g.r * g.r), perPoint((q) => q.cosT / q.r2)], // the receiver's cosine
  ];
  answers[3].follow = [
    {
      from: ['d-omega'],
      matches: (own, x) => {
        const w = ownNumber(own, 'd-omega');
        return typeof w === 'number' && ownFormulas.some(([wv, ev]) => closeTo(w, wv) && closeTo(x, ev));
      },
    },
  ];
  answers[0].tex = `r = ${tn(g.r)}`;
  answers[1].tex = `\\cos\\theta_l = ${tn(g.cosL)}`;
  answers[2].tex = `d\\omega = \\frac{dA\\cos\\theta_l}{r^2} = ${tn(g.dOmega)}\\ \\text{sr}`;
  answers[3].tex = `\\langle L_o\\rangle = ${tn(estimate)}`;
  const ptsValue = pts.map((q) => vecValue(q.x)).join(';');
  return {
    question: 'q6',
    seed,
    title: 'Solid angle and area lights',
    statement: `A floor point p = ${vecDisplay(P.p)} (normal +z, Lambertian, albedo ρ = ${P.rho}, so f = ρ/π) is lit by a one-sided rectangular light of radiance L = ${P.L}, centre ${vecDisplay(P.lc)}, size ${P.ls[0]} × ${P.ls[1]}, tilted ${P.tilt}° about its x axis (emitting normal ${vecDisplay(g.light.normal, 4)}). (a) A small square patch of side ${P.psize} on it has centre ${vecDisplay(g.centre, 5)} and normal ${vecDisplay(g.patch.normal, 4)}: find r, cos θ_l and the solid angle dω ≈ dA cos θ_l / r². (b) With the ${n} points below sampled uniformly on the light, give the area-sampling estimate of L_o (no occluder, V = 1).`,
    givens: [
      { name: 'p', label: 'floor point p', value: vecValue(P.p), display: vecDisplay(P.p) },
      { name: 'lc', label: 'light centre', value: vecValue(P.lc), display: vecDisplay(P.lc) },
      { name: 'ls', label: 'light size w,h', value: vecValue(P.ls), display: `${P.ls[0]} × ${P.ls[1]}` },
      { name: 'tilt', label: 'light tilt (°)', value: String(P.tilt), display: `${P.tilt}°` },
      { name: 'L', label: 'radiance L', value: String(P.L), display: String(P.L) },
      { name: 'rho', label: 'albedo ρ', value: String(P.rho), display: String(P.rho) },
      {
        name: 'patch-centre',
        label: 'patch centre',
        value: vecValue(g.centre),
        display: vecDisplay(g.centre, 5),
      },
      {
        name: 'patch-normal',
        label: 'patch normal n_l',
        value: vecValue(g.patch.normal),
        display: vecDisplay(g.patch.normal, 5),
      },
      { name: 'psize', label: 'patch side (dA = side²)', value: String(P.psize), display: String(P.psize) },
      {
        name: 'points',
        label: 'sample points on the light',
        value: ptsValue,
        display: pts.map((q) => vecDisplay(q.x, 5)).join('  '),
      },
    ],
    parts,
    intro: [],
    solution: assembleSolution([], parts),
    sceneHref: `#/area-light?${query({ p: vecValue(P.p), lc: vecValue(P.lc), ls: vecValue(P.ls), tilt: P.tilt, L: P.L, rho: P.rho, pu: P.pu, pv: P.pv, psize: P.psize, ptilt: P.ptilt })}`,
    sceneLabel: 'Open this light and patch in the area-light scene',
    notes: [
      'The scene draws its own random points on the light; its estimate converges to the analytic L_o rather than reproduce these three.',
    ],
  };
}
