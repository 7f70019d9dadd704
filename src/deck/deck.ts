/**
 * A lecture deck: a titled sequence of slides, each a scene state (a scene link, `ask=1` included)
 * with a title, the question put to the class, a caption and, optionally, one element of the page to
 * outline (a figure or readout, named by its `data-testid`). This file is the pure model: the
 * checks every slide and deck passes, with a message naming each malformed field, and the edits
 * (add, move, remove, change the texts). Decks always come out of it checked; its encodings (the
 * link, the file) are ./deckLink.ts and ./deckFile.ts.
 */
import { fail, type Failure } from '../core/failure';
import { findScene, predictPrompt } from '../kit/catalogue';
import { dropQueryParam, parseHash } from '../kit/shell';

export interface Slide {
  /** The scene state: a hash route and its query, e.g. `/texture?u=0.4&ask=1` (no `#`). */
  readonly link: string;
  readonly title: string;
  /** What to ask the class; while the slide's link asks (`ask=1`) it stands until revealed. */
  readonly question: string;
  readonly caption: string;
  /** The `data-testid` of the figure or readout to outline, if any. */
  readonly highlight?: string;
}

export interface Deck {
  readonly title: string;
  readonly slides: readonly Slide[];
}

/** The longest texts and the most slides a deck may hold (links stay short enough for a QR code). */
export const DECK_LIMITS = {
  slides: 60,
  title: 120,
  question: 600,
  caption: 600,
  link: 1500,
} as const;

/** The title of a deck nobody named. */
export const UNTITLED = 'My deck';

export const EMPTY_DECK: Deck = { title: UNTITLED, slides: [] };

/**
 * Shell flags a slide link does not keep: the deck decides them for every slide (classroom mode,
 * embedding, the theme, the host-page origins, the A11y view).
 */
const DECK_FLAGS = ['present', 'embed', 'theme', 'origin', 'a11y'] as const;

/** A `data-testid`: letters, digits, `_ - . :`, at most 64 characters. */
const TEST_ID = /^[A-Za-z0-9][\w.:-]{0,63}$/;

export type DeckFailure = Failure<'deck'>;
export type Checked<T> = { ok: true; value: T } | DeckFailure;

function bad(message: string): DeckFailure {
  return fail('deck', message);
}

/** `s` quoted for a message, cut to `n` characters. */
export function quoted(s: string, n = 40): string {
  return JSON.stringify(s.length > n ? `${s.slice(0, n)}…` : s);
}

/**
 * A scene link as a slide keeps it: `/route?query`, from a full address (`https://…/#/texture?u=1`),
 * a hash (`#/texture?u=1`) or a route (`/texture?u=1`). The route must be a scene or a lab; the
 * flags the deck decides (`present`, `embed`, `theme`, `origin`, `a11y`) are dropped.
 */
export function slideLink(input: string): Checked<string> {
  const raw = input.trim();
  if (!raw) return bad('the link is empty');
  const hash = raw.indexOf('#');
  const route = hash >= 0 ? raw.slice(hash + 1) : raw;
  if (!route.startsWith('/'))
    return bad(`${quoted(raw)} is not a link to a scene (like #/texture?u=0.4 or a copied address)`);
  const { path, query } = parseHash(route);
  const scene = findScene(path);
  if (!scene)
    return bad(`${quoted(path)} is not a scene of Render Math Lab (a slide shows a scene or the render lab)`);
  let q = query;
  for (const flag of DECK_FLAGS) q = dropQueryParam(q, flag);
  const link = `${scene.path}${q ? `?${q}` : ''}`;
  if (link.length > DECK_LIMITS.link)
    return bad(`the link is ${link.length} characters long; a slide's link may have ${DECK_LIMITS.link}`);
  return { ok: true, value: link };
}

/** The route and query of a slide's (checked) link. */
export function slideRoute(slide: Slide): { path: string; query: string } {
  return parseHash(slide.link);
}

/** Whether the slide's link holds its results back (`ask=1`). */
export function slideAsks(slide: Slide): boolean {
  return new URLSearchParams(slideRoute(slide).query).get('ask') === '1';
}

/**
 * A new slide for a scene link: titled after its scene, asking the scene's prediction question for
 * its part when the link asks (`ask=1`), no caption.
 */
export function slideFor(input: string): Checked<Slide> {
  const link = slideLink(input);
  if (!link.ok) return link;
  const { path, query } = parseHash(link.value);
  const scene = findScene(path)!;
  const sp = new URLSearchParams(query);
  const question = sp.get('ask') === '1' ? (predictPrompt(scene, sp.get('part')) ?? '') : '';
  return { ok: true, value: { link: link.value, title: scene.title, question, caption: '' } };
}

function text(v: unknown, field: string, max: number, where: string): Checked<string> {
  if (v === undefined || v === null) return { ok: true, value: '' };
  if (typeof v !== 'string') return bad(`${where}: ${field} is not text`);
  if (v.length > max) return bad(`${where}: ${field} has ${v.length} characters; at most ${max}`);
  return { ok: true, value: v };
}

