/**
 * `#/deck`, the lecture deck (src/deck), with what only the app has: its scene host, which plays
 * each slide's scene link (in classroom mode while the deck presents) without writing the address
 * (the deck's).
 */
import { useMemo } from 'react';
import { findScene } from '../kit/catalogue';
import { parseShellFlags, type ShellFlags } from '../kit/shell';
import { DeckPage } from '../deck/DeckPage';
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

const HOST: DeckHost = { SlideScene };

export default function DeckRoute({
  flags,
  query,
  theme,
}: {
  flags: ShellFlags;
  query: string;
  theme: 'light' | 'dark';
}) {
  return <DeckPage flags={flags} query={query} theme={theme} host={HOST} />;
}
