/**
 * The catalogue's teaching texts (the rest of the catalogue is ./catalogue.ts): each exam question's
 * lesson plan for the teacher's guide (presets: links that open a scene in a telling configuration,
 * with what to ask the class) and the misconceptions each scene is built to make visible. Kept apart
 * from the catalogue's index because only the guide reads them, so they load with the guide's chunk
 * and not with the entry.
 */
import { questionInfo, sceneById, type QuestionInfo, type SceneId, type SceneInfo } from './catalogue';
import { SHELL_PARAMS } from './params';

/** One step of a lesson plan: a link that opens a scene in a telling configuration. */
export interface LessonPreset {
  /** The scene the preset opens, when it is not the question's own scene. */
  scene?: SceneId;
  /** URL parameters (plain values; the link encodes them, so `+` stays a plus). */
  params: Readonly<Record<string, string>>;
  title: string;
  /** What the class sees. */
  shows: string;
  /** What to ask the class at this step. */
  ask: string;
  /** The exam part the link lands on (`part=`). */
  part?: string;
  /**
   * The link opens with `ask=1`: results hidden until revealed, for a question the class answers
   * before it sees them (false where the question is about what is on screen).
   */
  askFirst?: boolean;
}

/** Each question's lesson presets, by question number. */
export const LESSON_PRESETS: Readonly<Record<QuestionInfo['n'], readonly LessonPreset[]>> = {
  1: [
    {
      params: { lobe: 'exam', n: '2000', t: '0' },
      askFirst: true,
      title: 'The exam’s density, 2,000 samples',
      shows:
        'p(ω) = k cos θ eᵠ with its normalization k, the marginals, the CDFs and the inverted samples on the hemisphere.',
      ask: 'Before you reveal the points: where will they bunch up? Which factor decides the direction in θ, which in φ?',
    },
    {
      params: { lobe: 'exam', jacobian: 'inverted' },
      part: '1b',
      askFirst: true,
      title: 'The Jacobian written upside down',
      shows:
        'The key also grades p(θ, φ) = p(ω) / sin θ ∝ cot θ eᵠ; the scene shows why it is not a density: its θ-integral diverges at θ → 0.',
      ask: 'Integrate cot θ from 0 to π/2. Can a function whose integral is infinite be normalized? Where did the sin θ come from?',
    },
    {
      params: { lobe: 'uniform', n: '2000', t: '0' },
      askFirst: true,
      title: 'Uniform over solid angle is not uniform in θ',
      shows:
        'A uniform density per steradian, p(ω) = 1/(2π): the θ histogram follows sin θ, not a flat line.',
      ask: 'Before you reveal the points: will directions uniform per steradian be uniform in θ? What is p(θ) when p(ω) is constant?',
    },
    {
      params: { lobe: 'exam', points: 'stratified', n: '400', t: '0' },
      askFirst: true,
      title: 'The same inversion, stratified inputs',
      shows:
        'Stratified (ξ₁, ξ₂) through the same inverse CDFs: the warped grid shows how the inversion stretches the unit square.',
      ask: 'Before you play the warp: where will the grid be stretched, where squeezed? How does that relate to p?',
    },
    {
      params: { lobe: 'exam', n: '100', seed: '7' },
      part: '1d',
      title: 'Only 100 samples',
      shows: 'The χ² test of the histograms against the marginals with few samples.',
      ask: 'The histogram is ragged. Is the inversion wrong, or is this chance? What does the p-value tell you, and what does it not?',
    },
  ],
  2: [
    {
      params: { lobe: 'uniform', f: 'cos(theta)' },
      part: '2a',
      askFirst: true,
      title: 'Uniform sampling (Q2a)',
      shows: '⟨I⟩ = (2π/N) Σ f(Xᵢ) for f = cos θ, against the exact integral π.',
      ask: 'Where does the factor 2π come from? What would go wrong if you forgot it?',
    },
    {
      params: { lobe: 'cosine', f: 'cos(theta)' },
      part: '2b',
      askFirst: true,
      title: 'Importance sampling with p ∝ f (Q2b)',
      shows: 'Cosine-weighted samples for f = cos θ: every term f/p is the same number.',
      ask: 'What is f(X)/p(X) for each sample? What is the variance of this estimator, and why is this a special case?',
    },
    {
      params: { lobe: 'exam', f: 'cos(theta)' },
      part: '2b',
      askFirst: true,
      title: 'The exam’s density as the sampling pdf',
      shows: 'Importance sampling f = cos θ with p(ω) = k cos θ eᵠ: unbiased, but f/p now varies with φ.',
      ask: 'Is this estimator still unbiased? Which samples carry the largest weights f/p, and why?',
    },
    {
      params: { lobe: 'phong', exponent: '20', f: 'cos(theta)' },
      part: '2b',
      askFirst: true,
      title: 'A lobe much narrower than f',
      shows: 'A Phong lobe cos²⁰ θ sampling f = cos θ: f/p ∝ cos⁻¹⁹ θ grows without bound near the horizon.',
      ask: 'Unbiasedness needs p > 0 wherever f ≠ 0, and it holds here. Will the estimates be steady? What is the variance?',
    },
    {
      scene: 'monte-carlo',
      params: { hn: '4' },
      askFirst: true,
      title: 'Unbiased, one estimate at a time (Q2c)',
      shows:
        'The histogram of many independent estimates, each from only 4 samples, with its mean against the exact integral.',
      ask: 'Before you reveal the histogram: will a single 4-sample estimate be right? Where will the mean of many be? State E[⟨I⟩] = ∫ f with linearity of expectation and E[g(X)] = ∫ g p.',
    },
  ],
  3: [
    {
      params: { u: '0.4', v: '0.24' },
      part: '3a',
      askFirst: true,
      title: 'The exam’s lookup (Q3a, Q3b)',
      shows:
        'The 5 × 5 grid, the query point, its nearest node and the bilinear steps with the cell-size division.',
      ask: 'Which node is nearest? Which four nodes enter the bilinear lookup, and with which weights?',
    },
    {
      params: { u: '0.4', v: '0.24', vflip: '1' },
      part: '3b',
      askFirst: true,
      title: 'v measured from the top',
      shows: 'The key accepts v′ = 1 − v (image rows grow downward): different rows, a different answer.',
      ask: 'Predict the bilinear value with v′ = 1 − v. Both conventions exist in real APIs: which one does the exam’s figure use, and how would you tell from a picture?',
    },
    {
      params: { u: '0.4', v: '0.24', align: 'center' },
      part: '3a',
      askFirst: true,
      title: 'Values at texel centres',
      shows:
        'The GPU convention: node (i, j) sits at ((i + ½)/N, (j + ½)/N), so the same (u, v) falls in another cell.',
      ask: 'Why does a GPU put values at texel centres? Does the nearest value change here, and does the bilinear one?',
    },
    {
      params: { u: '1.3', v: '0.24', wrap: 'repeat' },
      part: '3b',
      askFirst: true,
      title: 'Outside [0, 1]: repeat',
      shows: 'u = 1.3 with repeat addressing; switch the addressing to clamp and mirror to compare.',
      ask: 'Predict the value at u = 1.3 under clamp, repeat and mirror before switching. Where would each be used?',
    },
    {
      params: { x: '1', y: '1', z: '1.4142135623730951', normalize: '0' },
      part: '3c',
      askFirst: true,
      title: 'The sphere point, not normalized (Q3c)',
      shows: 'u = φ and v = θ in radians, used directly as texture coordinates: the lookup leaves [0, 1].',
      ask: 'What do (2π, π) do to φ and θ? Which answer does the lookup give with and without them, and which is the texture’s?',
    },
  ],
  4: [
    {
      params: { samples: '1.16,1.98,0.54,1.26' },
      part: '4b',
      askFirst: true,
      title: 'The exam’s four samples (Q4b)',
      shows: 'f(xᵢ), p(xᵢ) = 1/2 and each term f/p for the four given samples, against the exact 56/3.',
      ask: 'Compute one term by hand before you reveal them. Will the estimate be 56/3? Would a fifth sample bring it closer?',
    },
    {
      params: { pdf: 'proportional' },
      part: '4c',
      askFirst: true,
      title: 'p proportional to f (Q4c)',
      shows: 'p(x) = 3(x + 2)²/56: every term f/p equals the integral, so the variance is zero.',
      ask: 'Before you reveal the terms: what is each f/p? Why can’t a renderer sample in proportion to f itself? What did we need to know to write this p?',
    },
    {
      params: { pdf: 'linear', t: '0' },
      part: '4d',
      askFirst: true,
      title: 'A pdf that is close to f',
      shows: 'The ramp through |f(a)| and |f(b)|: not proportional to f, yet far less variance than uniform.',
      ask: 'Before the race runs: will the ramp’s estimates spread less than the uniform ones? What makes a pdf good in practice?',
    },
    {
      params: { strategy: 'stratified', t: '0' },
      part: '4d',
      askFirst: true,
      title: 'Stratified samples and the convergence plot (Q4d)',
      shows: 'The error against N for stratified uniform samples, with the 1/√N reference line.',
      ask: 'Before the race runs: will the error fall faster than with independent samples? Is s/√N still an honest error bar here?',
    },
    {
      params: { f: '1/sqrt(x)', a: '0', b: '1' },
      askFirst: true,
      title: 'A finite integral with infinite variance',
      shows:
        '∫₀¹ 1/√x dx = 2 is finite, but f² is not integrable: uniform sampling is unbiased with infinite variance.',
      ask: 'Is the estimator unbiased? Will the running estimate settle as N grows? Which pdf would tame it?',
    },
  ],
  5: [
    {
      params: { o: '-3,0.3,0.2', d: '1,0,0', c: '0,0,0', r: '1' },
      part: '5',
      askFirst: true,
      title: 'Two hits',
      shows: 'Two roots t₀ < t₁, both ahead of the origin.',
      ask: 'Which root is the visible hit? What does the other one mean physically?',
    },
    {
      params: { o: '0.2,-0.3,0.1', d: '1,0.5,0', c: '0,0,0', r: '1' },
      part: '5',
      askFirst: true,
      title: 'Origin inside, d not unit length',
      shows: 'One root behind, one ahead: the hit is the exit point. d is not normalized, so a = d·d ≠ 1.',
      ask: 'Why is the smaller root not the answer here? What changes in the formula when d is not a unit vector, and what stays the same?',
    },
    {
      params: { o: '3,0.3,0.2', d: '1,0,0', c: '0,0,0', r: '1' },
      part: '5',
      askFirst: true,
      title: 'Sphere behind the ray',
      shows: 'Δ > 0, yet both roots are negative: no hit.',
      ask: 'Is Δ ≥ 0 enough for a hit? Why does a renderer also use tₘᵢₙ > 0 (think of a ray leaving a surface)?',
    },
    {
      params: { o: '-5,1,0', d: '1,0,0', c: '0,0,0', r: '1' },
      part: '5',
      askFirst: true,
      title: 'Tangent',
      shows: 'Δ = 0 exactly: one double root.',
      ask: 'Hit or miss? What would a tiny rounding error in Δ do here?',
    },
    {
      params: { o: '0,0,0', d: '1,5e-9,0', c: '100000000,0,0', r: '1', method: 'naive' },
      part: '5',
      askFirst: true,
      title: 'The textbook form breaks far away',
      shows:
        'A small sphere 10⁸ radii away: the textbook b² − 4ac′ rounds to zero; switch to the stable method to compare.',
      ask: 'Predict the textbook form’s Δ here. Which subtraction loses all the digits? How do the stable forms (Ray Tracing Gems, ch. 7) avoid it?',
    },
  ],
  6: [
    {
      params: { lc: '0,0,2', ls: '1,1', tilt: '0' },
      part: '6a',
      askFirst: true,
      title: 'A light overhead (Q6a, Q6b)',
      shows: 'dω = dA cos θₗ / r² on a patch of the light, and Lₒ against the exact reference.',
      ask: 'Derive dω from similar triangles. Which factor shrinks a patch’s solid angle fastest as it moves to the light’s edge?',
    },
    {
      params: { lc: '0,0,0.25', ls: '2,2', tilt: '0', strategy: 'area', t: '0' },
      part: '6c',
      askFirst: true,
      title: 'A big light close by, sampled by area (Q6c)',
      shows:
        'Uniform area sampling, pdf 1/|A| per unit area: r² varies wildly over the light, so the estimate is noisy.',
      ask: 'Which samples get the largest weights |A| cos θ cos θₗ / r²? Which strategy would you choose here?',
    },
    {
      params: { lc: '0,0,10', ls: '1,1', tilt: '0', strategy: 'cosine', t: '0' },
      part: '6c',
      askFirst: true,
      title: 'A small far light, cosine sampling',
      shows: 'Cosine-weighted directions almost never hit a small distant light.',
      ask: 'Before the samples are drawn: how many cosine-weighted directions will hit the light? Will the estimator be biased, or only noisy? What would area sampling do?',
    },
    {
      params: { lc: '0,1,1.5', ls: '1.5,1', tilt: '-45' },
      part: '6a',
      askFirst: true,
      title: 'A tilted light',
      shows: 'cos θₗ varies over the light: it is not one number per light.',
      ask: 'Where on the light is cos θₗ largest as seen from p? How does that change the contribution of each patch?',
    },
    {
      params: { occluder: '1' },
      part: '6b',
      askFirst: true,
      title: 'An occluder: visibility',
      shows: 'V(x, y) enters the integrand: part of the light is hidden from p.',
      ask: 'Where is V in the estimator? Can the exact reference still be written in closed form?',
    },
  ],
};

