/**
 * The deck editor (outside classroom mode): the deck's title, its slides (texts, order, removal),
 * a field to add a slide from any scene link, the deck as a link and as a file, and the ready decks.
 * Every change goes through the model (./deck.ts), so the deck stays valid; a file that is not a
 * deck is refused with a message and the deck on the page stays as it was.
 */
import { useEffect, useRef, useState } from 'react';
import { downloadFile } from '../ui/download';
import { addSlide, DECK_LIMITS, moveSlide, removeSlide, retitle, slideFor, type Deck } from './deck';
import { deckFileName, deckFileText, readDeckFile } from './deckFile';
import { READY_QUESTIONS } from './readyDecks';
import { SlideEditor } from './SlideEditor';

export interface DeckEditorProps {
  deck: Deck;
  index: number;
  /** The deck is the working deck (edits are stored in this browser). */
  working: boolean;
  onDeck: (deck: Deck, index?: number) => void;
  /** A deck opened from a file replaces the one on the page. */
  onOpen: (deck: Deck) => void;
  onKeep: () => void;
  go: (index: number) => void;
  /** A message about storing the deck, if storing failed. */
  storeProblem: string | null;
}

export function DeckEditor({
  deck,
  index,
  working,
  onDeck,
  onOpen,
  onKeep,
  go,
  storeProblem,
}: DeckEditorProps) {
  const [link, setLink] = useState('');
  const [said, setSaid] = useState<{ text: string; bad: boolean } | null>(null);
  const list = useRef<HTMLOListElement>(null);
  // after a move, focus stays on the same button of the moved slide
  const [focus, setFocus] = useState<{ i: number; action: string } | null>(null);
  useEffect(() => {
    if (!focus) return;
    const item = list.current?.querySelector<HTMLElement>(`[data-index="${focus.i}"]`);
    // the same button, else (a slide moved to an end) its other move button, else its first
    const other = focus.action === 'up' ? 'down' : focus.action === 'down' ? 'up' : focus.action;
    const btn =
      item?.querySelector<HTMLButtonElement>(`[data-action="${focus.action}"]:not(:disabled)`) ??
      item?.querySelector<HTMLButtonElement>(`[data-action="${other}"]:not(:disabled)`) ??
      item?.querySelector<HTMLButtonElement>('button');
    btn?.focus();
    setFocus(null);
  }, [focus]);

  const move = (from: number, to: number) => {
    onDeck(moveSlide(deck, from, to), from === index ? to : to === index ? from : index);
    setFocus({ i: to, action: to < from ? 'up' : 'down' });
  };
  const remove = (i: number) => {
    onDeck(
      removeSlide(deck, i),
      Math.min(i < index ? index - 1 : index, Math.max(0, deck.slides.length - 2)),
    );
    setFocus({ i: Math.min(i, deck.slides.length - 2), action: 'remove' });
    setSaid({ text: `Slide ${i + 1} removed.`, bad: false });
  };
  const add = () => {
    const s = slideFor(link);
    const next = s.ok ? addSlide(deck, s.value) : s;
    if (!next.ok) {
      setSaid({ text: `Not added: ${next.message}.`, bad: true });
      return;
    }
    onDeck(next.value, next.value.slides.length - 1);
    setLink('');
    setSaid({ text: `Added: slide ${next.value.slides.length}.`, bad: false });
  };
  const openFile = async (file: File | undefined) => {
    if (!file) return;
    let text: string;
    try {
      text = await file.text();
    } catch {
      setSaid({ text: `${file.name} could not be read; the deck is unchanged.`, bad: true });
      return;
    }
    const r = readDeckFile(text);
    if (!r.ok) {
      setSaid({ text: `${file.name} was not opened: ${r.message}. The deck is unchanged.`, bad: true });
      return;
    }
    onOpen(r.value);
    setSaid({ text: `Opened ${file.name}: ${r.value.slides.length} slides.`, bad: false });
  };

  return (
    <section className="deck-editor" aria-labelledby="deck-editor-h" data-testid="deck-editor">
      <h2 id="deck-editor-h">Edit the deck</h2>
      <p className="deck-where">
        {working
          ? 'This is your working deck, kept in this browser: “Add this view to a deck” on any scene adds to it.'
          : 'This deck is in the link: your changes go into the address (copy it to keep them).'}{' '}
        {working ? null : (
          <button type="button" data-testid="deck-keep" onClick={onKeep}>
            Make this my working deck
          </button>
        )}
      </p>
      {storeProblem ? (
        <p role="alert" className="notice notice-error">
          {storeProblem}; the deck still lives in this page and its link.
        </p>
      ) : null}
      <label htmlFor="deck-title">Deck title</label>
      <input
        id="deck-title"
        value={deck.title}
        maxLength={DECK_LIMITS.title}
        onChange={(e) => {
          const r = retitle(deck, e.target.value);
          if (r.ok) onDeck(r.value);
        }}
      />
      <ol className="deck-slides" ref={list}>
        {deck.slides.map((s, i) => (
          <SlideEditor
            key={`${i}\u0000${s.link}`}
            deck={deck}
            i={i}
            current={i === index}
            onDeck={(d) => onDeck(d)}
            onMove={move}
            onRemove={remove}
            onShow={go}
          />
        ))}
      </ol>
      <form
        className="deck-add"
        onSubmit={(e) => {
          e.preventDefault();
          add();
        }}
      >
        <label htmlFor="deck-add-link">Add a slide from a scene link</label>
        <input
          id="deck-add-link"
          data-testid="deck-add-link"
          placeholder="#/texture?u=0.4&ask=1"
          value={link}
          onChange={(e) => setLink(e.target.value)}
        />
        <button type="submit" data-testid="deck-add">
          Add
        </button>
      </form>
      <div className="deck-files">
        <button
          type="button"
          data-testid="deck-download"
          onClick={() => downloadFile(deckFileName(deck), deckFileText(deck), 'application/json')}
        >
          Download deck
        </button>
        <label className="deck-open">
          Open a deck file{' '}
          <input
            type="file"
            accept=".json,application/json"
            data-testid="deck-open-file"
            onChange={(e) => {
              void openFile(e.target.files?.[0]);
              e.target.value = '';
            }}
          />
        </label>
      </div>
      <p role="status" className={said?.bad ? 'notice notice-error' : 'deck-said'} data-testid="deck-said">
        {said?.text ?? ''}
      </p>
      <p className="deck-ready">
        Ready decks, one per exam question:{' '}
        {READY_QUESTIONS.map((q, k) => (
          <span key={q}>
            {k ? ' · ' : null}
            <a href={`#/deck?q=${q}`}>Q{q}</a>
          </span>
        ))}
      </p>
    </section>
  );
}
