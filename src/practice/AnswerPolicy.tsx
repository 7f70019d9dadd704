import { FORMULA_POLICY, NUMERIC_POLICY } from './check';
import { SCORING } from './session';

/** Text whose typed examples stand between backticks, with those set as code. */
function withCode(text: string) {
  return text.split('`').map((t, i) => (i % 2 ? <code key={i}>{t}</code> : t));
}

/** How answers are checked and marked: the policy the question page states under its answers. */
export function AnswerPolicy() {
  return (
    <details className="policy" data-testid="policy">
      <summary>How answers are checked and marked</summary>
      <p>{withCode(NUMERIC_POLICY.text)}</p>
      <p>{withCode(FORMULA_POLICY.text)}</p>
      <p>
        Classic mistakes the key deducts marks for are recognised and named. Where the key accepts another
        convention (the grid read with v′ = 1 − v in Q3), it is accepted and said so, as long as every answer
        of the variant uses the same one.
      </p>
      <p data-testid="scoring-policy">{SCORING.text}</p>
    </details>
  );
}
