import { Superscripted } from '../ui/Superscripted';
import { AnswerRow } from './AnswerRow';
import type { Part } from './model';
import { PartStatus } from './PartStatus';
import type { PartProgress, Session } from './session';
import { ShowAnswer } from './ShowAnswer';
import { SolutionSteps } from './SolutionSteps';

/**
 * One part of the question as a fieldset: its answers, its status, the hint and "Show answer"
 * buttons, the hint once asked for, and the part's worked step once the part is open.
 */
export function PartBlock({
  part,
  progress,
  answers,
  inputs,
  onInput,
  onHint,
  onReveal,
  stepsBelow,
}: {
  part: Part;
  progress: PartProgress;
  answers: Session['answers'];
  inputs: Record<string, string>;
  onInput: (name: string, text: string) => void;
  onHint: () => void;
  onReveal: () => void;
  /** The whole worked solution is shown below the form: the part's step is not repeated here. */
  stepsBelow: boolean;
}) {
  const done = part.answers.every((a) => answers[a.name].verdict?.value === 'correct');
  const open = progress.revealed !== null || done;
  return (
    <fieldset className="practice-part" data-testid={`part-${part.id}`}>
      <legend>
        <Superscripted text={part.prompt} />
      </legend>
      {part.answers.map((a) => (
        <AnswerRow
          key={a.name}
          spec={a}
          value={inputs[a.name] ?? ''}
          onChange={(t) => onInput(a.name, t)}
          progress={answers[a.name]}
          revealed={open}
        />
      ))}
      <div className="part-tools">
        <PartStatus part={part} progress={progress} answers={answers} open={open} />
        {!progress.hint && !open ? (
          <button type="button" onClick={onHint} data-testid={`hint-${part.id}`}>
            Hint
          </button>
        ) : null}
        {progress.revealed === null && !done ? <ShowAnswer partId={part.id} onReveal={onReveal} /> : null}
      </div>
      {progress.hint && !open ? (
        <div className="part-hint" data-testid={`hint-text-${part.id}`}>
          <strong>Hint:</strong> <SolutionSteps steps={part.hint} />
        </div>
      ) : null}
      {open && !stepsBelow ? (
        <div className="part-solution" data-testid={`part-solution-${part.id}`}>
          <h3 className="part-solution-title">Worked step</h3>
          <SolutionSteps steps={part.steps} />
        </div>
      ) : null}
    </fieldset>
  );
}
