/**
 * One student's work on one variant, as pure data: the verdicts of what was typed, attempts per
 * part, hints and answers shown, and the marks earned ({@link SCORING}). The page keeps a
 * {@link Session} in its state; nothing here touches the DOM.
 *
 * Grading ({@link gradeAnswers}) reads only what is typed. After each answer's own verdict:
 * - conventions: an answer correct only under an accepted convention (the grid's v′ = 1 − v) must
 *   agree with the variant's other answers; a mix is named `mistake:mixed-convention`;
 * - follow-through: an answer that is not correct, but is what the student's own earlier (wrong)
 *   answers give, is `consistent` and earns the stated partial credit.
 */
import { checkChoice, classifyTypedFormula, classifyTyped, normaliseInput, parseNumberAnswer } from './check';
import type { Verdict } from './check';
import { compileExpression } from '../core/expr';
import { allAnswers, type AnswerSpec, type OwnValue, type Part, type Variant } from './model';

export const SCORING = {
  /** Taken off an answer's mark for each earlier wrong attempt at its part. */
  penalty: 0.1,
  /** The share of a mark for an answer consistent with the student's own wrong earlier answers. */
  followCredit: 0.5,
  /** Wrong attempts at a part after which its answer and worked step are shown. */
  revealAfter: 3,
  text: 'Marks: each answer is worth 1 mark, less 10 % for each earlier wrong attempt at its part (a wrong attempt is a Check in which an answer of the part you changed was readable but not right). An answer that is right for your own wrong earlier answers (follow-through) earns half. Your best mark for each answer counts. Hints are free. Once a part’s answer is shown (by Show answer, or after 3 wrong attempts) that part earns no more. Answers that cannot be read, or have too few figures, do not count as attempts.',
} as const;

export interface PartProgress {
  attempts: number;
  wrong: number;
  hint: boolean;
  /** null: not shown yet; 'asked': Show answer; 'attempts': after {@link SCORING.revealAfter} wrong attempts. */
  revealed: null | 'asked' | 'attempts';
}

export interface AnswerProgress {
  /** The best mark earned so far (0 … 1). */
  best: number;
  /** The mark the latest check of this answer earned. */
  last: number;
  /** The text last counted as an attempt. */
  counted: string | null;
  verdict: Verdict | null;
}

export interface Session {
  parts: Record<string, PartProgress>;
  answers: Record<string, AnswerProgress>;
}

export function newSession(v: Variant): Session {
  const parts: Record<string, PartProgress> = {};
  const answers: Record<string, AnswerProgress> = {};
  for (const p of v.parts) {
    parts[p.id] = { attempts: 0, wrong: 0, hint: false, revealed: null };
    for (const a of p.answers) answers[a.name] = { best: 0, last: 0, counted: null, verdict: null };
  }
  return { parts, answers };
}

// ---------------------------------------------------------------------------------------------
// Grading what is typed

interface Graded {
  verdict: Verdict;
  /** What the student's answer is, for follow-through (absent when it could not be read). */
  own?: OwnValue;
}

async function gradeOne(a: AnswerSpec, text: string): Promise<Graded> {
  try {
    if (a.kind === 'number') {
      const p = await parseNumberAnswer(text);
      if (!p.ok) return { verdict: { value: 'invalid', message: p.error } };
      return { verdict: classifyTyped(a, p), own: p.value };
    }
    if (a.kind === 'formula') {
      const raw = text.trim();
      const src = normaliseInput(raw);
      const r = await compileExpression(src, a.variables);
      if (!r.ok) return { verdict: { value: 'invalid', message: `Cannot read that formula: ${r.message}.` } };
      return { verdict: await classifyTypedFormula(a, src, r.fn), own: r.fn };
    }
    const verdict = checkChoice(a, text);
    return {
      verdict,
      ...(verdict.value === 'invalid' ? {} : { own: text.trim().toLowerCase().replace(/\s+/g, '-') }),
    };
  } catch (e) {
    return {
      verdict: {
        value: 'invalid',
        message: `That answer could not be read (${e instanceof Error ? e.message : String(e)}).`,
      },
    };
  }
}

const CONVENTION_NAMES: Record<string, string> = {
  'v-flip': 'v′ = 1 − v (v = 0 on the top row)',
  standard: 'v = 0 on the bottom row (the exam’s convention)',
};

/**
 * The convention an answer's verdict shows, when the answer depends on one: its family (the
 * alternative's id, e.g. 'v-flip') and the one used ('standard' or the family). Else null.
 */
function conventionOf(a: AnswerSpec, v: Verdict): { family: string; used: string } | null {
  if (v.value !== 'correct') return null;
  if (v.convention) return { family: v.convention, used: v.convention };
  const alts = a.kind === 'number' || a.kind === 'formula' ? a.alternatives : [];
  const family = alts.find((x) => x.convention)?.convention;
  return family ? { family, used: 'standard' } : null;
}

/** Whether an answer counts as wrong for follow-through (readable, not right). */
function isWrong(v: Verdict): boolean {
  return v.value !== 'correct' && v.value !== 'invalid';
}

/**
 * The verdict of every answer typed (blank ones are left out), with conventions checked across the
 * variant and follow-through from the student's own earlier answers. Never throws.
 */
