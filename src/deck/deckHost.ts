/**
 * What the app lends the deck page: the deck plays scenes through the app's scene host, which sits
 * above the deck's layer, so the app passes it in (src/app/SlideScene.tsx) instead of the deck
 * importing it.
 */
import type { ComponentType } from 'react';

export interface SlideSceneProps {
  /** The slide's scene route, e.g. `/texture`. */
  path: string;
  /** The slide link's query (its scene state, `ask=1`, `part=`). */
  query: string;
  /** The slide's question: the prompt of an asking slide. */
  question: string | null;
  theme: 'light' | 'dark';
  /** Classroom mode (the deck presenting): the figure fills the stage. Else the scene's page layout. */
  present: boolean;
  /** Called when the slide's held-back results are revealed (`v` or the button). */
  onReveal: () => void;
}

export interface DeckHost {
  /** Hosts a scene link as a slide, never writing the address. */
  SlideScene: ComponentType<SlideSceneProps>;
}
