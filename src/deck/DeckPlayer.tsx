/**
 * The deck playing: a bar (the deck's title, "Slide k of n", previous / next, the timer, the black
 * screen), the slide's title, question and caption, and the slide's scene under them: presenting,
 * in classroom mode, its figure filling what is left of the screen; while the deck is edited (the
 * editor comes between the bar and the slide), as the scene's own page lays it out. An asking slide's question is
 * the scene's own prompt until revealed, then stands with the title.
 */
import { useCallback, useRef, useState, type ReactNode } from 'react';
import { findScene } from '../kit/catalogue';
import { slideAsks, slideRoute, type Deck } from './deck';
import type { DeckHost } from './deckHost';
import { useDeckKeys } from './useDeckKeys';
import { useKeyHelp, type KeyHelp } from '../ui/shortcuts';
import { useHighlight } from './useHighlight';
import { clockText, useDeckTimer } from './useDeckTimer';

export interface DeckPlayerProps {
  deck: Deck;
  index: number;
  go: (index: number) => void;
  host: DeckHost;
  theme: 'light' | 'dark';
  /** The page is in classroom mode: the deck's keys and the whole screen are the lecture's. */
  present: boolean;
  /** Buttons for the bar's end (copy the deck's link, leave or enter classroom mode). */
  actions?: ReactNode;
  /** Under the bar, above the slide (the editor). */
  children?: ReactNode;
}

/** The deck's keys in the `?` list. */
const DECK_KEYS: readonly KeyHelp[] = [
  { keys: '→ PageDown Space', label: 'next slide' },
  { keys: '← PageUp', label: 'previous slide' },
  { keys: 'Home End', label: 'first / last slide' },
  { keys: 'b', label: 'black screen (any key returns)' },
];

export function DeckPlayer({ deck, index, go, host, theme, present, actions, children }: DeckPlayerProps) {
  const n = deck.slides.length;
  const slide = n ? deck.slides[index] : null;
  const [black, setBlack] = useState(false);
  // the slides revealed so far, by position and link (an edit of the link asks again)
  const [revealed, setRevealed] = useState<ReadonlySet<string>>(new Set());
  const key = slide ? `${index}\u0000${slide.link}` : '';
  const onReveal = useCallback(() => setRevealed((r) => new Set(r).add(key)), [key]);
  const timer = useDeckTimer();
  const stage = useRef<HTMLDivElement>(null);
  useHighlight(stage, slide?.highlight);
  useKeyHelp(DECK_KEYS);
  useDeckKeys(
    {
      next: () => go(Math.min(n - 1, index + 1)),
      previous: () => go(Math.max(0, index - 1)),
      first: () => go(0),
      last: () => go(n - 1),
      black: () => setBlack(true),
      blackedOut: black,
      unblack: () => setBlack(false),
    },
    true,
  );

  const asking = !!slide && slideAsks(slide) && !revealed.has(key);
  const route = slide ? slideRoute(slide) : null;
  const scene = route ? findScene(route.path) : undefined;
  const { SlideScene } = host;
  return (
    <section className={`deck-player${present ? ' is-presenting' : ''}`} aria-label="The deck playing">
      <div className="deck-bar">
        <span className="deck-title">{deck.title}</span>
        <span className="deck-count" data-testid="deck-slide-number" aria-live="polite">
          Slide {n ? index + 1 : 0} of {n}
        </span>
        <button
          type="button"
          data-testid="deck-previous"
          aria-keyshortcuts="ArrowLeft PageUp"
          disabled={index <= 0}
          onClick={() => go(index - 1)}
        >
          ← Previous
        </button>
        <button
          type="button"
          data-testid="deck-next"
          aria-keyshortcuts="ArrowRight PageDown Space"
          disabled={index >= n - 1}
          onClick={() => go(index + 1)}
        >
          Next →
        </button>
        <span className="deck-timer">
          <span role="timer" aria-label="Time since the deck started" data-testid="deck-timer">
            {clockText(timer.seconds)}
          </span>{' '}
          <button
            type="button"
            data-testid="deck-timer-toggle"
            aria-pressed={!timer.running}
            onClick={timer.toggle}
          >
            {timer.running ? 'Pause' : 'Resume'}
          </button>
          {present ? null : (
            <button type="button" onClick={timer.restart}>
              Restart
            </button>
          )}
        </span>
        <button type="button" data-testid="deck-black" aria-keyshortcuts="b" onClick={() => setBlack(true)}>
          Black <kbd aria-hidden="true">b</kbd>
        </button>
        {actions}
      </div>
      {children}
      {slide ? (
        <>
          <div className="deck-text">
            <h1 className="deck-slide-title" data-testid="deck-slide-title">
              {slide.title || scene?.title}
            </h1>
            {slide.question && !asking ? (
              <p className="deck-question" data-testid="deck-question">
                {slide.question}
              </p>
            ) : null}
            {slide.caption ? (
              <p className="deck-caption" data-testid="deck-caption">
                {slide.caption}
              </p>
            ) : null}
          </div>
          <div className="deck-stage" ref={stage} data-testid="deck-stage">
            {route && scene ? (
              <SlideScene
                key={key}
                path={route.path}
                query={route.query}
                question={slide.question || null}
                theme={theme}
                present={present}
                onReveal={onReveal}
              />
            ) : null}
          </div>
        </>
      ) : (
        <p className="deck-empty" role="status" data-testid="deck-empty">
          This deck has no slides yet. Open any scene and press “Add this view to a deck” in its share bar, or
          paste a scene’s link below.
        </p>
      )}
      {black ? (
        <div
          className="deck-blackout"
          data-testid="deck-blackout"
          role="button"
          tabIndex={-1}
          aria-label="The screen is black: press any key or click to bring the slide back"
          onClick={() => setBlack(false)}
        />
      ) : null}
    </section>
  );
}
