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
import { useMemo, type ComponentType } from 'react';
import type { ShellFlags } from '../kit/shell';
import { lazyPage } from '../ui/lazyPage';
import { PracticeHome } from './PracticeHome';
import { LOAD_GENERATOR } from './generators';
import { QUESTION_IDS, isQuestionId, type QuestionId } from './model';
import type { QuestionRouteProps } from './QuestionRoute';
import './practice.css';

// A question page and the worksheet are chunks of their own, with the variant generators and the
// marking code: the index lists the questions without them. A question page brings only its own
// question's generator. (Each route's chunks are preloaded with the entry:
// scripts/routePreload.ts.)
const QUESTION_PAGES = Object.fromEntries(
  QUESTION_IDS.map((id) => [
    id,
    lazyPage(
      () =>
        Promise.all([import('./QuestionRoute'), LOAD_GENERATOR[id]()]).then(([m, generate]) => ({
          default: (props: QuestionRouteProps) => <m.QuestionRoute {...props} generate={generate} />,
        })),
      'This practice question',
    ),
  ]),
) as Record<QuestionId, ComponentType<QuestionRouteProps>>;
const Sheet = lazyPage(() => import('./Sheet'), 'The worksheet');

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
  if (isQuestionId(sub)) {
    const QuestionPage = QUESTION_PAGES[sub];
    return <QuestionPage key={sub} q={sub} sp={sp} flags={flags} />;
  }
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
