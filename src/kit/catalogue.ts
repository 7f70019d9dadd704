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
      'Normalize p(ω) = k cos θ e^φ, find its marginals and CDFs, invert them, and watch the samples land.',
    examQuery: 'lobe=exam',
    parts: ['1a', '1b', '1c', '1d', '2a', '2b', '2c'],
    keyReadout: 'k',
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
  },
  {
    id: 'area-light',
    path: '/area-light',
    title: 'Solid angle and area lights',
    questions: 'Q6',
    blurb: 'dω = dA cos θ_l / r², the rendering equation over a light’s area, and three ways to sample it.',
    examQuery: '',
    parts: ['6a', '6b', '6c'],
    keyReadout: 'reference',
  },
] as const satisfies readonly SceneInfoSpec[];

export const QUESTIONS: readonly QuestionInfo[] = [
  {
    n: 1,
    title: 'Sampling a hemisphere PDF by inversion',
    text: 'Normalize p(ω) = k cos θ e^φ, find its marginals and CDFs, and invert them to draw directions.',
    scene: 'hemisphere',
    query: 'lobe=exam',
    practice: { id: 'q1', blurb: 'Normalize k cosᵐθ e^(aφ), its marginals, CDFs and inversion formulas.' },
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
    text: 'dω = dA cos θ_l / r², the rendering equation over a light’s area, and area-light sampling.',
    scene: 'area-light',
    practice: {
      id: 'q6',
      blurb: 'dω = dA cos θ_l / r² for a patch, and the area-sampling estimator from given points.',
    },
  },
];

/** A scene's id, which is also its folder under src/scenes/ and its route. */
export type SceneId = (typeof SCENE_LIST)[number]['id'];

export interface SceneInfo extends SceneInfoSpec {
  id: SceneId;
}

export const SCENES: readonly SceneInfo[] = SCENE_LIST;

export const SCENE_IDS: readonly SceneId[] = SCENES.map((s) => s.id);

export function isSceneId(s: string): s is SceneId {
  return (SCENE_IDS as readonly string[]).includes(s);
}

export function sceneById(id: SceneId): SceneInfo {
  return SCENES.find((s) => s.id === id) as SceneInfo;
}

/** The scene at a hash path ('/texture'), if any. */
export function findScene(path: string): SceneInfo | undefined {
  return SCENES.find((s) => s.path === path);
}

export function questionInfo(n: number): QuestionInfo | undefined {
  return QUESTIONS.find((q) => q.n === n);
}

/** Where an exam question starts: its scene and its first part there. */
export function questionStart(q: number): { scene: SceneInfo; part: string } | null {
  for (const scene of SCENES) {
    const part = scene.parts.find((p) => p.startsWith(String(q)));
    if (part) return { scene, part };
  }
  return null;
}
