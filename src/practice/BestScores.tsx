import type { ShellFlags } from '../kit/shell';
import { flagSuffix } from './links';
import type { QuestionId } from './model';
import type { Scores } from './scores';

/** The best marks kept for a question's variants (the three best, linked). */
export function BestScores({ q, scores, flags }: { q: QuestionId; scores: Scores; flags: ShellFlags }) {
  const list = Object.entries(scores[q]).sort((a, b) => b[1] - a[1]);
  if (!list.length) return null;
  return (
    <p className="practice-best muted" data-testid={`best-${q}`} data-count={list.length}>
      Best marks:{' '}
      {list.slice(0, 3).map(([seed, score], i) => (
        <span key={seed}>
          {i ? ', ' : ''}
          <a href={`#/practice/${q}?seed=${seed}${flagSuffix(flags)}`}>variant {seed}</a>{' '}
          {Math.round(score * 100)} %
        </span>
      ))}
      {list.length > 3 ? ` (and ${list.length - 3} more)` : ''}.
    </p>
  );
}
