/** The deck page's address (src/deck/deckAddress.ts), its keys (useDeckKeys.ts) and its clock (useDeckTimer.ts). */
import { describe, expect, it } from 'vitest';
import { deckQuery, openDeck, sharedDeckQuery } from '../../src/deck/deckAddress';
import { encodeDeck } from '../../src/deck/deckLink';
import { readyDeck } from '../../src/deck/readyDecks';
import { deckKeyAction } from '../../src/deck/useDeckKeys';
import { clockText } from '../../src/deck/useDeckTimer';
import type { Deck } from '../../src/deck/deck';

const deck: Deck = {
  title: 'Mine',
  slides: ['/texture?u=0.4&ask=1', '/ray-sphere', '/hemisphere'].map((link) => ({
    link,
    title: link,
    question: '',
    caption: '',
  })),
};
const working = { deck: { title: 'Working', slides: deck.slides.slice(0, 1) }, problem: null };
const noFlags = { present: false, embed: false, theme: null };

describe('openDeck', () => {
  it('plays the link’s deck on the address’s slide', () => {
    expect(openDeck(`d=${encodeDeck(deck)}&slide=3&present=1`, () => working)).toEqual({
      deck,
      source: { kind: 'link' },
      index: 2,
      problem: null,
    });
  });
  it('plays a ready deck, and the working deck when the address names none', () => {
    const r = openDeck('q=3&slide=2', () => working);
    expect(r.source).toEqual({ kind: 'ready', n: 3 });
    expect(r.deck).toEqual(readyDeck(3));
    expect(r.index).toBe(1);
    expect(openDeck('', () => working)).toEqual({ ...working, source: { kind: 'working' }, index: 0 });
  });
  it('falls back to the working deck with a message naming what it could not use', () => {
    const bad = openDeck('d=abc$&slide=9', () => working);
    expect(bad.source).toEqual({ kind: 'working' });
    expect(bad.deck).toBe(working.deck);
    expect(bad.index).toBe(0);
    expect(bad.problem).toMatch(/^The deck in this link could not be read: the deck code has characters/);
    expect(openDeck('q=9', () => working).problem).toMatch(
      /^q="9" is not an exam question with a ready deck/,
    );
    expect(openDeck('q=3x', () => ({ ...working, problem: 'storage said no' })).problem).toMatch(
      /; storage said no$/,
    );
  });
});

describe('deckQuery and sharedDeckQuery', () => {
  it('write what openDeck reads back', () => {
    for (const source of [{ kind: 'link' }, { kind: 'ready', n: 3 }, { kind: 'working' }] as const) {
      const d = source.kind === 'ready' ? readyDeck(3)! : deck;
      const q = deckQuery(d, source, 1, { present: true, embed: false, theme: 'dark' });
      expect(q).toMatch(/slide=2&present=1&theme=dark$/);
      const back = openDeck(q, () => ({ deck: d, problem: null }));
      expect([back.deck, back.source, back.index]).toEqual([d, source, 1]);
    }
    expect(deckQuery(deck, { kind: 'working' }, 0, noFlags)).toBe('slide=1');
  });
  it('the shared link carries the deck itself, and classroom mode when presenting', () => {
    expect(sharedDeckQuery(deck, 1, true)).toBe(`d=${encodeDeck(deck)}&slide=2&present=1`);
    expect(sharedDeckQuery(deck, 0, false)).toBe(`d=${encodeDeck(deck)}&slide=1`);
  });
});

describe('deckKeyAction', () => {
  const page = { figure: false, pressable: false };
  it('turns the slides, jumps to the ends and blacks out', () => {
    expect(['ArrowRight', 'PageDown', ' '].map((k) => deckKeyAction(k, page))).toEqual([
      'next',
      'next',
      'next',
    ]);
    expect(['ArrowLeft', 'PageUp'].map((k) => deckKeyAction(k, page))).toEqual(['previous', 'previous']);
    expect([deckKeyAction('Home', page), deckKeyAction('End', page)]).toEqual(['first', 'last']);
    expect([deckKeyAction('b', page), deckKeyAction('B', page)]).toEqual(['black', 'black']);
    expect(['v', 'r', 'c', 'ArrowUp', 'Enter'].map((k) => deckKeyAction(k, page))).toEqual([
      null,
      null,
      null,
      null,
      null,
    ]);
  });
  it('leaves a focused figure its keys, and Space to a focused button', () => {
    const figure = { figure: true, pressable: false };
    expect(['ArrowRight', 'ArrowLeft', 'PageDown', 'Home', ' '].map((k) => deckKeyAction(k, figure))).toEqual(
      [null, null, null, null, null],
    );
    expect(deckKeyAction('b', figure)).toBe('black');
    const button = { figure: false, pressable: true };
    expect([deckKeyAction(' ', button), deckKeyAction('ArrowRight', button)]).toEqual([null, 'next']);
  });
});

describe('clockText', () => {
  it('reads m:ss, then h:mm:ss', () => {
    expect([0, 9.9, 61, 3599, 3600, 3725].map(clockText)).toEqual([
      '0:00',
      '0:09',
      '1:01',
      '59:59',
      '1:00:00',
      '1:02:05',
    ]);
    expect(clockText(-5)).toBe('0:00');
  });
});
