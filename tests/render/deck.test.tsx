/**
 * The deck's player and editor rendered outside the browser (react-dom/server): the slide count,
 * the texts, an asking slide's question left to the scene's prompt, the ends' buttons disabled,
 * every field labelled. The keys, focus and files are the browser spec's (tests/e2e/deck.spec.ts).
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import DeckPage from '../../src/deck/DeckPage';
import { DeckPlayer } from '../../src/deck/DeckPlayer';
import { DeckEditor } from '../../src/deck/DeckEditor';
import type { DeckHost, SlideSceneProps } from '../../src/deck/deckHost';
import type { Deck } from '../../src/deck/deck';
import { encodeDeck } from '../../src/deck/deckLink';
import { parseShellFlags } from '../../src/kit/shell';
import { installWindow } from '../practice/memoryWindow';

const deck: Deck = {
  title: 'Lecture 7',
  slides: [
    { link: '/texture?u=0.7&ask=1', title: 'Lookup', question: 'Which node?', caption: 'By hand first.' },
    { link: '/monte-carlo', title: 'Estimate', question: 'How far off?', caption: '', highlight: 'exact' },
  ],
};
const seen: SlideSceneProps[] = [];
const host: DeckHost = {
  SlideScene: (p) => {
    seen.push(p);
    return <div data-testid="slide-scene">{p.path}</div>;
  },
};
const noop = () => undefined;

describe('DeckPlayer', () => {
  it('shows slide k of n, the texts, and leaves an asking slide’s question to its prompt', () => {
    seen.length = 0;
    const html = renderToStaticMarkup(
      <DeckPlayer deck={deck} index={0} go={noop} host={host} theme="light" present />,
    );
    expect(html).toContain('Slide 1 of 2');
    expect(html).toContain('>Lookup</h1>');
    expect(html).toContain('By hand first.');
    expect(html).not.toContain('data-testid="deck-question"');
    expect(seen[0]).toMatchObject({
      path: '/texture',
      query: 'u=0.7&ask=1',
      question: 'Which node?',
      present: true,
    });
    expect(html).toMatch(/data-testid="deck-previous"[^>]*disabled/);
    expect(html).not.toMatch(/data-testid="deck-next"[^>]*disabled/);
  });
  it('shows the question of a slide that does not ask, and disables Next on the last', () => {
    const html = renderToStaticMarkup(
      <DeckPlayer deck={deck} index={1} go={noop} host={host} theme="dark" present={false} />,
    );
    expect(html).toContain('Slide 2 of 2');
    expect(html).toMatch(/data-testid="deck-question"[^>]*>How far off\?/);
    expect(html).toMatch(/data-testid="deck-next"[^>]*disabled/);
  });
  it('says what to do with an empty deck', () => {
    const html = renderToStaticMarkup(
      <DeckPlayer deck={{ title: 'x', slides: [] }} index={0} go={noop} host={host} theme="light" present />,
    );
    expect(html).toContain('Slide 0 of 0');
    expect(html).toContain('This deck has no slides yet');
  });
});

describe('DeckEditor', () => {
  it('labels every field and disables the moves off the ends', () => {
    const html = renderToStaticMarkup(
      <DeckEditor
        deck={deck}
        index={0}
        working
        onDeck={noop}
        onOpen={noop}
        onKeep={noop}
        go={noop}
        storeProblem={null}
      />,
    );
    for (const id of [
      'deck-slide-0-title',
      'deck-slide-1-question',
      'deck-slide-1-caption',
      'deck-slide-1-highlight',
    ])
      expect(html).toContain(`for="${id}"`);
    expect(html).toMatch(/aria-label="Move slide 1 up" disabled/);
    expect(html).toMatch(/aria-label="Move slide 2 down" disabled/);
    expect(html).not.toMatch(/aria-label="Move slide 1 down" disabled/);
    expect(html).toContain('This is your working deck');
    expect(html).not.toContain('Make this my working deck');
    expect(html).toContain('value="exact"');
  });
});

describe('DeckPage', () => {
  it('plays the link’s deck on its slide, and names a link it cannot read', () => {
    const remove = installWindow();
    try {
      const ok = renderToStaticMarkup(
        <DeckPage
          flags={parseShellFlags('')}
          query={`d=${encodeDeck(deck)}&slide=2`}
          theme="light"
          host={host}
        />,
      );
      expect(ok).toContain('Slide 2 of 2');
      expect(ok).toContain('Make this my working deck');
      const bad = renderToStaticMarkup(
        <DeckPage flags={parseShellFlags('present=1')} query="d=%%%&present=1" theme="light" host={host} />,
      );
      expect(bad).toContain('The deck in this link could not be read');
      expect(bad).toContain('Slide 0 of 0');
      expect(bad).not.toContain('data-testid="deck-editor"');
    } finally {
      remove();
    }
  });
});
