/** The deck's link code and file (src/deck/deckLink.ts, deckFile.ts): round trips and every refusal. */
import fc from 'fast-check';
import { deflateSync, strToU8 } from 'fflate';
import { describe, expect, it } from 'vitest';
import { DECK_LIMITS, type Deck, type Slide } from '../../src/deck/deck';
import { decodeDeck, encodeDeck } from '../../src/deck/deckLink';
import { deckFileName, deckFileText, readDeckFile } from '../../src/deck/deckFile';

const ROUTES = ['/texture', '/hemisphere', '/monte-carlo', '/ray-sphere', '/area-light', '/render'];
const arbSlide: fc.Arbitrary<Slide> = fc
  .record({
    route: fc.constantFrom(...ROUTES),
    u: fc.double({ min: 0, max: 1, noNaN: true }),
    ask: fc.boolean(),
    title: fc.string({ maxLength: DECK_LIMITS.title }),
    question: fc.string({ maxLength: 80, unit: 'binary' }),
    caption: fc.string({ maxLength: 80 }),
    highlight: fc.option(fc.constantFrom('k', 'texel-value', 'estimate.mean'), { nil: undefined }),
  })
  .map(({ route, u, ask, highlight, ...texts }) => ({
    link: `${route}?u=${u}${ask ? '&ask=1' : ''}`,
    ...texts,
    ...(highlight ? { highlight } : {}),
  }));
const arbDeck: fc.Arbitrary<Deck> = fc.record({
  title: fc.string({ minLength: 1, maxLength: 40 }).filter((t) => t.trim() === t && t !== ''),
  slides: fc.array(arbSlide, { maxLength: 12 }),
});

const b64url = (bytes: Uint8Array) =>
  btoa(String.fromCharCode(...bytes))
    .replace(/\+/g, '-')
    .replace(/\//g, '_')
    .replace(/=+$/, '');
const codeOf = (data: unknown) => b64url(deflateSync(strToU8(JSON.stringify(data))));
const message = (r: { ok: boolean; message?: string }) => (r.ok ? null : r.message);

describe('the deck link', () => {
  it('round-trips every deck through a URL-safe code', () => {
    fc.assert(
      fc.property(arbDeck, (deck) => {
        const code = encodeDeck(deck);
        expect(code).toMatch(/^[A-Za-z0-9_-]*$/);
        expect(decodeDeck(code)).toEqual({ ok: true, value: deck });
      }),
      { seed: 7, numRuns: 200 },
    );
  });
  it('keeps a dozen slides short enough for a link', () => {
    const deck: Deck = {
      title: 'Q3',
      slides: Array.from({ length: 12 }, (_, i) => ({
        link: `/texture?u=0.${i}&v=0.24&ask=1`,
        title: `Lookup ${i}`,
        question: 'Which texel is sampled, and with which weights?',
        caption: 'Bilinear filtering with clamped coordinates.',
      })),
    };
    expect(encodeDeck(deck).length).toBeLessThan(900);
  });
  it('refuses what is not a deck code, naming why', () => {
    expect(message(decodeDeck(''))).toBe('the deck code is empty');
    expect(message(decodeDeck('a'.repeat(12_001)))).toMatch(/12001 characters; at most 12000/);
    expect(message(decodeDeck('abc$def'))).toMatch(/characters a deck link never has/);
    expect(message(decodeDeck('AAAAA'))).toMatch(/characters a deck link never has/);
    expect(message(decodeDeck('AAAA'))).toMatch(/does not unpack|does not hold a deck/);
    expect(message(decodeDeck(b64url(deflateSync(strToU8('not json')))))).toMatch(/does not hold a deck/);
    expect(message(decodeDeck(codeOf({ v: 1 })))).toMatch(/not a deck of version 1/);
    expect(message(decodeDeck(codeOf([2, 'x', []])))).toMatch(/not a deck of version 1/);
    expect(message(decodeDeck(codeOf([1, 'x', [['/nowhere', '', '', '']]])))).toMatch(
      /slide 1: "\/nowhere" is not a scene/,
    );
    expect(message(decodeDeck(codeOf([1, 'x', [5]])))).toMatch(/slide 1 is not an object/);
    // a short code that would unpack into megabytes is stopped at the bound
    expect(message(decodeDeck(b64url(deflateSync(new Uint8Array(300_000)))))).toMatch(
      /more than a deck can hold/,
    );
  });
  it('a cut link is refused, never half read', () => {
    const code = encodeDeck({
      title: 'T',
      slides: [{ link: '/texture?u=0.4', title: 'a', question: 'b', caption: 'c' }],
    });
    expect(decodeDeck(code.slice(0, Math.floor(code.length / 2))).ok).toBe(false);
  });
});

describe('the deck file', () => {
  it('round-trips every deck', () => {
    fc.assert(
      fc.property(arbDeck, (deck) => {
        expect(readDeckFile(deckFileText(deck))).toEqual({ ok: true, value: deck });
      }),
      { seed: 9, numRuns: 100 },
    );
  });
  it('names the file after the deck', () => {
    expect(deckFileName({ title: 'Q3 · Texture lookup!', slides: [] })).toBe('q3-texture-lookup.deck.json');
    expect(deckFileName({ title: '···', slides: [] })).toBe('deck.deck.json');
  });
  it('refuses a file that is not a deck, naming why', () => {
    expect(message(readDeckFile('{'))).toMatch(/^the file is not JSON \(/);
    expect(message(readDeckFile('[1]'))).toMatch(/not a Render Math Lab deck/);
    expect(message(readDeckFile('{"title":"x","slides":[]}'))).toMatch(
      /it has no "format": "render-math-lab-deck"/,
    );
    expect(message(readDeckFile('{"format":"render-math-lab-deck","version":2,"slides":[]}'))).toMatch(
      /a deck of version 2; this build reads version 1/,
    );
    expect(
      message(
        readDeckFile(
          '{"format":"render-math-lab-deck","version":1,"slides":[{"link":"/texture","title":1}]}',
        ),
      ),
    ).toMatch(/slide 1: the title is not text/);
    expect(message(readDeckFile(' '.repeat(400_001)))).toMatch(
      /400001 characters; a deck file has at most 400000/,
    );
  });
});
