/**
 * Exam Q4's answers first: (a), (b) and (c) as the model computes them for the page's f, [a, b] and
 * samples (the exam's unless changed), above the race, so they stand on the first screen. The parts
 * below derive each of them.
 */
import { Readout } from '../../../ui';
import { estimateHasZeroVariance } from '../zeroVariance';
import { roundTo } from '../exam';
import type { Exact } from '../integral';
import type { SampleTable } from '../sampleTable';
import { thirdsText } from '../view/examMath';

export function Q4Answers({
  exact,
  table,
  isExamConfig,
}: {
  exact: Exact | null;
  table: SampleTable | null;
  isExamConfig: boolean;
}) {
  const I = exact && !exact.problem ? exact.value : null;
  const uni = table && !table.uniform.invalid ? table.uniform : null;
  const prop = table?.proportional && !table.proportional.invalid ? table.proportional : null;
  const xs = table ? table.rows.filter((r) => !r.outside).map((r) => String(r.x)) : [];
  return (
    <section className="mc-answers" aria-labelledby="mc-answers-title" data-testid="q4-answers">
      <h3 id="mc-answers-title" className="mc-answers-title">
        The answers, computed live (derived in (a)–(d) below)
      </h3>
      <div className="readouts mc-answers-row">
        <Readout
          id="q4-answer-a"
          label={isExamConfig ? '(a) I = ∫₀² (x + 2)² dx' : '(a) I = ∫ f dx'}
          value={I}
          digits={6}
          note={I !== null ? `= ${thirdsText(I)}` : undefined}
        />
        <Readout
          id="q4-answer-b"
          label={
            isExamConfig ? `(b) uniform ⟨I⟩, x = ${xs.join(', ')}` : `(b) uniform ⟨I⟩, ${xs.length} samples`
          }
          value={uni ? uni.estimate : null}
          digits={6}
          note={uni ? `≈ ${roundTo(uni.estimate, 2).toFixed(2)} to 2 decimals` : undefined}
        />
        <Readout
          id="q4-answer-c"
          label="(c) ⟨I⟩ with p ∝ f"
          value={prop ? prop.estimate : null}
          digits={6}
          note={
            prop
              ? estimateHasZeroVariance(prop)
                ? `= ${thirdsText(prop.estimate)}: every term f/p is the same (zero variance)`
                : `= ${thirdsText(prop.estimate)} (tabulated p: the terms vary a little)`
              : undefined
          }
        />
      </div>
      <p className="mc-note">
        (d) is the race below: the estimate as the samples arrive, uniform against importance sampling.
      </p>
    </section>
  );
}