export async function gradeAnswers(
  v: Variant,
  texts: Readonly<Record<string, string>>,
): Promise<Record<string, Verdict>> {
  const answers = allAnswers(v);
  const graded: Record<string, Graded> = {};
  for (const a of answers) {
    const t = texts[a.name] ?? '';
    if (t.trim() === '') continue;
    graded[a.name] = await gradeOne(a, t);
  }
  // conventions: the first answer (in order) that depends on one sets it for the variant
  const first = new Map<string, { label: string; used: string }>();
  for (const a of answers) {
    const g = graded[a.name];
    const c = g ? conventionOf(a, g.verdict) : null;
    if (!g || !c) continue;
    const f = first.get(c.family);
    if (!f) {
      first.set(c.family, { label: a.label, used: c.used });
      continue;
    }
    if (f.used === c.used) continue;
    const name = (u: string) => CONVENTION_NAMES[u] ?? u;
    g.verdict = {
      value: 'mistake:mixed-convention',
      message: `Mixed conventions: your ${f.label} reads the grid with ${name(f.used)}, this answer with ${name(c.used)}. The key accepts either, used throughout: redo this one in the convention of your ${f.label}.`,
    };
  }
  // follow-through, in order (a consistent answer is itself wrong for the answers after it)
  const own: Record<string, OwnValue> = {};
  for (const [k, g] of Object.entries(graded)) if (g.own !== undefined) own[k] = g.own;
  for (const a of answers) {
    const g = graded[a.name];
    if (!g || g.own === undefined || !a.follow?.length) continue;
    if (g.verdict.value === 'correct' || g.verdict.value === 'invalid') continue;
    for (const rule of a.follow) {
      if (!rule.from.every((n) => n in own)) continue;
      const wrongFrom = rule.from.filter((n) => graded[n] && isWrong(graded[n].verdict));
      if (!wrongFrom.length) continue;
      let ok = false;
      try {
        ok = rule.matches(own, g.own);
      } catch {
        ok = false;
      }
      if (!ok) continue;
      const labels = wrongFrom.map((n) => answers.find((x) => x.name === n)!.label);
      const list = labels.length === 1 ? labels[0] : `${labels.slice(0, -1).join(', ')} and ${labels.at(-1)}`;
      g.verdict = {
        value: 'consistent',
        message: `Consistent with your ${list}, which ${labels.length === 1 ? 'was' : 'were'} wrong: this step is right for ${labels.length === 1 ? 'it' : 'them'} (follow-through, half marks). Fix the earlier answer first.`,
        from: wrongFrom,
      };
      break;
    }
  }
  const out: Record<string, Verdict> = {};
  for (const [k, g] of Object.entries(graded)) out[k] = g.verdict;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Attempts and marks

/** The mark an answer's verdict earns after `wrongBefore` wrong attempts at its part. */
export function creditFor(v: Verdict, wrongBefore: number, revealed: boolean): number {
  if (revealed) return 0;
  const base = v.value === 'correct' ? 1 : v.value === 'consistent' ? SCORING.followCredit : 0;
  return Math.max(0, base * (1 - SCORING.penalty * wrongBefore));
}

/**
 * The session after a Check of `texts` whose verdicts are `verdicts` (from {@link gradeAnswers}).
 * A part's attempt is counted when one of its answers changed since it was last counted and is
 * readable; it is wrong when one of those is not right.
 */
export function applyCheck(
  v: Variant,
  s: Session,
  texts: Readonly<Record<string, string>>,
  verdicts: Readonly<Record<string, Verdict>>,
): Session {
  const parts = { ...s.parts };
  const answers = { ...s.answers };
  for (const p of v.parts) {
    const st = { ...parts[p.id] };
    const changed = p.answers.filter((a) => {
      const t = (texts[a.name] ?? '').trim();
      const vd = verdicts[a.name];
      return t !== '' && vd && vd.value !== 'invalid' && t !== answers[a.name].counted;
    });
    const wrongBefore = st.wrong;
    const revealedBefore = st.revealed !== null;
    if (changed.length) {
      st.attempts += 1;
      if (changed.some((a) => verdicts[a.name].value !== 'correct')) st.wrong += 1;
    }
    for (const a of p.answers) {
      const t = (texts[a.name] ?? '').trim();
      const prev = answers[a.name];
      const vd = t === '' ? null : (verdicts[a.name] ?? null);
      const isChanged = changed.includes(a);
      const last = isChanged && vd ? creditFor(vd, wrongBefore, revealedBefore) : vd ? prev.last : 0;
      answers[a.name] = {
        verdict: vd,
        counted: isChanged ? t : prev.counted,
        last,
        best: Math.max(prev.best, last),
      };
    }
    if (st.revealed === null && st.wrong >= SCORING.revealAfter) st.revealed = 'attempts';
    parts[p.id] = st;
  }
  return { parts, answers };
}

export function showHint(s: Session, partId: string): Session {
  return { ...s, parts: { ...s.parts, [partId]: { ...s.parts[partId], hint: true } } };
}

export function revealPart(s: Session, partId: string): Session {
  const p = s.parts[partId];
  if (p.revealed) return s;
  return { ...s, parts: { ...s.parts, [partId]: { ...p, revealed: 'asked' } } };
}

/** Marks earned (best per answer) out of the number of answers. */
export function sessionScore(v: Variant, s: Session): { marks: number; total: number } {
  const all = allAnswers(v);
  return { marks: all.reduce((m, a) => m + s.answers[a.name].best, 0), total: all.length };
}

/** Whether every answer of a part is correct (its latest verdicts). */
export function partDone(p: Part, s: Session): boolean {
  return p.answers.every((a) => s.answers[a.name].verdict?.value === 'correct');
}

/** The answers that earn nothing in a check from `s`: those of parts whose answer was shown. */
export function forfeitedAnswers(v: Variant, s: Session): string[] {
  return v.parts.filter((p) => s.parts[p.id].revealed !== null).flatMap((p) => p.answers.map((a) => a.name));
}
