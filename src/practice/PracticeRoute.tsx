/**
 * Practice mode (its own lazy chunk): `#/practice` (the six questions with the student's progress),
 * `#/practice/q1` … `#/practice/q6` with `seed` (one variant: givens, answer fields, "Check",
 * mistake-aware verdicts, the worked solution and a link to the scene), and the printable worksheet
 * `#/practice/sheet?seed=…&q=1,3,5&count=…`.
 *
 * Contract (README): givens `data-testid="given-NAME"` with full-precision `data-value`; inputs
 * `answer-NAME`; verdicts `verdict-NAME` with `data-value` correct | incorrect | mistake:<id> |
 * invalid; expected answers `expected-NAME` once shown. Every verdict is also announced to the page
 * as `rml:practice-verdict` (a CustomEvent on window) for the host-page API.
 */
import { useMemo } from 'react';
import type { ShellFlags } from '../kit/shell';
import { PracticeHome } from './PracticeHome';
import { QuestionRoute } from './QuestionRoute';
import { isQuestionId } from './questions';
import Sheet from './Sheet';
import './practice.css';

interface Props {
  path: string;
  query: string;
  flags: ShellFlags;
}

export default function PracticeRoute({ path, query, flags }: Props) {
  const sp = useMemo(() => new URLSearchParams(query), [query]);
  const sub = path.slice('/practice'.length).replace(/^\//, '');
  if (sub === '') return <PracticeHome flags={flags} query={query} />;
  if (sub === 'sheet') return <Sheet sp={sp} flags={flags} />;
  if (isQuestionId(sub)) return <QuestionRoute key={sub} q={sub} sp={sp} flags={flags} />;
  return (
    <main id="main" className="page practice" tabIndex={-1}>
      <h1>Page not found</h1>
      <p role="status">
        There is no practice page <code>{sub.slice(0, 40)}</code>.{' '}
        <a href="#/practice">See the practice questions</a>.
      </p>
    </main>
  );
}
