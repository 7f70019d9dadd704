/**
 * The scene registry: metadata for the home page (static, tiny) and one lazy loader per scene.
 * `import.meta.glob` makes each `src/scenes/<id>/index.ts` its own chunk, loaded only when the
 * scene is opened; a scene whose folder has no index.ts yet shows as "not built yet".
 */
import type { SceneModule } from '../app/scene';

export interface SceneInfo {
  id: string;
  /** Hash path, e.g. '/hemisphere'. */
  path: string;
  title: string;
  /** Which exam questions the scene teaches. */
  questions: string;
  blurb: string;
  /** Query opening the scene in the exam question's configuration ('' = defaults). */
  examQuery: string;
  /**
   * The exam's sub-questions this scene teaches, in page order (`part=1c` in a link lands on the
   * element with id `part-1c`).
   */
  parts: readonly string[];
}

export const SCENES: readonly SceneInfo[] = [
  {
    id: 'hemisphere',
    path: '/hemisphere',
    title: 'Sampling a hemisphere',
    questions: 'Q1 · Q2',
    blurb:
      'Normalize p(ω) = k cos θ e^φ, find its marginals and CDFs, invert them, and watch the samples land.',
    examQuery: 'lobe=exam',
    parts: ['1a', '1b', '1c', '1d', '2a', '2b', '2c'],
  },
  {
    id: 'monte-carlo',
    path: '/monte-carlo',
    title: 'Monte Carlo integration',
    questions: 'Q2 · Q4',
    blurb: 'Estimate ∫₀² (x + 2)² dx with uniform and importance sampling, and see how fast each converges.',
    examQuery: 'samples=1.16,1.98,0.54,1.26',
    parts: ['4a', '4b', '4c', '4d'],
  },
  {
    id: 'texture',
    path: '/texture',
    title: 'Texture lookup',
    questions: 'Q3',
    blurb: 'Nearest-neighbour and bilinear lookup on a texel grid, and the spherical (u, v) mapping.',
    examQuery: 'u=0.4&v=0.24',
    parts: ['3a', '3b', '3c'],
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
  },
  {
    id: 'area-light',
    path: '/area-light',
    title: 'Solid angle and area lights',
    questions: 'Q6',
    blurb: 'dω = dA cos θ_l / r², the rendering equation over a light’s area, and three ways to sample it.',
    examQuery: '',
    parts: ['6a', '6b', '6c'],
  },
];

const loaders = import.meta.glob<SceneModule>('./*/index.ts');

/** The lazy loader of a scene, or null if the scene has not been built yet. */
export function sceneLoader(id: string): (() => Promise<SceneModule>) | null {
  return (loaders[`./${id}/index.ts`] as (() => Promise<SceneModule>) | undefined) ?? null;
}

export function findScene(path: string): SceneInfo | undefined {
  return SCENES.find((s) => s.path === path);
}

/** Where each exam question starts: its scene and its first part. */
export function questionStart(q: number): { scene: SceneInfo; part: string } | null {
  for (const scene of SCENES) {
    const part = scene.parts.find((p) => p.startsWith(String(q)));
    if (part) return { scene, part };
  }
  return null;
}

/** The scene that teaches a part (e.g. '2c'), if any. */
export function sceneOfPart(part: string): SceneInfo | undefined {
  return SCENES.find((s) => s.parts.includes(part));
}
