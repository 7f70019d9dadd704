/** The deck model (src/deck/deck.ts): slide links, the checks with their messages, and the edits. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  addSlide,
  DECK_LIMITS,
  editSlide,
  EMPTY_DECK,
  moveSlide,
  readDeck,
  readSlide,
  removeSlide,
  retitle,
  slideAsks,
  slideFor,
  slideLink,
  slideNumber,
  type Deck,
  type Slide,
} from '../../src/deck/deck';

const slide = (link: string, title = 't'): Slide => ({ link, title, question: '', caption: '' });
const deckOf = (...links: string[]): Deck => ({ title: 'D', slides: links.map((l) => slide(l)) });
const message = (r: { ok: boolean; message?: string }) => (r.ok ? null : r.message);

describe('slideLink', () => {
  it('takes a full address, a hash or a route, and keeps the scene state and ask', () => {
    expect(slideLink('https://x.org/app/?lms=1#/texture?u=0.4&ask=1')).toEqual({
      ok: true,
      value: '/texture?u=0.4&ask=1',
    });
    expect(slideLink('#/ray-sphere')).toEqual({ ok: true, value: '/ray-sphere' });
    expect(slideLink('  /render?spp=4 ')).toEqual({ ok: true, value: '/render?spp=4' });
  });
  it('drops the flags the deck decides', () => {
    expect(slideLink('#/texture?present=1&u=0.4&embed=1&theme=dark&a11y=1&part=3a&ask=1')).toEqual({
      ok: true,
      value: '/texture?u=0.4&part=3a&ask=1',
    });
  });
  it('refuses what is not a scene link, naming it', () => {
    expect(message(slideLink(''))).toBe('the link is empty');
    expect(message(slideLink('texture?u=1'))).toMatch(/"texture\?u=1" is not a link to a scene/);
    expect(message(slideLink('#/guide'))).toMatch(/"\/guide" is not a scene of Render Math Lab/);
    expect(message(slideLink(`/texture?u=${'1'.repeat(2000)}`))).toMatch(
      /characters long; a slide's link may have 1500/,
    );
  });
});

describe('slideFor', () => {
  it('titles the slide after its scene and asks the scene’s question when the link asks', () => {
    const s = slideFor('#/hemisphere?lobe=exam&part=1a&ask=1');
    expect(s.ok && s.value.title).toBe('Sampling a hemisphere');
    expect(s.ok && s.value.question).toMatch(/^Before you reveal k/);
    expect(s.ok && slideAsks(s.value)).toBe(true);
    const plain = slideFor('#/hemisphere');
    expect(plain.ok && plain.value.question).toBe('');
    expect(plain.ok && slideAsks(plain.value)).toBe(false);
  });
});

describe('readDeck and readSlide: every malformed field gives a message', () => {
  const cases: [unknown, RegExp][] = [
    [null, /the deck is not an object/],
    [[], /the deck is not an object/],
    [{ title: 3, slides: [] }, /the deck: the title is not text/],
    [{ title: 'x'.repeat(121), slides: [] }, /the deck: the title has 121 characters; at most 120/],
    [{ title: 'a' }, /the deck has no list of slides/],
    [{ slides: Array(61).fill(slide('/texture')) }, /the deck has 61 slides; at most 60/],
    [{ slides: [7] }, /slide 1 is not an object/],
    [{ slides: [{ title: 'x' }] }, /slide 1 has no link/],
    [{ slides: [slide('/texture'), { link: '/nowhere' }] }, /slide 2: "\/nowhere" is not a scene/],
    [{ slides: [{ link: '/texture', title: 5 }] }, /slide 1: the title is not text/],
    [
      { slides: [{ link: '/texture', question: 'q'.repeat(601) }] },
      /slide 1: the question has 601 characters/,
    ],
    [{ slides: [{ link: '/texture', caption: [] }] }, /slide 1: the caption is not text/],
    [{ slides: [{ link: '/texture', highlight: 'a b' }] }, /slide 1: the highlight "a b" is not the name/],
    [{ slides: [{ link: '/texture', highlight: 4 }] }, /slide 1: the highlight is not text and is not/],
  ];
  it.each(cases)('%j', (raw, re) => {
    expect(message(readDeck(raw))).toMatch(re);
  });
  it('reads a good deck, defaulting missing texts and an empty title', () => {
    const r = readDeck({ title: ' ', slides: [{ link: '#/texture?u=0.4', highlight: 'texel-value' }] });
    expect(r).toEqual({
      ok: true,
      value: {
        title: 'My deck',
        slides: [{ link: '/texture?u=0.4', title: '', question: '', caption: '', highlight: 'texel-value' }],
      },
    });
    expect(readSlide({ link: '/texture', highlight: '' }, 1)).toEqual({
      ok: true,
      value: slide('/texture', ''),
    });
  });
});

describe('the edits', () => {
  it('add refuses a full deck', () => {
    const full: Deck = { title: 'F', slides: Array(DECK_LIMITS.slides).fill(slide('/texture')) };
    expect(message(addSlide(full, slide('/texture')))).toMatch(/the deck is full \(60 slides\)/);
    const one = addSlide(EMPTY_DECK, slide('/texture'));
    expect(one.ok && one.value.slides.length).toBe(1);
  });
  it('move is a permutation that puts the slide where asked (clamped)', () => {
    const links = ['/texture', '/hemisphere', '/ray-sphere', '/monte-carlo', '/area-light'];
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: links.length }),
        fc.integer({ min: -2, max: 7 }),
        fc.integer({ min: -2, max: 7 }),
        (n, from, to) => {
          const d = deckOf(...links.slice(0, n));
          const m = moveSlide(d, from, to);
          expect([...m.slides].map((s) => s.link).sort()).toEqual([...d.slides].map((s) => s.link).sort());
          if (from >= 0 && from < n) expect(m.slides[Math.min(n - 1, Math.max(0, to))]).toBe(d.slides[from]);
          else expect(m).toBe(d);
        },
      ),
      { seed: 11 },
    );
  });
  it('remove drops one slide, out of range nothing', () => {
    const d = deckOf('/texture', '/hemisphere');
    expect(removeSlide(d, 0).slides.map((s) => s.link)).toEqual(['/hemisphere']);
    expect(removeSlide(d, 2)).toBe(d);
  });
  it('edit checks the new texts and names a missing slide', () => {
    const d = deckOf('/texture');
    const e = editSlide(d, 0, { caption: 'Look at the corners', highlight: 'texel-value' });
    expect(e.ok && e.value.slides[0]).toEqual({
      ...d.slides[0],
      caption: 'Look at the corners',
      highlight: 'texel-value',
    });
    expect(message(editSlide(d, 0, { title: 'x'.repeat(200) }))).toMatch(
      /slide 1: the title has 200 characters/,
    );
    expect(message(editSlide(d, 3, { title: 'x' }))).toBe('there is no slide 4 (the deck has 1)');
    expect(retitle(d, '  ')).toEqual({ ok: true, value: { ...d, title: 'My deck' } });
  });
  it('slideNumber clamps the address’s slide into the deck', () => {
    expect(slideNumber('3', 5)).toBe(3);
    expect(slideNumber('9', 5)).toBe(5);
    expect(slideNumber('0', 5)).toBe(1);
    expect(slideNumber('two', 5)).toBe(1);
    expect(slideNumber(null, 0)).toBe(1);
  });
});
