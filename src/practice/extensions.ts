/**
 * Extension points of the practice pages, for code that runs beside them without being part of
 * them (an LMS runtime inside a SCORM or cmi5 package, the results recorder behind "Download my
 * results"). The pages ask the registered extensions three things and tell them one:
 *
 *  - `seedFor(q)`: the variant seed of question q when the link gives none (an LMS derives it from
 *    the learner id, so each learner keeps their own variant across sessions);
 *  - `restore(q, seed)`: typed answers to put back into the fields (a learner resuming);
 *  - `onInput(q, seed, answers)`: the fields changed (an LMS keeps them in its suspend data);
 *  - `onCheck(record)`: the learner pressed Check: every typed answer and its verdict, the marks
 *    the page states, and the answers that earn nothing because they were shown;
 *  - `onReset()`: the learner pressed "Reset progress" (a results log forgets its checks and name).
 *
 * Nothing registers by default; with no extension the pages behave exactly as without this module.
 */
import type { ComponentType } from 'react';
import type { QuestionId } from './model';

export interface CheckedAnswer {
  /** The answer's name (the contract's `answer-NAME`). */
  name: string;
  /** What the learner typed. */
  response: string;
  /** The verdict's data-value: correct | incorrect | invalid | mistake:<id>. */
  verdict: string;
  /** The verdict's message (the named mistake's explanation, for instance). */
  message: string;
}

export interface CheckRecord {
  question: QuestionId;
  seed: number;
  /** Every answer the question asks for, in order (blank ones included, with verdict 'blank'). */
  answers: CheckedAnswer[];
  /** When the check happened (ISO 8601). */
  time: string;
  /** The variant's marks as the page states them after this check (best kept, forfeits applied). */
  marks?: { earned: number; total: number };
  /** Answers whose part's answer was shown before this check: they earn nothing. */
  forfeited?: string[];
}

export interface PracticeExtension {
  seedFor?(q: QuestionId): number | null;
  restore?(q: QuestionId, seed: number): Record<string, string> | null;
  onInput?(q: QuestionId, seed: number, answers: Record<string, string>): void;
  onCheck?(record: CheckRecord): void;
  onReset?(): void;
}

const extensions: PracticeExtension[] = [];

/** Register an extension; returns its removal. */
export function addPracticeExtension(x: PracticeExtension): () => void {
  extensions.push(x);
  return () => {
    const i = extensions.indexOf(x);
    if (i >= 0) extensions.splice(i, 1);
  };
}

function each<T>(f: (x: PracticeExtension) => T | null | undefined): T | null {
  for (const x of extensions) {
    try {
      const r = f(x);
      if (r !== null && r !== undefined) return r;
    } catch {
      /* an extension's failure never breaks the page */
    }
  }
  return null;
}

/** The first registered extension's seed for q, or null. */
export function extensionSeed(q: QuestionId): number | null {
  return each((x) => x.seedFor?.(q));
}

/** The first registered extension's saved answers for (q, seed), or null. */
export function extensionRestore(q: QuestionId, seed: number): Record<string, string> | null {
  return each((x) => x.restore?.(q, seed));
}

export function extensionInput(q: QuestionId, seed: number, answers: Record<string, string>): void {
  each((x) => x.onInput?.(q, seed, answers));
}

export function extensionCheck(record: CheckRecord): void {
  each((x) => x.onCheck?.(record));
}

/** Tell every registered extension that the learner reset their progress. */
export function extensionReset(): void {
  for (const x of extensions)
    try {
      x.onReset?.();
    } catch {
      /* an extension's failure never breaks the page */
    }
}

// ---------------------------------------------------------------------------------------------
// Slots: parts of the practice pages that other features provide (registered by the app before the
// pages render, so practice never imports them): "Download my results" under a question and on the
// list, and the LMS packages on the worksheet page.

export interface SlotProps {
  'question-footer': Record<string, never>;
  'home-footer': Record<string, never>;
  sheet: { questions: QuestionId[]; variants: number; seed: number };
}
export type SlotName = keyof SlotProps;

const slots: { [K in SlotName]?: ComponentType<SlotProps[K]> } = {};

export function registerPracticeSlot<K extends SlotName>(
  name: K,
  component: ComponentType<SlotProps[K]>,
): void {
  (slots as Record<string, unknown>)[name] = component;
}

/** The component registered for a slot, or null. */
export function practiceSlot<K extends SlotName>(name: K): ComponentType<SlotProps[K]> | null {
  return (slots[name] as ComponentType<SlotProps[K]> | undefined) ?? null;
}
