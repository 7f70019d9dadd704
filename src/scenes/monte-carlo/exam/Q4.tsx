/**
 * Exam Q4's introduction: what the question asks, a way back to the exam's configuration when the
 * page's settings differ, the answers first, and the race of uniform against importance sampling
 * that (d) refers to (in classroom mode the race is the stage above, and the answers follow here).
 * The race as a table and as sound is folded under the race.
 */
import type { ReactNode } from 'react';
import { Revealed, keepTextParenthesesTogether } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { EXAM_F, EXAM_SAMPLES } from '../exam';
import { EXAM_A, EXAM_B } from '../integral';
import type { Exact } from '../integral';
import type { SampleTable } from '../sampleTable';
import { RaceDataSection, type RaceInput } from '../view/RaceSection';
import { Q4Answers } from './Q4Answers';

export function Q4Intro({
  isExamConfig,
  onExamConfig,
  race,
  input,
  t,
  exact,
  table,
  ask,
}: {
  isExamConfig: boolean;
  onExamConfig: (patch: { f: string; a: number; b: number; samples: number[] }) => void;
  /** The race, or null when it is the stage (classroom mode). */
  race: ReactNode;
  input: RaceInput | null;
  /** The race's paused position (for its table and audio traces). */
  t: number;
  exact: Exact | null;
  table: SampleTable | null;
  /** ask=1, not yet revealed. */
  ask: boolean;
}) {
  const answers = (
    <Revealed ask={ask} what="the answers (a)–(c)" minHeight="6rem">
      <Q4Answers exact={exact} table={table} isExamConfig={isExamConfig} />
    </Revealed>
  );
  return (
    <>
      <p>
        I = ∫₀² {keepTextParenthesesTogether('(x + 2)²')} dx: (a) analytically, (b) uniform Monte Carlo, (c)
        importance sampling, (d) convergence.
        {!isExamConfig ? (
          <>
            {' '}
            <span className="mc-note" data-testid="not-exam-config">
              Your settings differ from the exam’s; the numbers below are for yours.{' '}
              <button
                type="button"
                onClick={() => onExamConfig({ f: EXAM_F, a: EXAM_A, b: EXAM_B, samples: [...EXAM_SAMPLES] })}
              >
                Exam configuration
              </button>
            </span>
          </>
        ) : null}
      </p>
      {race ? answers : null}
      {race}
      {input ? (
        <Fold name="race-data" summary="The race as a table and as sound (audio traces)">
          <Revealed ask={ask} what="the race as a table and as sound">
            <RaceDataSection input={input} t={t} />
          </Revealed>
        </Fold>
      ) : null}
      {race ? null : answers}
    </>
  );
}
