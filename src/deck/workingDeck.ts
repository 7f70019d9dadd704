/**
 * The lecturer's working deck: the deck "Add this view to a deck" appends to and `#/deck` (with no
 * deck in its link) opens, kept in this browser's storage as a deck file's text, per learner like
 * the other stored state (../practice/learnerScope.ts). Storage can be missing, full or forbidden,
 * and what it holds can be hand-edited: every failure comes back as a message, never a throw.
 */
import { scopedKey } from '../practice/learnerScope';
import { addSlide, EMPTY_DECK, slideFor, type Deck } from './deck';
import { deckFileText, readDeckFile } from './deckFile';

export const WORKING_DECK_KEY = 'rml:deck';

/** The working deck, with a message when what storage holds could not be read (then empty). */
export function loadWorkingDeck(): { deck: Deck; problem: string | null } {
  let raw: string | null;
  try {
    raw = window.localStorage.getItem(scopedKey(WORKING_DECK_KEY));
  } catch {
    return { deck: EMPTY_DECK, problem: 'this browser does not let the page read its storage' };
  }
  if (raw === null) return { deck: EMPTY_DECK, problem: null };
  const read = readDeckFile(raw);
  if (read.ok) return { deck: read.value, problem: null };
  return {
    deck: EMPTY_DECK,
    problem: `the stored deck could not be read (${read.message}); starting afresh`,
  };
}

/** Keeps `deck` as the working deck; a message when storage refuses. */
export function saveWorkingDeck(deck: Deck): string | null {
  try {
    window.localStorage.setItem(scopedKey(WORKING_DECK_KEY), deckFileText(deck));
    return null;
  } catch {
    return 'the deck could not be stored (this browser’s storage is full or blocked)';
  }
}

/** Appends the scene link `link` to the working deck: its new slide number, or a message. */
export function addToWorkingDeck(link: string): { ok: true; n: number } | { ok: false; message: string } {
  const slide = slideFor(link);
  if (!slide.ok) return { ok: false, message: slide.message };
  const { deck, problem } = loadWorkingDeck();
  if (problem && problem.startsWith('this browser')) return { ok: false, message: problem };
  const next = addSlide(deck, slide.value);
  if (!next.ok) return { ok: false, message: next.message };
  const refused = saveWorkingDeck(next.value);
  if (refused) return { ok: false, message: refused };
  return { ok: true, n: next.value.slides.length };
}
