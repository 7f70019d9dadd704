/**
 * Q5 variants: a ray o + t d and a sphere (centre C, radius r) with small integer coordinates, drawn
 * so every case appears (two hits, origin inside, sphere behind, miss, tangent). Expected values come
 * from the core's intersectRaySphere (the ray–sphere scene's routine, textbook method): a = d·d, b = 2 d·(o − C),
 * c = |o − C|² − r², Δ = b² − 4ac, the roots t0 ≤ t1, t_hit (nearest root ≥ 0) and the case.
 * With integer inputs a, b, c and Δ are exact in double precision.
 * C is the centre, c the constant term of the quadratic (the page keeps the two apart).
 * Classic mistakes: the sign slip in b (d·(C − o)), b without its 2, r not squared or − r² left
 * out of c, Δ/4 (the half-b
 * form), b² + 4ac, roots over a instead of 2a, the negative root chosen as the hit, the far root.
 */
import { formatSignificant } from '../core/format';
import { Rng } from '../core/random';
import { intersectRaySphere, type RaySphereCase, type RaySphereHit, type Vec3 } from '../core/geometry';
import { choiceAnswer, intIn, numberAnswer, pick, query } from './build';
import { closeTo, ownNumber } from './follow';
import {
  assembleSolution,
  tn,
  tp,
  vecDisplay,
  vecValue,
  type FollowRule,
  type Part,
  type SolutionStep,
  type Variant,
} from './model';

export const CASES: readonly RaySphereCase[] = ['miss', 'tangent', 'two-hits', 'inside', 'behind'];

export interface Q5Params {
  o: Vec3;
  d: Vec3;
  c: Vec3;
  r: number;
}

function ivec(rng: Rng, lo: number, hi: number): [number, number, number] {
  return [intIn(rng, lo, hi), intIn(rng, lo, hi), intIn(rng, lo, hi)];
}

/**
 * The textbook evaluation (the key's form): with these small integers a, b, c and b² − 4ac are
 * exact, whereas the robust form's 4a(r² − |l|²) can be off by an ulp (16 → 15.999999999999996).
 */
function solve(p: Q5Params): RaySphereHit | null {
  const res = intersectRaySphere(p.o, p.d, p.c, p.r, 'naive');
  return res.ok ? res : null;
}

/** Well-posed: the wanted case, no near-tangent doubt, the origin not on the surface. */
function good(p: Q5Params, want: RaySphereCase): boolean {
  const h = solve(p);
  if (!h || h.case !== want) return false;
  if (want !== 'tangent' && h.nearTangent) return false;
  if (h.c === 0) return false;
  if (want === 'two-hits' && !(h.t0! > 0 && h.t1! > h.t0!)) return false;
  return true;
}

export function q5Params(seed: number): Q5Params {
  const rng = new Rng(seed, 0x5105);
  const want = pick(rng, [
    'two-hits',
    'two-hits',
    'two-hits',
    'inside',
    'inside',
    'behind',
    'behind',
    'miss',
    'miss',
    'tangent',
  ] as const);
  for (let k = 0; k < 5000; k++) {
    const o = ivec(rng, -3, 3);
    const r = pick(rng, [1, 2, 3]);
    let d: [number, number, number];
    let c: [number, number, number];
    if (want === 'tangent') {
      const ax = intIn(rng, 0, 2);
      const ax2 = (ax + 1 + intIn(rng, 0, 1)) % 3;
      d = [0, 0, 0];
      d[ax] = pick(rng, [1, 2, -1, -2]);
      const s = intIn(rng, 2, 5);
      c = [o[0], o[1], o[2]];
      c[ax] += s * Math.sign(d[ax]);
      c[ax2] += pick(rng, [r, -r]);
    } else {
      d = ivec(rng, -2, 2);
      if (d[0] === 0 && d[1] === 0 && d[2] === 0) continue;
      const t = want === 'behind' ? -intIn(rng, 2, 4) : want === 'inside' ? 0 : intIn(rng, 2, 4);
      const e = want === 'miss' ? ivec(rng, -3, 3) : want === 'inside' ? ivec(rng, -1, 1) : ivec(rng, -1, 1);
      c = [o[0] + t * d[0] + e[0], o[1] + t * d[1] + e[1], o[2] + t * d[2] + e[2]];
    }
    const p = { o, d, c, r };
    if (good(p, want)) return p;
  }
  return { o: [0, 0, -5], d: [0, 0, 1], c: [0, 0, 0], r: 1 };
}

