/**
 * Where the practice sessions (./sessionStore.ts) are kept, and forgetting them: apart from the
 * store, so that "Reset progress" on the practice index does not load the marking code.
 */
import { scopedKey } from './learnerScope';

export const SESSIONS_KEY = 'rml:practice-sessions';

/** Forget every variant's marking state for this learner. */
export function resetSessions(): void {
  try {
    window.localStorage.removeItem(scopedKey(SESSIONS_KEY));
  } catch {
    /* nothing to remove */
  }
}
