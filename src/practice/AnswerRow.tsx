import { MathTex } from '../ui/MathTex';
import { Superscripted } from '../ui/Superscripted';
import { formatSignificant } from '../ui/format';
import { expectedText } from './check';
import type { AnswerSpec } from './model';
import type { AnswerProgress } from './session';
import { Verdict, verdictKind } from './Verdict';

function answerHint(spec: Exclude<AnswerSpec, { kind: 'choice' }>): string {
  if (spec.kind === 'formula') return `formula in ${spec.variables.join(', ')}`;
  return 'number, expression or none';
}

/** The option a stored answer names (a draft typed before choices were lists: "two hits"), or ''. */
function choiceValue(options: readonly string[], text: string): string {
  const s = text.trim().toLowerCase().replace(/\s+/g, '-');
  return options.includes(s) ? s : '';
}

/**
 * One answer of a part: its field (contract: `answer-NAME`), its verdict once checked and, once the
 * part is open, the expected answer (`expected-NAME`).
 */
export function AnswerRow({
  spec,
  value,
  onChange,
  progress,
  revealed,
}: {
  spec: AnswerSpec;
  value: string;
  onChange: (t: string) => void;
  progress: AnswerProgress;
  revealed: boolean;
}) {
  const id = `answer-${spec.name}`;
  const exp = expectedText(spec);
  const verdict = progress.verdict;
  const kind = verdict ? verdictKind(verdict.value) : null;
  // What the answer's control carries whether it is a choice or typed text.
  const control = {
    id,
    'data-testid': id,
    'aria-describedby': verdict ? `verdict-${spec.name}` : undefined,
    'aria-invalid': verdict && verdict.value !== 'correct' ? true : undefined,
  };
  return (
    <div className={`answer-row${kind ? ` is-${kind}` : ''}`}>
      <label htmlFor={id} className="answer-label">
        <Superscripted text={spec.label} />
      </label>
      {spec.kind === 'choice' ? (
        // a choice is chosen from its options (graded as the option's name), never typed
        <select
          {...control}
          value={choiceValue(spec.options, value)}
          onChange={(e) => onChange(e.target.value)}
        >
          <option value="">Choose…</option>
          {spec.options.map((o) => (
            <option key={o} value={o}>
              {o.replace(/-/g, ' ')}
            </option>
          ))}
        </select>
      ) : (
        <input
          {...control}
          type="text"
          value={value}
          onChange={(e) => onChange(e.target.value)}
          autoComplete="off"
          autoCapitalize="off"
          spellCheck={false}
          placeholder={answerHint(spec)}
        />
      )}
      {verdict ? <Verdict name={spec.name} verdict={verdict} credit={progress.last} /> : null}
      {revealed ? (
        <p className="expected">
          Expected:{' '}
          <output data-testid={`expected-${spec.name}`} data-value={exp} title={exp}>
            {spec.tex ? (
              <MathTex tex={spec.tex} />
            ) : spec.kind === 'number' && spec.expected !== null ? (
              formatSignificant(spec.expected, 6, 'e')
            ) : (
              // the answer as one would type it (expression syntax)
              <code>{exp}</code>
            )}
          </output>
        </p>
      ) : null}
    </div>
  );
}
