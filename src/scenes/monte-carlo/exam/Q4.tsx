/**
 * Exam Q4's introduction: what the question asks, a way back to the exam's configuration when the
 * page's settings differ, and the race of uniform against importance sampling that (d) refers to.
 */
import { EXAM_A, EXAM_B, EXAM_F, EXAM_SAMPLES, type Exact, type SampleTable } from '../model';
import { RaceSection, type RaceInput } from '../view/RaceSection';
import { Q4Answers } from './Q4Answers';

export function Q4Intro({
  isExamConfig,
  onExamConfig,
  race,
  importanceLabel,
  importanceName,
  t,
  play,
  setRace,
  exact,
  table,
  present,
}: {
  /** Classroom mode: the race (the figure the room watches) first, the answers under it. */
  present: boolean;
  exact: Exact | null;
  table: SampleTable | null;
  isExamConfig: boolean;
  onExamConfig: (patch: { f: string; a: number; b: number; samples: number[] }) => void;
  race: RaceInput | null;
  importanceLabel: string;
  importanceName: string;
  t: number;
  play: boolean;
  setRace: (patch: { t?: number; play?: boolean }) => void;
}) {
  const answers = <Q4Answers exact={exact} table={table} isExamConfig={isExamConfig} />;
  return (
    <>
      <p>
        I = ∫₀² (x + 2)² dx: (a) analytically, (b) uniform Monte Carlo, (c) importance sampling, (d)
        convergence.
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
      {present ? null : answers}
      <RaceSection
        input={race}
        importanceLabel={importanceLabel}
        importanceName={importanceName}
        t={t}
        play={play}
        setParams={setRace}
        fallback={
          <p className="mc-note">The animation needs a finite integral and a usable importance pdf.</p>
        }
      />
      {present ? answers : null}
    </>
  );
}
