/**
 * Every practice question's page rendered outside the browser (react-dom/server), with every part's
 * answer shown so that the expected answers and the worked solution are on it too: no caret in the
 * text a reader sees. Powers are written as superscripts; a formula is rendered here as the
 * plain-text reading shown until KaTeX arrives, which has no caret either. Code (an expression as
 * typed, TeX source) is not prose and is left out.
 */
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { QuestionPage } from '../../src/practice/QuestionPage';
import { QUESTIONS } from '../../src/practice/questions';
import { loadSession, saveSession } from '../../src/practice/sessionStore';
import { revealPart } from '../../src/practice/session';
import { parseShellFlags } from '../../src/kit/shell';
import { installWindow } from '../practice/memoryWindow';

let remove = () => {};
beforeEach(() => {
  remove = installWindow();
});
afterEach(() => remove());

/** The text of the markup outside code, with the elements' tags dropped. */
function proseOf(html: string): string {
  return html
    .replace(/<(code|pre|kbd|samp|textarea|script|style)\b[^>]*>[\s\S]*?<\/\1>/g, ' ')
    .replace(/<[^>]+>/g, ' ')
    .replace(/&[a-z#0-9]+;/gi, ' ');
}

describe('the practice questions: no caret in the statement, the expected answers or the worked solution', () => {
  for (const q of QUESTIONS)
    it(q.id, () => {
      const v = q.generate(3);
      saveSession(
        v,
        v.parts.reduce((s, p) => revealPart(s, p.id), loadSession(v)),
      );
      const html = renderToStaticMarkup(
        <QuestionPage variant={v} flags={parseShellFlags('')} problems={[]} />,
      );
      // the page shows the worked solution and every part's expected answers
      expect(html).toContain('data-testid="solution"');
      for (const p of v.parts)
        for (const a of p.answers) expect(html, a.name).toContain(`data-testid="expected-${a.name}"`);
      const text = proseOf(html);
      const at = text.indexOf('^');
      expect(at < 0 ? '' : text.slice(Math.max(0, at - 40), at + 20)).toBe('');
    });
});
