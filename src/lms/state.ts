/**
 * What an LMS runtime keeps of a learner's practice: per question of the package, the learner's
 * variant seed, the typed answers, and the last check's score. It is the practice pages' extension
 * (seeds from the learner id, answers restored, every check reported) and serialises itself into
 * SCORM's suspend_data or cmi5's state within a length limit.
 */
import { allAnswers, type QuestionId } from '../practice/model';
import type { CheckRecord, PracticeExtension } from '../practice/extensions';
import { variantOf } from './grade';
import { learnerSeed } from './seeds';

export interface QuestionState {
  seed: number;
  /** Typed answers by answer name. */
  answers: Record<string, string>;
  /** The best marks the page stated for the variant (0 before any check): never lowered. */
  score: number;
  /** Answers the question asks for. */
  max: number;
  checked: boolean;
}

export interface Totals {
  raw: number;
  max: number;
  /** raw / max in [0, 1]. */
  scaled: number;
  /** Questions checked at least once. */
  checked: number;
  questions: number;
  /** Every question checked at least once. */
  complete: boolean;
  passed: boolean;
}

/** What the LMS already holds from an earlier session: a score is never reported lower. */
export interface PriorResult {
  /** The scaled score (0 … 1) the LMS holds, or null when it holds none. */
  scaled: number | null;
  complete: boolean;
  passed: boolean;
}

const round6 = (x: number) => Math.round(x * 1e6) / 1e6;

export class PracticeState {
  readonly byQuestion = new Map<QuestionId, QuestionState>();
  /** The LMS's result from earlier sessions (kept even when the saved state cannot be read). */
  prior: PriorResult = { scaled: null, complete: false, passed: false };

  constructor(
    readonly questions: readonly QuestionId[],
    learnerId: string,
    packageSeed: number,
    public mastery: number,
  ) {
    for (const q of questions) {
      const seed = learnerSeed(learnerId, q, packageSeed);
      const max = allAnswers(variantOf(q, seed)).length;
      this.byQuestion.set(q, { seed, answers: {}, score: 0, max, checked: false });
    }
  }

  totals(): Totals {
    let raw = 0;
    let max = 0;
    let checked = 0;
    for (const s of this.byQuestion.values()) {
      raw += s.score;
      max += s.max;
      if (s.checked) checked++;
    }
    let scaled = max > 0 ? raw / max : 0;
    // never below what the LMS already holds: a lost or unreadable saved state, a relaunch
    if (this.prior.scaled !== null && this.prior.scaled > scaled) {
      scaled = this.prior.scaled;
      raw = round6(scaled * max);
    }
    const complete = checked === this.byQuestion.size || this.prior.complete;
    return {
      raw: round6(raw),
      max,
      scaled: round6(scaled),
      checked,
      questions: this.byQuestion.size,
      complete,
      passed: scaled >= this.mastery - 1e-9 || this.prior.passed,
    };
  }

  /**
   * Apply a check; returns false when it is not one of the package's variants. The question's
   * score is the marks the page states (best kept, nothing for a shown answer), never lowered by a
   * worse later check.
   */
  record(r: CheckRecord): boolean {
    const s = this.byQuestion.get(r.question);
    if (!s || s.seed !== r.seed) return false;
    s.answers = Object.fromEntries(r.answers.map((a) => [a.name, a.response]));
    const earned = r.marks
      ? r.marks.earned
      : r.answers.filter((a) => a.verdict === 'correct' && !r.forfeited?.includes(a.name)).length;
    s.score = round6(Math.max(s.score, Math.min(s.max, Math.max(0, earned))));
    s.checked = true;
    return true;
  }

  /** The practice pages' extension; `onCheck` is told after the state has recorded a check. */
  extension(hooks: { onCheck(r: CheckRecord): void; onInput(): void }): PracticeExtension {
    return {
      seedFor: (q) => this.byQuestion.get(q)?.seed ?? null,
      restore: (q, seed) => {
        const s = this.byQuestion.get(q);
        return s && s.seed === seed && Object.keys(s.answers).length ? { ...s.answers } : null;
      },
      onInput: (q, seed, answers) => {
        const s = this.byQuestion.get(q);
        if (!s || s.seed !== seed) return;
        s.answers = { ...answers };
        hooks.onInput();
      },
      onCheck: (r) => {
        if (this.record(r)) hooks.onCheck(r);
      },
    };
  }

  /**
   * JSON of the state, at most `limit` characters: the longest typed answers are shortened
   * first, then dropped, so scores always survive.
   */
  serialise(limit: number): string {
    const data: Record<string, { s: number; a: Record<string, string>; sc: number; c: number }> = {};
    for (const [q, s] of this.byQuestion)
      data[q] = { s: s.seed, a: { ...s.answers }, sc: s.score, c: s.checked ? 1 : 0 };
    const text = () => JSON.stringify({ v: 1, q: data });
    let out = text();
    while (out.length > limit) {
      let longest: { q: string; k: string; n: number } | null = null;
      for (const [q, e] of Object.entries(data))
        for (const [k, v] of Object.entries(e.a))
          if (!longest || v.length > longest.n) longest = { q, k, n: v.length };
      if (!longest) break;
      const e = data[longest.q];
      if (longest.n > 40) e.a[longest.k] = e.a[longest.k].slice(0, Math.floor(longest.n / 2));
      else delete e.a[longest.k];
      out = text();
    }
    return out;
  }

  /** Restore from {@link serialise}'s text (ignored when unreadable or for other seeds). */
  restore(text: string): boolean {
    try {
      const d = JSON.parse(text) as { v?: number; q?: Record<string, unknown> };
      if (d?.v !== 1 || typeof d.q !== 'object' || d.q === null) return false;
      for (const [q, s] of this.byQuestion) {
        const e = (d.q as Record<string, { s?: unknown; a?: unknown; sc?: unknown; c?: unknown }>)[q];
        if (!e || e.s !== s.seed) continue;
        if (e.a && typeof e.a === 'object')
          s.answers = Object.fromEntries(
            Object.entries(e.a as Record<string, unknown>).filter(
              (x): x is [string, string] => typeof x[1] === 'string',
            ),
          );
        if (typeof e.sc === 'number' && e.sc >= 0 && e.sc <= s.max) s.score = Math.max(s.score, round6(e.sc));
        s.checked = s.checked || e.c === 1;
      }
      return true;
    } catch {
      return false;
    }
  }
}
