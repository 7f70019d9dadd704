/**
 * What the app lends the lecture deck (src/deck, `#/deck`): its scene host, playing a slide's scene
 * link (in classroom mode while the deck presents) without writing the address, which is the
 * deck's. Handed to the deck's page as a prop: the deck sits below the app, and a lazy chunk that
 * imported the scene host would split the entry's shared code into more chunks.
 */
import { useMemo } from 'react';
import { findScene } from '../kit/catalogue';
import { parseShellFlags, type ShellFlags } from '../kit/shell';
import type { DeckHost, SlideSceneProps } from '../deck/deckHost';
import { SceneHost } from './SceneHost';

function SlideScene({ path, query, question, theme, present, onReveal }: SlideSceneProps) {
  const info = findScene(path);
  // the slide's own flags (ask, part, open); the deck decides the rest
  const flags = useMemo<ShellFlags>(
    () => ({ ...parseShellFlags(query), present, embed: false, theme: null, origins: null }),
    [query, present],
  );
  if (!info) return null;
  return <SceneHost info={info} query={query} flags={flags} theme={theme} slide={{ question, onReveal }} />;
}

export const DECK_HOST: DeckHost = { SlideScene };
