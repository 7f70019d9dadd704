/**
 * KaTeX typesetting off the main thread: a scene's exam page has a hundred-odd
 * formulas, and one aligned derivation takes tens of ms to typeset on a phone — each one a long
 * task on the main thread. Here they cost the page nothing; the main thread only inserts the HTML.
 * Requests are answered in the order they arrive (the page sends the formulas near the screen
 * first).
 */
import katex from 'katex';
import { KATEX_OPTIONS } from './katexOptions';
import { speakableMathml } from './mathmlSpeech';

export interface TypesetRequest {
  id: number;
  tex: string;
  display: boolean;
}
export interface TypesetReply {
  id: number;
  /** KaTeX's HTML + MathML, or null if it failed (the page then shows the TeX source). */
  html: string | null;
}

self.onmessage = (e: MessageEvent<TypesetRequest>) => {
  const { id, tex, display } = e.data;
  let html: string | null = null;
  try {
    html = speakableMathml(katex.renderToString(tex, { ...KATEX_OPTIONS, displayMode: display }));
  } catch {
    html = null;
  }
  (self as unknown as Worker).postMessage({ id, html } satisfies TypesetReply);
};
