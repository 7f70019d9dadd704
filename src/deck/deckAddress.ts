/**
 * The deck page's address: which deck it plays and which slide it is on. `#/deck` plays the
 * lecturer's working deck (kept in this browser), `#/deck?q=3` the guide's ready deck of question 3,
 * `#/deck?d=<code>` the deck the link carries (./deckLink.ts); `slide=3` is the slide on screen, so a
 * reload stays on it. The shell's flags (`present`, `embed`, `theme`) are kept as they came.
 */
import { slideNumber, type Deck } from './deck';
import { decodeDeck, encodeDeck } from './deckLink';
import { readyDeck } from './readyDecks';

/** The deck page's own parameters (beside the shell's). */
export const DECK_PARAMS = ['d', 'q', 'slide'] as const;

/** Where the deck on the page comes from; edits to a working deck are stored, others go into the link. */
export type DeckSource = { kind: 'working' } | { kind: 'ready'; n: number } | { kind: 'link' };

export interface OpenedDeck {
  deck: Deck;
  source: DeckSource;
  /** 0-based index of the slide to show. */
  index: number;
  /** What the address held that could not be used, and what is shown instead. */
  problem: string | null;
}

/** The deck and slide the address names; `working` reads the working deck when that is the one. */
export function openDeck(query: string, working: () => { deck: Deck; problem: string | null }): OpenedDeck {
  const sp = new URLSearchParams(query);
  const d = sp.get('d');
  const q = sp.get('q');
  const fallback = (problem: string): OpenedDeck => {
    const w = working();
    return {
      deck: w.deck,
      source: { kind: 'working' },
      index: slideNumber(sp.get('slide'), w.deck.slides.length) - 1,
      problem: w.problem ? `${problem}; ${w.problem}` : problem,
    };
  };
  let opened: Omit<OpenedDeck, 'index'>;
  if (d !== null) {
    const r = decodeDeck(d);
    if (!r.ok)
      return fallback(`The deck in this link could not be read: ${r.message}. Showing your working deck`);
    opened = { deck: r.value, source: { kind: 'link' }, problem: null };
  } else if (q !== null) {
    const n = /^[1-9]$/.test(q) ? Number(q) : NaN;
    const ready = Number.isInteger(n) ? readyDeck(n) : null;
    if (!ready)
      return fallback(
        `q=${JSON.stringify(q.slice(0, 12))} is not an exam question with a ready deck (1 to 6). Showing your working deck`,
      );
    opened = { deck: ready, source: { kind: 'ready', n }, problem: null };
  } else {
    const w = working();
    opened = { deck: w.deck, source: { kind: 'working' }, problem: w.problem };
  }
  return { ...opened, index: slideNumber(sp.get('slide'), opened.deck.slides.length) - 1 };
}

/** The shell flags a deck address keeps. */
export interface DeckFlags {
  present: boolean;
  embed: boolean;
  theme: 'light' | 'dark' | null;
}

/** The query of the deck page's address for `deck` from `source`, on slide `index` (0-based). */
export function deckQuery(deck: Deck, source: DeckSource, index: number, flags: DeckFlags): string {
  const entries: [string, string][] = [];
  if (source.kind === 'link') entries.push(['d', encodeDeck(deck)]);
  else if (source.kind === 'ready') entries.push(['q', String(source.n)]);
  entries.push(['slide', String(index + 1)]);
  if (flags.present) entries.push(['present', '1']);
  if (flags.embed) entries.push(['embed', '1']);
  if (flags.theme) entries.push(['theme', flags.theme]);
  return entries.map(([k, v]) => `${k}=${v}`).join('&');
}

/**
 * The query of the deck's shareable link: the deck itself in the link (`d=`, whatever it came
 * from), the slide on screen, and classroom mode when the page is in it (the slides keep their own
 * `ask=1` inside the deck).
 */
export function sharedDeckQuery(deck: Deck, index: number, present: boolean): string {
  return deckQuery(deck, { kind: 'link' }, index, { present, embed: false, theme: null });
}
