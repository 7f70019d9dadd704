/**
 * Exam Q4(d): convergence. The graph is the race at the top of the question; the answer reads the
 * errors at the end of the whole run (nothing is shown without a race).
 */
import { Derivation, ExamPart, LiveAnswer, Readout, Revealed } from '../../../ui';
import { formatCount } from '../../../ui/format';
import { RACE_MAX, raceAt } from '../race';
import { Worked } from '../view/examMath';
import { raceOf, type RaceInput } from '../view/RaceSection';

export function Q4d({
  input,
  importanceIsExam,
  onWhole,
  ask,
}: {
  input: RaceInput | null;
  importanceIsExam: boolean;
  onWhole: () => void;
  /** ask=1, not yet revealed: the graph's description and the answer are hidden. */
  ask: boolean;
}) {
  if (!input) return null;
  const { track } = raceOf(input);
  const end = raceAt(track, track.max, []);
  return (
    <Q4dParts
      uErr={end.uniform.absError}
      iErr={end.importance.absError}
      N={RACE_MAX}
      importanceIsExam={importanceIsExam}
      onWhole={onWhole}
      ask={ask}
    />
  );
}

function Q4dParts({
  uErr,
  iErr,
  N,
  onWhole,
  importanceIsExam,
  ask,
}: {
  ask: boolean;
  uErr: number;
  iErr: number;
  N: number;
  onWhole: () => void;
  importanceIsExam: boolean;
}) {
  return (
    <ExamPart
      id="4d"
      title="Convergence"
      asks={
        <>
          Draw a convergence graph: the Monte Carlo estimate as the number of samples grows, for (b) and (c).
          Which converges faster?
        </>
      }
    >
      <Revealed ask={ask} what="the derivation and the answer">
        <Worked>
          <Derivation title="The graph">
            <p>
              The animation at the top of this question is the graph: the running estimate ⟨I⟩ against N for
              uniform sampling (b) and importance sampling (c), drawn from the same random numbers, with the ±
              s/√N band and |error| on log-log axes. Uniform sampling wanders around I and closes in like σ/√N
              (the |error| curve follows the N⁻½ trend);
              {importanceIsExam
                ? ' importance sampling with p ∝ f sits on I from the first sample.'
                : ' the importance lane uses your chosen pdf.'}
            </p>
            <button type="button" onClick={onWhole} data-testid="race-whole">
              Show the whole run ({formatCount(N)} samples)
            </button>
          </Derivation>
          <LiveAnswer>
            <div className="readouts">
              <Readout
                id="q4d-uniform-error"
                label={`uniform |error| after N = ${formatCount(N)}`}
                value={uErr}
                digits={3}
              />
              <Readout
                id="q4d-importance-error"
                label={`importance |error| after N = ${formatCount(N)}`}
                value={iErr}
                digits={3}
              />
            </div>
            {importanceIsExam ? (
              <p data-testid="answer-4d">
                <strong>(c) converges faster</strong>: it has zero variance (every term f/p equals I), so its
                error is at rounding level for every N, while the uniform estimator’s error only falls like
                N⁻½.
              </p>
            ) : (
              <p data-testid="answer-4d">
                With p ∝ f (the exam’s (c)) the importance estimate would be exact at every N (zero variance);
                your pdf only approximates f, so its error also falls like N⁻½, with a smaller constant when p
                follows f more closely.
              </p>
            )}
          </LiveAnswer>
        </Worked>
      </Revealed>
    </ExamPart>
  );
}
