/**
 * `#/deck`: a lecture deck playing, and (outside classroom mode and embeds) its editor. Which deck
 * and which slide is the address's (./deckAddress.ts); every change of slide or deck rewrites the
 * address in place, so a reload stays where it was and the address is always the deck's link.
 */
import { useCallback, useEffect, useMemo, useState } from 'react';
import type { ShellFlags } from '../kit/shell';
import { shareUrl } from '../kit/shareLink';
import { ParamNotice, RouteNotice } from '../ui/RouteNotice';
import type { Deck } from './deck';
import { DeckEditor } from './DeckEditor';
import { DeckPlayer } from './DeckPlayer';
import { DECK_PARAMS, deckQuery, openDeck, sharedDeckQuery, type DeckSource } from './deckAddress';
import type { DeckHost } from './deckHost';
import { loadWorkingDeck, saveWorkingDeck, WORKING_DECK_KEY } from './workingDeck';
import './deck.css';

export interface DeckPageProps {
  flags: ShellFlags;
  query: string;
  theme: 'light' | 'dark';
  host: DeckHost;
}

interface State {
  deck: Deck;
  source: DeckSource;
  index: number;
}

const clampIndex = (i: number, deck: Deck) => Math.min(Math.max(0, i), Math.max(0, deck.slides.length - 1));

export default function DeckPage({ flags, query, theme, host }: DeckPageProps) {
  const [opened] = useState(() => openDeck(query, loadWorkingDeck));
  const [state, setState] = useState<State>({
    deck: opened.deck,
    source: opened.source,
    index: opened.index,
  });
  const [problem, setProblem] = useState(opened.problem);
  const [storeProblem, setStoreProblem] = useState<string | null>(null);
  const { deck, source, index } = state;
  const { present, embed, theme: themeFlag } = flags;

  const address = useMemo(
    () => deckQuery(deck, source, index, { present, embed, theme: themeFlag }),
    [deck, source, index, present, embed, themeFlag],
  );
  useEffect(() => {
    try {
      window.history.replaceState(window.history.state, '', `#/deck?${address}`);
    } catch {
      /* some sandboxed iframes forbid it; the deck still lives in the page */
    }
  }, [address]);
  useEffect(() => {
    document.title = `${deck.title} — Render Math Lab`;
  }, [deck.title]);
  // the working deck grows from other tabs ("Add this view to a deck" on a scene page)
  useEffect(() => {
    if (source.kind !== 'working') return;
    const on = (e: StorageEvent) => {
      if (e.key !== null && !e.key.startsWith(WORKING_DECK_KEY)) return;
      const w = loadWorkingDeck();
      setState((s) => ({ ...s, deck: w.deck, index: clampIndex(s.index, w.deck) }));
    };
    window.addEventListener('storage', on);
    return () => window.removeEventListener('storage', on);
  }, [source.kind]);

  const go = useCallback((i: number) => setState((s) => ({ ...s, index: clampIndex(i, s.deck) })), []);
  const onDeck = (next: Deck, i = index) => {
    // an edited ready deck is no longer the guide's: it goes into the link
    const src: DeckSource = source.kind === 'ready' ? { kind: 'link' } : source;
    if (src.kind === 'working') setStoreProblem(saveWorkingDeck(next));
    setState({ deck: next, source: src, index: clampIndex(i, next) });
  };
  const onKeep = () => {
    const refused = saveWorkingDeck(deck);
    setStoreProblem(refused);
    if (!refused) setState((s) => ({ ...s, source: { kind: 'working' } }));
  };

  const editing = !present && !embed;
  const switchHref = `#/deck?${deckQuery(deck, source, index, { present: !present, embed, theme: themeFlag })}`;
  const actions = (
    <>
      <CopyDeckLink deck={deck} index={index} present={present} />
      {embed ? null : (
        <a
          className="deck-mode"
          data-testid={present ? 'deck-edit-link' : 'deck-present-link'}
          href={switchHref}
        >
          {present ? 'Edit' : 'Present ▶'}
        </a>
      )}
    </>
  );
  return (
    <main id="main" className={`page deck-page${present ? ' is-presenting' : ''}`} tabIndex={-1}>
      <RouteNotice flags={flags} query={query} known={DECK_PARAMS} />
      {problem ? (
        <ParamNotice
          problems={[{ name: 'deck', message: problem }]}
          lead={<strong>The deck link could not be used</strong>}
        >
          <button type="button" className="link-button" onClick={() => setProblem(null)}>
            Dismiss
          </button>
        </ParamNotice>
      ) : null}
      <DeckPlayer
        deck={deck}
        index={index}
        go={go}
        host={host}
        theme={theme}
        present={present}
        actions={actions}
      >
        {editing ? (
          <DeckEditor
            deck={deck}
            index={index}
            working={source.kind === 'working'}
            onDeck={onDeck}
            onOpen={(d) => setState({ deck: d, source: { kind: 'link' }, index: 0 })}
            onKeep={onKeep}
            go={go}
            storeProblem={storeProblem}
          />
        ) : null}
      </DeckPlayer>
    </main>
  );
}

/** "Copy deck link": the deck in the link, on this slide, in classroom mode when the page is. */
function CopyDeckLink({ deck, index, present }: { deck: Deck; index: number; present: boolean }) {
  const [shown, setShown] = useState<{ text: string; copied: boolean } | null>(null);
  const copy = async () => {
    const text = shareUrl(window.location.href, '/deck', sharedDeckQuery(deck, index, present));
    setShown({ text, copied: false });
    try {
      await navigator.clipboard.writeText(text);
      setShown({ text, copied: true });
    } catch {
      /* no clipboard here: the text is in the box */
    }
  };
  return (
    <>
      <button type="button" data-testid="deck-copy-link" onClick={() => void copy()}>
        Copy deck link
      </button>
      <span role="status" className="share-status">
        {shown ? (shown.copied ? 'Deck link copied.' : 'Copy it from the box:') : ''}
      </span>
      {shown ? (
        <input
          className="share-text"
          data-testid="deck-link-text"
          aria-label="The deck link to copy"
          readOnly
          value={shown.text}
          onFocus={(e) => e.currentTarget.select()}
        />
      ) : null}
    </>
  );
}
