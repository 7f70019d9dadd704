/** One slide in the deck editor: its texts, its link, and the buttons that move, show or remove it. */
import { useState } from 'react';
import { DECK_LIMITS, editSlide, type Deck, type SlideTexts } from './deck';

export interface SlideEditorProps {
  deck: Deck;
  i: number;
  current: boolean;
  onDeck: (deck: Deck) => void;
  onMove: (from: number, to: number) => void;
  onRemove: (i: number) => void;
  onShow: (i: number) => void;
}

export function SlideEditor({ deck, i, current, onDeck, onMove, onRemove, onShow }: SlideEditorProps) {
  const s = deck.slides[i];
  const n = deck.slides.length;
  const [problem, setProblem] = useState<string | null>(null);
  const edit = (patch: SlideTexts) => {
    const r = editSlide(deck, i, patch);
    setProblem(r.ok ? null : r.message);
    if (r.ok) onDeck(r.value);
  };
  const id = `deck-slide-${i}`;
  return (
    <li
      className={`deck-slide-edit${current ? ' is-current' : ''}`}
      data-testid="deck-slide-edit"
      data-index={i}
    >
      <div className="deck-slide-head">
        <span className="deck-slide-n">Slide {i + 1}</span>
        <a className="deck-slide-link" href={`#${s.link}`} title="Open this slide’s scene">
          {s.link}
        </a>
      </div>
      <label htmlFor={`${id}-title`}>Title</label>
      <input
        id={`${id}-title`}
        value={s.title}
        maxLength={DECK_LIMITS.title}
        onChange={(e) => edit({ title: e.target.value })}
      />
      <label htmlFor={`${id}-question`}>Question for the class</label>
      <textarea
        id={`${id}-question`}
        rows={2}
        value={s.question}
        maxLength={DECK_LIMITS.question}
        onChange={(e) => edit({ question: e.target.value })}
      />
      <label htmlFor={`${id}-caption`}>Caption</label>
      <textarea
        id={`${id}-caption`}
        rows={2}
        value={s.caption}
        maxLength={DECK_LIMITS.caption}
        onChange={(e) => edit({ caption: e.target.value })}
      />
      <label htmlFor={`${id}-highlight`}>Highlight (a figure’s or readout’s test id, optional)</label>
      <input
        id={`${id}-highlight`}
        value={s.highlight ?? ''}
        maxLength={64}
        spellCheck={false}
        onChange={(e) => edit({ highlight: e.target.value })}
      />
      {problem ? (
        <p role="alert" className="notice notice-error">
          Not changed: {problem}.
        </p>
      ) : null}
      <div className="deck-slide-buttons">
        <button type="button" aria-current={current ? 'step' : undefined} onClick={() => onShow(i)}>
          Show
        </button>
        <button
          type="button"
          data-action="up"
          aria-label={`Move slide ${i + 1} up`}
          disabled={i === 0}
          onClick={() => onMove(i, i - 1)}
        >
          ↑ Up
        </button>
        <button
          type="button"
          data-action="down"
          aria-label={`Move slide ${i + 1} down`}
          disabled={i === n - 1}
          onClick={() => onMove(i, i + 1)}
        >
          ↓ Down
        </button>
        <button
          type="button"
          data-action="remove"
          aria-label={`Remove slide ${i + 1}`}
          onClick={() => onRemove(i)}
        >
          Remove
        </button>
      </div>
    </li>
  );
}
