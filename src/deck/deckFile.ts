/**
 * A deck as a file a lecturer downloads and opens again (`.json`): the deck's fields under a format
 * marker and a version, so that any other JSON file is refused with a message saying what it is
 * not. The same text is what the working deck keeps in the browser's storage (./workingDeck.ts).
 */
import { fail } from '../core/failure';
import { readDeck, type Checked, type Deck } from './deck';

/** The marker every deck file carries (`"format"`). */
export const DECK_FORMAT = 'render-math-lab-deck';
/** The version of the file layout this build writes and reads. */
export const DECK_FILE_VERSION = 1;
/** The largest deck file read (a full deck with every text at its limit is well below it). */
export const MAX_DECK_FILE = 400_000;

/** The deck as a deck file's text (indented JSON). */
export function deckFileText(deck: Deck): string {
  return `${JSON.stringify(
    {
      format: DECK_FORMAT,
      version: DECK_FILE_VERSION,
      title: deck.title,
      slides: deck.slides.map((s) => ({
        link: s.link,
        title: s.title,
        question: s.question,
        caption: s.caption,
        ...(s.highlight ? { highlight: s.highlight } : {}),
      })),
    },
    null,
    2,
  )}\n`;
}

/** A deck file's name: the deck's title in letters, digits and dashes. */
export function deckFileName(deck: Deck): string {
  const stem = deck.title
    .normalize('NFKD')
    .replace(/[^\w\s-]/g, '')
    .trim()
    .replace(/[\s_]+/g, '-')
    .toLowerCase()
    .slice(0, 60);
  return `${stem || 'deck'}.deck.json`;
}

/** Reads a deck file's text, with a message naming what is wrong when it is not a usable deck. */
export function readDeckFile(text: string): Checked<Deck> {
  if (text.length > MAX_DECK_FILE)
    return fail('deck', `the file has ${text.length} characters; a deck file has at most ${MAX_DECK_FILE}`);
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (e) {
    return fail('deck', `the file is not JSON (${e instanceof Error ? e.message : String(e)})`);
  }
  if (
    !data ||
    typeof data !== 'object' ||
    Array.isArray(data) ||
    (data as { format?: unknown }).format !== DECK_FORMAT
  )
    return fail('deck', `the file is not a Render Math Lab deck (it has no "format": "${DECK_FORMAT}")`);
  const version = (data as { version?: unknown }).version;
  if (version !== DECK_FILE_VERSION)
    return fail(
      'deck',
      `the file is a deck of version ${JSON.stringify(version)}; this build reads version ${DECK_FILE_VERSION}`,
    );
  return readDeck(data);
}