export function q5Variant(seed: number): Variant {
  const P = q5Params(seed);
  const h = solve(P)!;
  const { a, b, c: cc, discriminant: D, t0, t1, tHit } = h;
  const f: Vec3 = [P.o[0] - P.c[0], P.o[1] - P.c[1], P.o[2] - P.c[2]];
  const ff = f[0] ** 2 + f[1] ** 2 + f[2] ** 2;
  const hit = t0 !== null && t1 !== null;
  const slipped = hit ? [-t1!, -t0!] : null; // roots of a t² − b t + c
  const slippedHit = slipped ? (slipped[0] >= 0 ? slipped[0] : slipped[1] >= 0 ? slipped[1] : null) : null;
  const signMsg =
    'Sign slip in b: b = 2 d·(o − C), with f = o − C pointing from the centre C to the ray origin (here you used C − o).';
  // t₀ and t₁ are asked alike: the same two slips (b's sign, the missing 2 in 2a) named for each
  const rootAnswer = (k: 0 | 1, t: number | null) =>
    numberAnswer(
      `t${k}`,
      k === 0 ? 't0 (smaller root)' : 't1 (larger root)',
      t,
      [],
      [
        {
          id: 'b-sign',
          value: slipped ? slipped[k] : null,
          message: `${signMsg} The roots come out negated.`,
        },
        {
          id: 'no-2a',
          value: hit ? 2 * t! : null,
          message: 'The roots are (−b ± √Δ)/(2a): the 2 in the denominator is missing.',
        },
      ],
    );
  const answers = [
    numberAnswer(
      'a',
      'a',
      a,
      [],
      [{ id: 'a-not-squared', value: Math.sqrt(a), message: 'a = d·d = |d|², not |d|.' }],
    ),
    numberAnswer(
      'b',
      'b',
      b,
      [],
      [
        { id: 'b-sign', value: -b, message: signMsg },
        {
          id: 'b-no-2',
          value: b / 2,
          message:
            'That is d·(o − C) = b/2 (the half-b form); in a t² + b t + c the coefficient is b = 2 d·(o − C).',
        },
      ],
    ),
    numberAnswer(
      'c',
      'c',
      cc,
      [],
      [
        { id: 'r-not-squared', value: ff - P.r, message: 'c = |o − C|² − r²: the radius must be squared.' },
        {
          id: 'forgot-r-squared',
          value: ff,
          message: `That is |o − C|² = ${ff} alone: the constant term is c = |o − C|² − r², so subtract r² = ${P.r * P.r}.`,
        },
      ],
    ),
    numberAnswer(
      'discriminant',
      'Δ = b² − 4ac',
      D,
      [],
      [
        {
          id: 'quarter-discriminant',
          value: D / 4,
          message: 'That is Δ/4 = (b/2)² − ac, the half-b form; the question asks for Δ = b² − 4ac.',
        },
        { id: 'plus-4ac', value: b * b + 4 * a * cc, message: 'Δ = b² − 4ac (minus).' },
      ],
    ),
    rootAnswer(0, t0),
    rootAnswer(1, t1),
    numberAnswer(
      't-hit',
      't_hit',
      tHit,
      [],
      [
        {
          id: 'negative-root',
          value: hit && t0! < 0 ? t0 : null,
          message:
            'That root is negative: it lies behind the ray origin. A hit needs t ≥ 0 (the nearest non-negative root).',
        },
        {
          id: 'negative-root',
          value: hit && t1! < 0 ? t1 : null,
          message:
            'That root is negative: it lies behind the ray origin. A hit needs t ≥ 0; here both roots are negative, so there is no hit (none).',
        },
        {
          id: 'far-root',
          value: h.case === 'two-hits' ? t1 : null,
          message: 'That is where the ray leaves the sphere; the visible hit is the nearest root t ≥ 0.',
        },
        { id: 'b-sign', value: slippedHit, message: `${signMsg}` },
      ],
    ),
    choiceAnswer(
      'case',
      'case',
      CASES,
      h.case,
      h.case === 'inside' || h.case === 'behind'
        ? [
            {
              id: 'ignored-t-sign',
              value: 'two-hits',
              message: 'Δ > 0 gives two roots, but not two hits: a root counts only if t ≥ 0.',
            },
          ]
        : [],
      caseWhy(h),
    ),
  ];
  const dot = (u: Vec3, v: Vec3) =>
    `${tp(u[0])}\\cdot${tp(v[0])} + ${tp(u[1])}\\cdot${tp(v[1])} + ${tp(u[2])}\\cdot${tp(v[2])}`;
  const stepsA: SolutionStep[] = [
    { text: 'Substitute p(t) = o + t d into |p − C|² = r² (C the centre), with f = o − C:' },
    { tex: `f = o - C = ${vecDisplay(f)}` },
    { tex: `(d\\cdot d)\\,t^2 + 2\\,(d\\cdot f)\\,t + (f\\cdot f - r^2) = 0` },
    { tex: `a = d\\cdot d = ${dot(P.d, P.d)} = ${tn(a)}` },
    { tex: `b = 2\\,d\\cdot f = 2\\,(${dot(P.d, f)}) = ${tn(b)}` },
    { tex: `c = f\\cdot f - r^2 = ${tn(ff)} - ${tn(P.r * P.r)} = ${tn(cc)}` },
    { tex: `\\Delta = b^2 - 4ac = ${tp(b)}^2 - 4\\cdot${tp(a)}\\cdot${tp(cc)} = ${tn(D)}` },
  ];
  const rootsTex = `t_{0,1} = \\frac{-b \\mp \\sqrt{\\Delta}}{2a} = \\frac{${tn(-b)} \\mp ${tn(Math.sqrt(Math.max(D, 0)))}}{${tn(2 * a)}}`;
  const stepsB: SolutionStep[] = [
    ...(hit
      ? [{ tex: rootsTex }, { tex: `t_0 = ${tn(t0!)},\\quad t_1 = ${tn(t1!)}` }]
      : [{ text: 'Δ < 0: no real root, the ray misses (t0, t1 and t_hit: none).' }]),
    {
      text: `${caseWhy(h)} ${tHit !== null ? `t_hit = ${formatSignificant(tHit, 6, 'e')}.` : 't_hit: none.'} A hit needs Δ ≥ 0 and t ≥ 0.`,
    },
  ];
  const parts: Part[] = [
    {
      id: 'a',
      prompt: 'The quadratic a t² + b t + c = 0 and its discriminant.',
      answers: answers.slice(0, 4),
      hint: [
        { text: 'Write f = o − C (C the centre) and expand |f + t d|² = r²:' },
        {
          tex: `f = o - C = ${vecDisplay(f)}, \\qquad (d\\cdot d)\\,t^2 + 2\\,(d\\cdot f)\\,t + (f\\cdot f - r^2) = 0`,
        },
      ],
      steps: stepsA,
    },
    {
      id: 'b',
      prompt:
        'The roots (none on a miss), the hit (none if no root is ≥ 0), and the case: miss, tangent, two-hits, inside or behind.',
      paperPrompt:
        'The roots t0 ≤ t1, the hit t_hit (the nearest root with t ≥ 0, if any), and the case: miss, tangent, two hits, origin inside, or sphere behind.',
      answers: answers.slice(4),
      hint: [
        {
          text: 'The sign of Δ says how many real roots there are; if Δ ≥ 0 use the quadratic formula, then keep only roots with t ≥ 0:',
        },
        { tex: `t_{0,1} = \\frac{-b \\mp \\sqrt{\\Delta}}{2a}` },
      ],
      steps: stepsB,
    },
  ];
  const byName = Object.fromEntries(answers.map((x) => [x.name, x]));
  // follow-through from the student's own a, b, c, Δ and roots
  type Own = Parameters<FollowRule['matches']>[0];
  const N = (own: Own, n: string) => ownNumber(own, n);
  const ownRoots = (own: Own): [number | null, number | null] | null => {
    const A = N(own, 'a');
    const B = N(own, 'b');
    const Dd = N(own, 'discriminant');
    if (typeof A !== 'number' || typeof B !== 'number' || typeof Dd !== 'number' || A === 0) return null;
    if (Dd < 0) return [null, null];
    const r0 = (-B - Math.sqrt(Dd)) / (2 * A);
    const r1 = (-B + Math.sqrt(Dd)) / (2 * A);
    return [Math.min(r0, r1), Math.max(r0, r1)];
  };
  byName.discriminant.follow = [
    {
      from: ['a', 'b', 'c'],
      matches: (own, x) => {
        const [A, B, C] = [N(own, 'a'), N(own, 'b'), N(own, 'c')];
        return (
          typeof A === 'number' &&
          typeof B === 'number' &&
          typeof C === 'number' &&
          closeTo(x, B * B - 4 * A * C)
        );
      },
    },
  ];
  byName.t0.follow = [
    { from: ['a', 'b', 'discriminant'], matches: (own, x) => closeTo(x, ownRoots(own)?.[0]) },
  ];
  byName.t1.follow = [
    { from: ['a', 'b', 'discriminant'], matches: (own, x) => closeTo(x, ownRoots(own)?.[1]) },
  ];
  byName['t-hit'].follow = [
    {
      from: ['t0', 't1'],
      matches: (own, x) => {
        const r = [N(own, 't0'), N(own, 't1')];
        if (r.some((t) => t === undefined)) return false;
        const ahead = r.filter((t): t is number => typeof t === 'number' && t >= 0);
        return closeTo(x, ahead.length ? Math.min(...ahead) : null);
      },
    },
  ];
  byName.case.follow = [
    {
      from: ['discriminant', 't0', 't1'],
      matches: (own, x) => {
        const Dd = N(own, 'discriminant');
        const r0 = N(own, 't0');
        const r1 = N(own, 't1');
        if (typeof Dd !== 'number' || r0 === undefined || r1 === undefined) return false;
        let want: string;
        if (Dd < 0) want = 'miss';
        else if (Dd === 0) want = 'tangent';
        else if (r0 === null || r1 === null) return false;
        else {
          const lo = Math.min(r0, r1);
          const hi = Math.max(r0, r1);
          want = lo >= 0 ? 'two-hits' : hi >= 0 ? 'inside' : 'behind';
        }
        return x === want;
      },
    },
  ];
  const texOf = (x: number | null) => (x === null ? '\\text{none}' : tn(x));
  byName.a.tex = `a = ${tn(a)}`;
  byName.b.tex = `b = ${tn(b)}`;
  byName.c.tex = `c = ${tn(cc)}`;
  byName.discriminant.tex = `\\Delta = ${tn(D)}`;
  byName.t0.tex = `t_0 = ${texOf(t0)}`;
  byName.t1.tex = `t_1 = ${texOf(t1)}`;
  byName['t-hit'].tex = `t_{\\text{hit}} = ${texOf(tHit)}`;
  byName.case.tex = `\\text{${h.case}}`;
  return {
    question: 'q5',
    seed,
    title: 'Ray–sphere intersection',
    statement: `The ray p(t) = o + t d with o = ${vecDisplay(P.o)}, d = ${vecDisplay(P.d)} and the sphere with centre C = ${vecDisplay(P.c)} and radius r = ${P.r}. Write |o + t d − C|² = r² as a t² + b t + c = 0 and give a, b, c, the discriminant Δ, the roots t0 ≤ t1, the hit t_hit (nearest root with t ≥ 0) and the case.`,
    givens: [
      { name: 'o', label: 'ray origin o', value: vecValue(P.o), display: vecDisplay(P.o) },
      { name: 'd', label: 'direction d', value: vecValue(P.d), display: vecDisplay(P.d) },
      { name: 'c', label: 'centre C', value: vecValue(P.c), display: vecDisplay(P.c) },
      { name: 'r', label: 'radius r', value: String(P.r), display: String(P.r) },
    ],
    parts,
    intro: [],
    solution: assembleSolution([], parts),
    sceneHref: `#/ray-sphere?${query({ o: vecValue(P.o), d: vecValue(P.d), c: vecValue(P.c), r: P.r, method: 'naive' })}`,
    sceneLabel: 'Open this ray and sphere in the ray–sphere scene',
    notes: [],
  };
}

function caseWhy(h: RaySphereHit): string {
  switch (h.case) {
    case 'miss':
      return 'Δ < 0: the line passes the sphere (miss).';
    case 'tangent':
      return 'Δ = 0: one double root, the ray grazes the sphere (tangent).';
    case 'two-hits':
      return 'Δ > 0 and both roots ≥ 0: the ray enters at t0 and leaves at t1 (two-hits).';
    case 'inside':
      return 'Δ > 0, t0 < 0 ≤ t1: the origin is inside the sphere; the hit is t1 (inside).';
    default:
      return 'Δ ≥ 0 but both roots are negative: the sphere is behind the origin, no hit (behind).';
  }
}
