/**
 * Whose practice data this page keeps. On a public page it is this browser's (keys as named);
 * inside an LMS package the LMS names the learner, and every key the practice pages, the results
 * log and the name use is suffixed with a hash of that learner's id, so the next learner on a
 * shared lab computer starts with nothing of the previous one's. Only the hash is stored, never
 * the id itself (it may be an e-mail address).
 */

let scope = '';

/** A 64-bit FNV-1a style hash of `s` as 16 hex digits (two 32-bit lanes, different offsets). */
export function learnerHash(s: string): string {
  let a = 0x811c9dc5;
  let b = 0x01000193 ^ 0x9e3779b9;
  for (let i = 0; i < s.length; i++) {
    const c = s.charCodeAt(i);
    a = Math.imul(a ^ c, 0x01000193);
    b = Math.imul(b ^ c, 0x5bd1e995);
    b ^= b >>> 13;
  }
  const hex = (x: number) => (x >>> 0).toString(16).padStart(8, '0');
  return hex(a) + hex(b);
}

/** Keep this page's practice data for the learner `learnerId` (null: this browser's own). */
export function setLearnerScope(learnerId: string | null): void {
  scope = learnerId ? `@${learnerHash(learnerId)}` : '';
}

/** The storage key `base` for the current learner. */
export function scopedKey(base: string): string {
  return base + scope;
}
