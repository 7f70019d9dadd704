/**
 * The catalogue: every exam question and every scene, in one place. The shell (router, home page,
 * scene registry), the teacher's guide, the practice index, the perf scripts and the browser tests
 * all read it; nothing else spells out the list of scenes. Pure data and tiny look-ups: no imports,
 * so Node scripts can load it too (scripts/catalogue.mjs). The teacher's texts that go with it (each
 * question's lesson presets, each scene's misconceptions) are in ./lessons.ts, which only the guide
 * loads: the shell's entry stays small.
 *
 * A scene (a route, e.g. `#/texture`) teaches one or more exam questions; a question's parts
 * (`1a`, `1b`, …) are anchors on its scene's page (`part=1c` lands on the element `part-1c`).
 */

/** What the catalogue says of a scene. */
export interface SceneInfoSpec {
  id: string;
  /** Hash path, e.g. '/hemisphere'. */
  path: string;
  title: string;
  /** Which exam questions the scene teaches, for display ('Q1 · Q2'). */
  questions: string;
  blurb: string;
  /** Query opening the scene in the exam's configuration ('' = the defaults). */
  examQuery: string;
  /** The exam's sub-questions this scene teaches, in page order. */
  parts: readonly string[];
  /** A readout (data-testid) the scene computes as soon as it opens: what shows it is working. */
  keyReadout: string;
  /**
   * Per part: the question to put to the class before its results are revealed (`ask=1` shows it
   * above the scene with a Reveal button). Parts where a prediction makes no sense have none.
   */
  predict?: Readonly<Partial<Record<string, string>>>;
}

export interface QuestionInfo {
  n: 1 | 2 | 3 | 4 | 5 | 6;
  /** The question's one title: the home page, its scene's heading, the guide and practice use it. */
  title: string;
  /** The question in one sentence (home page). */
  text: string;
  /** The scene that teaches it. */
  scene: SceneId;
  /** Query the home page opens the scene with (default: the scene's examQuery). */
  query?: string;
  /** Its practice question: route `#/practice/<id>`, and a blurb for the practice index. */
  practice: { id: string; blurb: string };
}

