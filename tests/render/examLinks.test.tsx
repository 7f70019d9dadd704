/**
 * "Practise this" outside the browser: each exam question ends with one pair of links to its
 * practice page (the fixed variant everyone shares, and a fresh one), its parts carry none, and the
 * catalogue's scenes reach all six questions. (The whole-page pass checks every scene's questions
 * in the browser.)
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { ExamPart, ExamQuestion, PRACTISE_SEED, PractiseLinks } from '../../src/ui/exam';
import { SCENES } from '../../src/kit/catalogue';

describe('Practise this', () => {
  it('ends each question with one pair of links to its practice page', () => {
    const html = renderToStaticMarkup(
      <ExamQuestion n={3}>
        <ExamPart id="3a" asks="a">
          <p>steps</p>
        </ExamPart>
        <ExamPart id="3b" asks="b">
          <p>steps</p>
        </ExamPart>
      </ExamQuestion>,
    );
    expect(html.match(/data-testid="practise-link-/g)).toHaveLength(1);
    expect(html).toContain(`href="#/practice/q3?seed=${PRACTISE_SEED}" data-testid="practise-link-3"`);
    expect(html).toContain('href="#/practice/q3" data-testid="practise-fresh-3"');
    // after the parts
    expect(html.indexOf('practise-link-3')).toBeGreaterThan(html.indexOf('part-3b'));
  });

  it('links nowhere for a number that is not an exam question', () => {
    expect(renderToStaticMarkup(<PractiseLinks n={7} />)).toBe('');
    expect(renderToStaticMarkup(<PractiseLinks n={0} />)).toBe('');
  });

  it('the scenes together reach all six questions', () => {
    const qs = new Set(SCENES.flatMap((s) => s.parts.map((p) => p[0])));
    expect([...qs].sort()).toEqual(['1', '2', '3', '4', '5', '6']);
  });
});
