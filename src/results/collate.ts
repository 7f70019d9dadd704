/**
 * Collating a class's results files (pure, no DOM): every attempt is regraded from its seed and
 * typed answers with the practice checker (src/lms/grade.ts), so a verdict edited in a file cannot
 * raise a score. Per question: attempts, students, the mean of each student's best score, and how
 * often each named mistake occurs (in regraded verdicts, over all attempts). Per student: the best
 * score of each question. Disagreements between a file's verdicts and the regraded ones are counted.
 */
import { QUESTION_IDS, type QuestionId } from '../practice/model';
import { gradeAttempt, mistakeOf } from '../lms/grade';
import { parseResultsFile, type Attempt } from './format';
import { csvText } from './csv';

export interface InputFile {
  name: string;
  text: string;
}

export interface StudentRow {
  student: string;
  file: string;
  /** Best fraction correct (0–1) per question attempted. */
  best: Partial<Record<QuestionId, { score: number; max: number; attempts: number }>>;
  attempts: number;
}

export interface QuestionStats {
  question: QuestionId;
  attempts: number;
  students: number;
  /** Mean over students of their best fraction correct. */
  meanBest: number;
  /** Checked answers (non-blank) and how many were correct. */
  answers: number;
  correct: number;
  /** Named mistake id → occurrences. */
  mistakes: Record<string, number>;
  /** Answers the file said were correct that regrade otherwise (an edited or stale verdict). */
  disagreements: number;
}

export interface Collation {
  files: number;
  attempts: number;
  students: StudentRow[];
  questions: QuestionStats[];
  problems: string[];
}

/** Long enough to do work, short enough for the page to answer input at once. */
const SLICE_MS = 12;

/** A student's key across files: their name, else the file's. */
function studentKey(student: string): string {
  return student.normalize('NFC').trim().replace(/\s+/g, ' ').toLowerCase();
}

function attemptKey(a: Attempt): string {
  return JSON.stringify([a.question, a.seed, a.time, a.answers]);
}

/**
 * Collate the files. Works in slices that yield to the page (whatever a file holds: a crafted one
 * whose every attempt is slow to grade included), reporting each file as it starts; `signal`
 * cancels. A student in several files (by name), and an attempt in several files, count once.
 */
export async function collate(
  files: readonly InputFile[],
  onProgress?: (done: number, current?: string) => void,
  signal?: AbortSignal,
): Promise<Collation> {
  const problems: string[] = [];
  const rows = new Map<string, StudentRow>();
  const seen = new Set<string>();
  let attempts = 0;
  let done = 0;
  let sliceStart = performance.now();
  const yieldNow = async () => {
    if (signal?.aborted) throw new DOMException('The collation was cancelled.', 'AbortError');
    if (performance.now() - sliceStart < SLICE_MS) return;
    await new Promise((r) => setTimeout(r, 0));
    sliceStart = performance.now();
    if (signal?.aborted) throw new DOMException('The collation was cancelled.', 'AbortError');
  };
  const stats = new Map<QuestionId, QuestionStats>();
  for (const q of QUESTION_IDS)
    stats.set(q, {
      question: q,
      attempts: 0,
      students: 0,
      meanBest: 0,
      answers: 0,
      correct: 0,
      mistakes: {},
      disagreements: 0,
    });
  for (const f of files) {
    onProgress?.(done, f.name);
    await yieldNow();
    const p = parseResultsFile(f.text);
    done++;
    if (!p.ok) {
      problems.push(`${f.name}: ${p.error}; left out.`);
      onProgress?.(done);
      continue;
    }
    if (p.skipped)
      problems.push(`${f.name}: ${p.skipped} attempt(s) that name no question 1–6 or seed were left out.`);
    const student = p.file.student || f.name.replace(/\.json$/i, '');
    const key = studentKey(student);
    let row = rows.get(key);
    if (!row) {
      row = { student, file: f.name, best: {}, attempts: 0 };
      rows.set(key, row);
    } else if (!row.file.split(', ').includes(f.name)) row.file += `, ${f.name}`;
    for (const a of p.file.attempts) {
      const id = `${key}\u0000${attemptKey(a)}`;
      if (seen.has(id)) continue;
      seen.add(id);
      const g = await gradeAttempt(a.question, a.seed, a.answers);
      const s = stats.get(a.question)!;
      s.attempts++;
      attempts++;
      row.attempts++;
      for (const x of g.answers) {
        if (x.verdict === 'blank') continue;
        s.answers++;
        if (x.verdict === 'correct') s.correct++;
        const m = mistakeOf(x.verdict);
        if (m) s.mistakes[m] = (s.mistakes[m] ?? 0) + 1;
        if (a.verdicts[x.name] === 'correct' && x.verdict !== 'correct') s.disagreements++;
      }
      // an answer shown on the page before this check earns nothing, as it did there
      const forfeited = new Set(a.forfeited ?? []);
      const score = g.answers.filter((x) => x.verdict === 'correct' && !forfeited.has(x.name)).length;
      const prev = row.best[a.question];
      const frac = g.max ? score / g.max : 0;
      if (!prev || frac > prev.score / prev.max)
        row.best[a.question] = { score, max: g.max, attempts: (prev?.attempts ?? 0) + 1 };
      else prev.attempts++;
      await yieldNow();
    }
    onProgress?.(done);
  }
  const students = [...rows.values()];
  const questions = [...stats.values()].map((s) => {
    const bests = students.map((r) => r.best[s.question]).filter((b) => b !== undefined);
    const sum = bests.reduce((t, b) => t + (b.max ? b.score / b.max : 0), 0);
    return { ...s, students: bests.length, meanBest: bests.length ? sum / bests.length : 0 };
  });
  return { files: files.length, attempts, students, questions, problems };
}

/** One row per student: name, file, attempts, then each question's best score and max. */
export function studentsCsv(c: Collation): string {
  const head: (string | number)[] = [
    'student',
    'file',
    'attempts',
    ...QUESTION_IDS.flatMap((q) => [`${q} score`, `${q} max`]),
  ];
  const rows = c.students.map((s): (string | number)[] => [
    s.student,
    s.file,
    s.attempts,
    ...QUESTION_IDS.flatMap((q): (string | number)[] => {
      const b = s.best[q];
      return b ? [b.score, b.max] : ['', ''];
    }),
  ]);
  return csvText([head, ...rows]);
}
