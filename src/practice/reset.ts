/**
 * "Reset progress": everything the practice pages keep for this learner is forgotten: progress,
 * best marks, each variant's marking state, and (through the extensions) the results log and the
 * name it downloads under.
 */
import { extensionReset } from './extensions';
import { resetProgress, type Progress } from './progress';
import { resetScores } from './scores';
import { resetSessions } from './sessionKey';

/** Forget this learner's practice data; returns the empty progress. */
export function resetPractice(): Progress {
  const p = resetProgress();
  resetScores();
  resetSessions();
  extensionReset();
  return p;
}