/** The misconceptions each scene addresses, by scene. */
export const MISCONCEPTIONS: Readonly<Record<SceneId, { title: string; items: readonly string[] }>> = {
  hemisphere: {
    title: 'Sampling a hemisphere (Q1, Q2)',
    items: [
      '“Uniform on the hemisphere means uniform in θ.” Uniform per steradian gives p(θ) = sin θ: few samples near the pole.',
      '“p(ω) and p(θ, φ) are the same function.” They differ by the Jacobian sin θ; writing it upside down gives a density that does not integrate.',
      '“Any non-negative function can be sampled.” It must integrate to 1 over solid angle (not over the θ–φ rectangle) before its CDF can be inverted.',
      '“arccos(1 − 2ξ)/2 and arcsin √ξ are the same formula.” Equal in exact arithmetic, not in floating point near ξ → 0.',
      '“Importance sampling always reduces variance.” A lobe narrower than f makes f/p unbounded.',
    ],
  },
  'monte-carlo': {
    title: 'Monte Carlo integration (Q2, Q4)',
    items: [
      '“Unbiased means each estimate is right.” Only the mean of the estimates is; each one scatters.',
      '“More samples fix any estimator.” They fix the variance of an unbiased one, not a bias (p = 0 where f ≠ 0).',
      '“s/√N is the error of every estimate.” Not for stratified or quasi-random points, whose errors are not independent.',
      '“The zero-variance pdf is a method.” Sampling p ∝ f needs ∫ f, the answer itself.',
      '“A finite integral has a finite-variance estimator.” ∫₀¹ 1/√x dx is finite, its variance is not.',
    ],
  },
  texture: {
    title: 'Texture lookup (Q3)',
    items: [
      '“v grows downward like image rows.” The exam’s v grows upward; the flipped convention gives another answer.',
      '“Texel values sit at the corners.” Here they do (the exam); on a GPU they sit at texel centres.',
      '“Bilinear is the average of the four neighbours.” It weights them by the distances to the query point.',
      '“Spherical angles are texture coordinates.” They must be divided by (2π, π) to land in [0, 1].',
      '“Coordinates outside [0, 1] are errors.” Clamp, repeat and mirror each give a defined value.',
    ],
  },
  'ray-sphere': {
    title: 'Ray–sphere intersection (Q5)',
    items: [
      '“Δ ≥ 0 means a hit.” The roots may both be behind the origin.',
      '“The smaller root is the hit.” Not when the origin is inside the sphere (t₀ < 0).',
      '“d must be a unit vector.” The quadratic works for any d; a = d·d then is not 1.',
      '“The textbook formula is exact.” b² − 4ac′ and −b ± √Δ cancel catastrophically far away and at grazing angles.',
      '“t ≥ 0 is enough in a renderer.” A ray leaving a surface re-hits it at t ≈ 0 unless tₘᵢₙ > 0.',
    ],
  },
  'area-light': {
    title: 'Solid angle and area lights (Q6)',
    items: [
      '“A light’s contribution falls off as 1/r², full stop.” The cosines at the receiver and at the light matter as much.',
      '“cos θ and cos θₗ are the same angle.” One is at the shading point, the other at the light.',
      '“Uniform over the light’s area is uniform in solid angle.” The Jacobian cos θₗ / r² makes them differ.',
      '“Cosine sampling is always best.” It rarely hits a small or distant light.',
      '“A light facing away still lights the point.” Its back emits nothing: Lₒ = 0.',
    ],
  },
};

/** The scene a lesson preset opens: its own, or the question's. */
export function presetScene(n: QuestionInfo['n'], p: LessonPreset): SceneInfo {
  return sceneById(p.scene ?? (questionInfo(n) as QuestionInfo).scene);
}

/**
 * The `ask` text of the lesson preset whose link `query` is (its scene parameters exactly, whatever
 * the shell flags), or null: an `ask=1` page opened from the guide puts the preset's own question.
 */
export function presetAskFor(scene: string, query: string): string | null {
  let sp: URLSearchParams;
  try {
    sp = new URLSearchParams(query);
  } catch {
    return null;
  }
  const given = new Map<string, string>();
  for (const [k, v] of sp) {
    if (!(SHELL_PARAMS as readonly string[]).includes(k) && !given.has(k)) given.set(k, v);
  }
  for (const q of QUESTION_NUMBERS) {
    for (const p of LESSON_PRESETS[q]) {
      if (presetScene(q, p).id !== scene) continue;
      const entries = Object.entries(p.params);
      if (entries.length === given.size && entries.every(([k, v]) => given.get(k) === v)) return p.ask;
    }
  }
  return null;
}

const QUESTION_NUMBERS: readonly QuestionInfo['n'][] = [1, 2, 3, 4, 5, 6];
