/**
 * Answers typed on a practice page but not yet checked survive a reload of the tab (the reader's
 * own, or the one that moves the tab to a new build): they are kept per question and seed in this
 * tab's sessionStorage, which lives as long as the tab (per learner inside an LMS package:
 * ./learnerScope.ts). Only plain strings are read back; anything
 * else stored under the key is ignored.
 */
import { scopedKey } from './learnerScope';

const PREFIX = 'rml:practice-draft:';
const MAX_ANSWERS = 64;
const MAX_LENGTH = 4000;

function key(question: string, seed: number): string {
  return scopedKey(`${PREFIX}${question}:${seed}`);
}

function storage(): Storage | null {
  try {
    return window.sessionStorage;
  } catch {
    return null; // sandboxed frame, storage disabled
  }
}

/** The answers typed for this variant in this tab (empty when none, or unreadable). */
export function loadDraft(question: string, seed: number): Record<string, string> {
  let raw: unknown;
  try {
    raw = JSON.parse(storage()?.getItem(key(question, seed)) ?? 'null');
  } catch {
    return {};
  }
  if (!raw || typeof raw !== 'object' || Array.isArray(raw)) return {};
  const out: Record<string, string> = {};
  for (const [name, text] of Object.entries(raw as Record<string, unknown>).slice(0, MAX_ANSWERS)) {
    if (typeof text === 'string' && text.length <= MAX_LENGTH && /^[a-z0-9-]{1,40}$/i.test(name))
      out[name] = text;
  }
  return out;
}

/** Keeps the answers typed for this variant (an all-empty set removes the draft). */
export function saveDraft(question: string, seed: number, inputs: Record<string, string>): void {
  const s = storage();
  if (!s) return;
  const kept = Object.fromEntries(
    Object.entries(inputs).filter(([, t]) => t !== '' && t.length <= MAX_LENGTH),
  );
  try {
    if (Object.keys(kept).length === 0) s.removeItem(key(question, seed));
    else s.setItem(key(question, seed), JSON.stringify(kept));
  } catch {
    /* quota or disabled storage: the answers stay in the page */
  }
}

/**
 * The answers a practice page opens with: this tab's draft (typed last, so the newest, as after a
 * crash and relaunch inside an LMS), else what an extension kept (an LMS's saved answers: a
 * relaunch in a new tab), else none.
 */
export function openingAnswers(
  question: string,
  seed: number,
  kept: () => Record<string, string> | null,
): Record<string, string> {
  const draft = loadDraft(question, seed);
  if (Object.keys(draft).length) return draft;
  return kept() ?? {};
}
