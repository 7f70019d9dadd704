/**
 * The teacher's guide's content, read from the catalogue (src/kit/catalogue.ts, lessons.ts): for each exam
 * question, a lesson plan of presets (links that open a scene in a telling configuration, with what
 * to ask the class), and the misconceptions each scene addresses. Every preset's parameters are
 * checked against the scene's schema by tests/guide/lessons.test.ts and opened in the browser by
 * tests/e2e/guide.spec.ts.
 */
import { QUESTIONS, SCENES } from '../kit/catalogue';
import { LESSON_PRESETS, MISCONCEPTIONS as BY_SCENE, presetScene, type LessonPreset } from '../kit/lessons';

/** A lesson preset as the guide shows it: the catalogue's preset with the route of the scene it opens. */
export type Preset = Omit<LessonPreset, 'scene'> & {
  /** Scene route, e.g. '/hemisphere'. */
  route: string;
};

export interface Lesson {
  id: string;
  question: string;
  title: string;
  presets: Preset[];
}

export const LESSONS: readonly Lesson[] = QUESTIONS.map((q) => ({
  id: `q${q.n}`,
  question: `Q${q.n}`,
  title: q.title,
  presets: LESSON_PRESETS[q.n].map(({ scene: _scene, ...p }) => ({
    route: presetScene(q.n, { scene: _scene, ...p }).path,
    ...p,
  })),
}));

export interface Misconceptions {
  route: string;
  title: string;
  items: readonly string[];
}

export const MISCONCEPTIONS: readonly Misconceptions[] = SCENES.map((s) => ({
  route: s.path,
  ...BY_SCENE[s.id],
}));

/** encodeURIComponent, keeping `,` readable (the scenes' vectors and lists). */
function enc(s: string): string {
  return encodeURIComponent(s).replace(/%2C/g, ',');
}

/** The hash link of a preset: its parameters, its part, ask=1 if it asks first (optionally in classroom mode). */
export function presetHref(p: Preset, present = false): string {
  const q = Object.entries(p.params).map(([k, v]) => `${enc(k)}=${enc(v)}`);
  if (p.part) q.push(`part=${enc(p.part)}`);
  if (p.askFirst) q.push('ask=1');
  if (present) q.push('present=1');
  return `#${p.route}${q.length ? `?${q.join('&')}` : ''}`;
}