const SCENE_LIST = [
  {
    id: 'hemisphere',
    path: '/hemisphere',
    title: 'Sampling a hemisphere',
    questions: 'Q1 · Q2',
    blurb:
      'Normalize p(ω) = k cos θ eᵠ, find its marginals and CDFs, invert them, and watch the samples land.',
    examQuery: 'lobe=exam',
    parts: ['1a', '1b', '1c', '1d', '2a', '2b', '2c'],
    keyReadout: 'k',
    predict: {
      '1a': 'Before you reveal k: is it larger or smaller than 1/(2π), the constant of a uniform density? What does dω = sin θ dθ dφ add to the integral?',
      '1b': 'Predict the marginals p(θ) and p(φ) before you reveal them: where does each one peak, and where does the Jacobian sin θ go?',
      '1c': 'Sketch the CDFs P(θ) and P(φ) before you reveal them: which one climbs slowly and then steeply, and why?',
      '1d': 'Before you reveal the points: where will they bunch up? Which factor decides the direction in θ, which in φ?',
      '2a': 'Uniform sampling: which factor multiplies the mean of f(Xᵢ), and how far from the exact integral do you expect the estimate to land?',
      '2b': 'Importance sampling: which samples carry the largest weights f(Xᵢ)/p(Xᵢ)? Will the estimate scatter more or less than the uniform one?',
      '2c': 'Many independent estimates, each from a few samples: where will the mean of their histogram be, and how wide will it be?',
    },
  },
  {
    id: 'monte-carlo',
    path: '/monte-carlo',
    title: 'Monte Carlo integration',
    questions: 'Q2 · Q4',
    blurb: 'Estimate ∫₀² (x + 2)² dx with uniform and importance sampling, and see how fast each converges.',
    examQuery: 'samples=1.16,1.98,0.54,1.26',
    parts: ['4a', '4b', '4c', '4d'],
    keyReadout: 'exact',
    predict: {
      '4a': 'Work out ∫₀² (x + 2)² dx by hand before you reveal it: which antiderivative, and roughly what value?',
      '4b': 'Predict the uniform estimate from the four samples 1.16, 1.98, 0.54, 1.26: above or below the exact integral, and why?',
      '4c': 'With p ∝ f, predict each term f(xᵢ)/p(xᵢ): how much do the terms differ from one another?',
      '4d': 'Predict the convergence plot: how fast does each estimator’s error fall as N grows, and which one falls lowest?',
    },
  },
  {
    id: 'texture',
    path: '/texture',
    title: 'Texture lookup',
    questions: 'Q3',
    blurb: 'Nearest-neighbour and bilinear lookup on a texel grid, and the spherical (u, v) mapping.',
    examQuery: 'u=0.4&v=0.24',
    parts: ['3a', '3b', '3c'],
    keyReadout: 'bilinear',
    predict: {
      '3a': 'Which node is nearest to (u, v), and what value does the nearest-neighbour lookup return?',
      '3b': 'Predict the bilinear value: which four nodes enter, with which weights? Is it nearer the nearest node’s value or the four’s average?',
      '3c': 'From the point on the sphere, predict (u, v) with and without dividing by (2π, π): which of the two lands in [0, 1]?',
    },
  },
  {
    id: 'ray-sphere',
    path: '/ray-sphere',
    title: 'Ray–sphere intersection',
    questions: 'Q5',
    blurb:
      'The quadratic, its discriminant, every hit case, and what floating point does to the textbook form.',
    examQuery: '',
    parts: ['5'],
    keyReadout: 't-hit',
    predict: {
      '5': 'Before you reveal the roots: how many real roots does the quadratic have here, and which one (if any) is the visible hit?',
    },
  },
  {
    id: 'area-light',
    path: '/area-light',
    title: 'Solid angle and area lights',
    questions: 'Q6',
    blurb: 'dω = dA cos θₗ / r², the rendering equation over a light’s area, and three ways to sample it.',
    examQuery: '',
    parts: ['6a', '6b', '6c'],
    keyReadout: 'reference',
    predict: {
      '6a': 'As a patch of the light moves towards the light’s edge, which factors of dω = dA cos θₗ / r² shrink it, and which shrinks it fastest?',
      '6b': 'Before you reveal Lₒ: which parts of the light contribute most to the shading point, and why?',
      '6c': 'Uniform area sampling: which samples get the largest weights |A| cos θ cos θₗ / r²? How noisy will the estimate be?',
    },
  },
] as const satisfies readonly SceneInfoSpec[];

export const QUESTIONS: readonly QuestionInfo[] = [
  {
    n: 1,
    title: 'Sampling a hemisphere PDF by inversion',
    text: 'Normalize p(ω) = k cos θ eᵠ, find its marginals and CDFs, and invert them to draw directions.',
    scene: 'hemisphere',
    query: 'lobe=exam',
    practice: { id: 'q1', blurb: 'Normalize k cosᵐθ eᵃᵠ, its marginals, CDFs and inversion formulas.' },
  },
  {
    n: 2,
    title: 'Monte Carlo estimators on the hemisphere',
    text: 'Uniform and importance-sampled estimators of ∫ f dω, and why both are unbiased.',
    scene: 'hemisphere',
    query: 'lobe=exam&f=cos(theta)',
    practice: {
      id: 'q2',
      blurb: 'Uniform and importance-sampled estimates from given directions; which has zero variance.',
    },
  },
  {
    n: 3,
    title: 'Texture lookup',
    text: 'Nearest neighbour and bilinear lookup at (0.4, 0.24), and the spherical (u, v) mapping.',
    scene: 'texture',
    query: 'u=0.4&v=0.24',
    practice: {
      id: 'q3',
      blurb: 'Nearest and bilinear lookup on a texel grid, and the spherical (u, v) of a point.',
    },
  },
  {
    n: 4,
    title: 'Monte Carlo integration in 1D',
    text: '∫₀² (x + 2)² dx by uniform against importance sampling with four given samples, and how each converges.',
    scene: 'monte-carlo',
    query: 'samples=1.16,1.98,0.54,1.26',
    practice: {
      id: 'q4',
      blurb: 'The exact integral, the uniform and the importance-sampled estimate from given samples.',
    },
  },
  {
    n: 5,
    title: 'Ray–sphere intersection',
    text: 'The quadratic, its discriminant, which root is the hit, and floating-point robustness.',
    scene: 'ray-sphere',
    practice: { id: 'q5', blurb: 'The quadratic, its discriminant, the roots, the hit and the case.' },
  },
  {
    n: 6,
    title: 'Solid angle and area lights',
    text: 'dω = dA cos θₗ / r², the rendering equation over a light’s area, and area-light sampling.',
    scene: 'area-light',
    practice: {
      id: 'q6',
      blurb: 'dω = dA cos θₗ / r² for a patch, and the area-sampling estimator from given points.',
    },
  },
];

