/**
 * Collating a class's results files (pure, no DOM): every attempt is regraded from its seed and
 * typed answers with the practice checker (src/lms/grade.ts), so a verdict edited in a file cannot
 * raise a score. Per question: attempts, students, the mean of each student's best score, and how
 * often each named mistake occurs (in regraded verdicts, over all attempts). Per student: the best
 * score of each question. Disagreements between a file's verdicts and the regraded ones are counted.
 */
import { QUESTION_IDS, type QuestionId } from '../practice/model';
import { gradeAttempt, mistakeOf, type GradedAttempt } from '../lms/grade';
import { parseResultsFile, type Attempt } from './format';

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

/** A student's key across files: their name, else the file's. */
function studentKey(student: string): string {
  return student.normalize('NFC').trim().replace(/\s+/g, ' ').toLowerCase();
}

function attemptKey(a: Attempt): string {
  return JSON.stringify([a.question, a.seed, a.time, a.answers]);
}

/** Progress of a collation: files done, and the file being checked (absent between files). */
export type CollateProgress = (done: number, current?: string) => void;

/**
 * Collate the files (in the results page's worker: ./results.worker.ts; a crafted file whose
 * every attempt is slow to grade then holds up no page). `onProgress` hears of each file as it
 * starts and ends. A student in several files (by name), and an attempt in several files, count
 * once. A file that cannot be read, or whose grading fails, is named in `problems` and left out.
 */
export async function collate(files: readonly InputFile[], onProgress?: CollateProgress): Promise<Collation> {
  const problems: string[] = [];
  const rows = new Map<string, StudentRow>();
  const seen = new Set<string>();
  let attempts = 0;
  let done = 0;
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
    // the file's new attempts are graded first, and counted only when all of them could be
    const fresh: Attempt[] = [];
    const ids = new Set<string>();
    for (const a of p.file.attempts) {
      const id = `${key}\u0000${attemptKey(a)}`;
      if (seen.has(id) || ids.has(id)) continue;
      ids.add(id);
      fresh.push(a);
    }
    let graded: GradedAttempt[];
    try {
      graded = [];
      for (const a of fresh) graded.push(await gradeAttempt(a.question, a.seed, a.answers));
    } catch (e) {
      problems.push(
        `${f.name}: could not be checked (${e instanceof Error ? e.message : String(e)}); left out.`,
      );
      onProgress?.(done);
      continue;
    }
    for (const id of ids) seen.add(id);
    let row = rows.get(key);
    if (!row) {
      row = { student, file: f.name, best: {}, attempts: 0 };
      rows.set(key, row);
    } else if (!row.file.split(', ').includes(f.name)) row.file += `, ${f.name}`;
    fresh.forEach((a, i) => {
      const g = graded[i];
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
    });
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
