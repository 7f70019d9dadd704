import { formatPlain } from '../ui/format';
import { roundTo, type Part } from './model';
import { SCORING, type PartProgress, type Session } from './session';

/** A part's progress in one line: attempts, wrong ones, marks, and how the answer came to be shown. */
export function PartStatus({
  part,
  progress,
  answers,
  open,
}: {
  part: Part;
  progress: PartProgress;
  answers: Session['answers'];
  /** The part's answers are shown (revealed or all right). */
  open: boolean;
}) {
  const marks = part.answers.reduce((m, a) => m + answers[a.name].best, 0);
  const left = SCORING.revealAfter - progress.wrong;
  return (
    <span
      className="part-status"
      data-testid={`attempts-${part.id}`}
      data-attempts={progress.attempts}
      data-wrong={progress.wrong}
    >
      {progress.attempts === 0
        ? 'Not checked yet.'
        : `${progress.attempts} attempt${progress.attempts === 1 ? '' : 's'}, ${progress.wrong} wrong · ${formatPlain(roundTo(marks, 2))} of ${part.answers.length} mark${part.answers.length === 1 ? '' : 's'}`}
      {progress.revealed === 'attempts' ? ' · answer shown after 3 wrong attempts' : ''}
      {progress.revealed === 'asked' ? ' · answer shown' : ''}
      {!open && progress.wrong > 0
        ? ` · ${left} wrong attempt${left === 1 ? '' : 's'} before the answer is shown`
        : ''}
    </span>
  );
}
