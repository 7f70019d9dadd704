/**
 * The ready decks: each exam question of the teacher's guide as a deck of its lesson presets, in
 * the guide's order (a preset's title, its question for the class, what the class sees as the
 * caption; presets that ask first keep `ask=1`). `#/deck?q=3` plays question 3's.
 */
import { questionInfo } from '../kit/catalogue';
import { LESSONS, presetHref } from '../guide/lessons';
import { slideLink, type Deck, type Slide } from './deck';

/** The question numbers that have a ready deck. */
export const READY_QUESTIONS = [1, 2, 3, 4, 5, 6] as const;

/** Question `n`'s ready deck, or null when there is no such question. */
export function readyDeck(n: number): Deck | null {
  const q = questionInfo(n);
  const lesson = LESSONS.find((l) => l.id === `q${n}`);
  if (!q || !lesson) return null;
  const slides: Slide[] = [];
  for (const p of lesson.presets) {
    const link = slideLink(presetHref(p));
    // every preset is a scene link (the guide's tests check them), so none is skipped in practice
    if (link.ok) slides.push({ link: link.value, title: p.title, question: p.ask, caption: p.shows });
  }
  return { title: `Q${n} · ${q.title}`, slides };
}