/** Checks one slide as read from a file or a link (`n`: its 1-based number, for the messages). */
export function readSlide(raw: unknown, n: number): Checked<Slide> {
  const where = `slide ${n}`;
  if (!raw || typeof raw !== 'object' || Array.isArray(raw)) return bad(`${where} is not an object`);
  const o = raw as Record<string, unknown>;
  if (typeof o.link !== 'string') return bad(`${where} has no link`);
  const link = slideLink(o.link);
  if (!link.ok) return bad(`${where}: ${link.message}`);
  const title = text(o.title, 'the title', DECK_LIMITS.title, where);
  if (!title.ok) return title;
  const question = text(o.question, 'the question', DECK_LIMITS.question, where);
  if (!question.ok) return question;
  const caption = text(o.caption, 'the caption', DECK_LIMITS.caption, where);
  if (!caption.ok) return caption;
  const slide: Slide = {
    link: link.value,
    title: title.value,
    question: question.value,
    caption: caption.value,
  };
  if (o.highlight === undefined || o.highlight === null || o.highlight === '')
    return { ok: true, value: slide };
  if (typeof o.highlight !== 'string' || !TEST_ID.test(o.highlight))
    return bad(
      `${where}: the highlight ${typeof o.highlight === 'string' ? quoted(o.highlight) : 'is not text and'} is not the name of a figure or readout (a data-testid such as "k")`,
    );
  return { ok: true, value: { ...slide, highlight: o.highlight } };
}

/** Checks a whole deck as read from a file, a link or storage. */
export function readDeck(raw: unknown): Checked<Deck> {
  if (!raw || typeof raw !== 'object' || Array.isArray(raw)) return bad('the deck is not an object');
  const o = raw as Record<string, unknown>;
  const title = text(o.title, 'the title', DECK_LIMITS.title, 'the deck');
  if (!title.ok) return title;
  if (!Array.isArray(o.slides)) return bad('the deck has no list of slides');
  if (o.slides.length > DECK_LIMITS.slides)
    return bad(`the deck has ${o.slides.length} slides; at most ${DECK_LIMITS.slides}`);
  const slides: Slide[] = [];
  for (let i = 0; i < o.slides.length; i++) {
    const s = readSlide(o.slides[i], i + 1);
    if (!s.ok) return s;
    slides.push(s.value);
  }
  return { ok: true, value: { title: title.value.trim() || UNTITLED, slides } };
}

/** The deck with `slide` appended (refused when the deck is full). */
export function addSlide(deck: Deck, slide: Slide): Checked<Deck> {
  if (deck.slides.length >= DECK_LIMITS.slides)
    return bad(`the deck is full (${DECK_LIMITS.slides} slides); remove one first`);
  return { ok: true, value: { ...deck, slides: [...deck.slides, slide] } };
}

/** The deck with slide `from` moved to position `to` (0-based; `to` is clamped into the deck). */
export function moveSlide(deck: Deck, from: number, to: number): Deck {
  const n = deck.slides.length;
  if (!Number.isInteger(from) || from < 0 || from >= n || !Number.isInteger(to)) return deck;
  const target = Math.min(n - 1, Math.max(0, to));
  if (target === from) return deck;
  const slides = [...deck.slides];
  const [s] = slides.splice(from, 1);
  slides.splice(target, 0, s);
  return { ...deck, slides };
}

/** The deck without slide `i` (0-based; out of range: unchanged). */
export function removeSlide(deck: Deck, i: number): Deck {
  if (!Number.isInteger(i) || i < 0 || i >= deck.slides.length) return deck;
  return { ...deck, slides: deck.slides.filter((_, j) => j !== i) };
}

/** The texts of a slide a lecturer edits. */
export type SlideTexts = Partial<Pick<Slide, 'title' | 'question' | 'caption' | 'highlight'>>;

/** The deck with slide `i`'s texts changed, each checked as a file's would be. */
export function editSlide(deck: Deck, i: number, patch: SlideTexts): Checked<Deck> {
  if (!Number.isInteger(i) || i < 0 || i >= deck.slides.length)
    return bad(`there is no slide ${i + 1} (the deck has ${deck.slides.length})`);
  const next = readSlide({ ...deck.slides[i], ...patch }, i + 1);
  if (!next.ok) return next;
  const slides = [...deck.slides];
  slides[i] = next.value;
  return { ok: true, value: { ...deck, slides } };
}

/** The deck retitled (an empty title: the default one). */
export function retitle(deck: Deck, title: string): Checked<Deck> {
  const t = text(title, 'the title', DECK_LIMITS.title, 'the deck');
  if (!t.ok) return t;
  return { ok: true, value: { ...deck, title: t.value.trim() || UNTITLED } };
}

/** A 1-based slide number from the address (`slide=3`), clamped into the deck; 1 when absent or unusable. */
export function slideNumber(raw: string | null, count: number): number {
  const n = raw !== null && /^\d{1,4}$/.test(raw) ? Number(raw) : 1;
  return Math.min(Math.max(1, n), Math.max(1, count));
}