/** A scene's id, which is also its folder under src/scenes/ and its route. */
export type SceneId = (typeof SCENE_LIST)[number]['id'];

export interface SceneInfo extends SceneInfoSpec {
  id: SceneId;
}

export const SCENES: readonly SceneInfo[] = SCENE_LIST;

/**
 * The labs: pages routed like scenes (same shell, URL rules and share bar) that compose several exam
 * answers instead of teaching one. They are not in {@link SCENES}, so the lists of exam scenes (the
 * home page, the guide, the per-scene browser checks) do not include them.
 */
const LAB_LIST = [
  {
    id: 'render',
    path: '/render',
    title: 'The render lab',
    questions: 'Q1–Q6',
    blurb:
      'A small progressive path tracer of the exam’s own objects, where every pixel opens onto the six answers at work.',
    examQuery: '',
    parts: [],
    keyReadout: 'spp',
  },
] as const satisfies readonly SceneInfoSpec[];

/** A lab's id, which is also its folder under src/scenes/ and its route. */
export type LabId = (typeof LAB_LIST)[number]['id'];

/** What the router knows of a page it hosts like a scene: an exam scene or a lab. */
export interface PageInfo extends SceneInfoSpec {
  id: SceneId | LabId;
}

export const LABS: readonly PageInfo[] = LAB_LIST;

/** The app's pages that are neither scenes nor labs, by name: their routes and titles. */
export const PAGES = {
  practice: { path: '/practice', title: 'Practice' },
  guide: { path: '/guide', title: 'Teacher’s guide' },
  deck: { path: '/deck', title: 'Lecture decks' },
  results: { path: '/results', title: 'Class results' },
  accessibility: { path: '/accessibility', title: 'Accessibility' },
} as const;

export const SCENE_IDS: readonly SceneId[] = SCENES.map((s) => s.id);

export function isSceneId(s: string): s is SceneId {
  return (SCENE_IDS as readonly string[]).includes(s);
}

export function sceneById(id: SceneId): SceneInfo {
  return SCENES.find((s) => s.id === id) as SceneInfo;
}

/** The scene or lab at a hash path ('/texture', '/render'), if any. */
export function findScene(path: string): PageInfo | undefined {
  return SCENES.find((s) => s.path === path) ?? LABS.find((s) => s.path === path);
}

export function questionInfo(n: number): QuestionInfo | undefined {
  return QUESTIONS.find((q) => q.n === n);
}

/**
 * The prediction prompt of an `ask=1` page: the one of `part` when it has one, else the scene's first
 * part's that has one; null when the scene asks nothing.
 */
export function predictPrompt(scene: SceneInfoSpec, part: string | null): string | null {
  const p = scene.predict;
  if (!p) return null;
  const own = part ? p[part] : undefined;
  if (own) return own;
  for (const q of scene.parts) {
    const t = p[q];
    if (t) return t;
  }
  return null;
}

/** Where an exam question starts: its scene and its first part there. */
export function questionStart(q: number): { scene: SceneInfo; part: string } | null {
  for (const scene of SCENES) {
    const part = scene.parts.find((p) => p.startsWith(String(q)));
    if (part) return { scene, part };
  }
  return null;
}
