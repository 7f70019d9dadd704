/**
 * `#/results` (its own lazy chunk): an instructor drops or picks the class's results files; every
 * verdict is recomputed from the seeds and typed answers (./collate.ts, in a worker: ./jobs.ts,
 * with progress and Cancel; files dropped meanwhile wait their turn), then the page shows per
 * question the scores and how often each named mistake occurs (a bar chart and a table), a table
 * per student, and CSV exports. Everything happens in the page: no file or result is sent anywhere.
 */
import { useEffect, useRef, useState, type DragEvent } from 'react';
import { questionMeta } from '../practice/questionList';
import { QUESTION_IDS } from '../practice/model';
import type { Collation, InputFile, QuestionStats } from './collate';
import { CollationFailed, ResultsChecker } from './jobs';
import { isCancelled } from '../workers/run';
import { downloadFile } from '../ui/download';
import { ScrollBox } from '../ui/ScrollBox';
import { afterPaint } from '../ui/afterPaint';
import { csvText, studentsCsv } from './csv';
import { addBatch } from './batches';
import './results.css';

const MAX_FILES = 2000;
const MAX_BYTES = 2_000_000;

function pct(x: number): string {
  return `${Math.round(x * 1000) / 10} %`;
}

function mistakesCsv(c: Collation): string {
  const rows = [['question', 'mistake', 'count']];
  for (const q of c.questions)
    for (const [m, n] of Object.entries(q.mistakes).sort((a, b) => b[1] - a[1]))
      rows.push([q.question, m, String(n)]);
  return csvText(rows);
}

export default function ResultsRoute() {
  const [ready, setReady] = useState(false);
  const [busy, setBusy] = useState<{ done: number; total: number; file?: string; waiting: number } | null>(
    null,
  );
  // every batch of files adds to the class (a second drop does not replace the first); files
  // dropped while a batch is being checked wait for it
  const classFiles = useRef<InputFile[]>([]);
  const waiting = useRef<File[]>([]);
  const running = useRef<AbortController | null>(null);
  const [result, setResult] = useState<Collation | null>(null);
  const [problems, setProblems] = useState<string[]>([]);
  const [over, setOver] = useState(false);
  const checker = useRef<ResultsChecker | null>(null);
  useEffect(() => {
    document.title = 'Class results — Render Math Lab';
    // the worker loads the answer checker once the page is painted (its download would otherwise
    // hold up the first paint on a slow connection), so collating needs no request later
    const c = new ResultsChecker();
    checker.current = c;
    let live = true;
    void afterPaint().then(() => {
      if (!live) return;
      c.warm().then(
        () => setReady(true),
        (e: unknown) =>
          // (a page closed before the checker was ready ended its worker: nothing to say)
          isCancelled(e) ||
          setProblems(['The answer checker could not be loaded; reload the page while online once.']),
      );
    });
    return () => {
      live = false;
      c.dispose();
    };
  }, []);

  const take = async (list: FileList | File[] | null) => {
    waiting.current.push(...(list ?? []));
    if (running.current) {
      setBusy((b) => (b ? { ...b, waiting: waiting.current.length } : b));
      return;
    }
    while (waiting.current.length) {
      const next = waiting.current.splice(0);
      const ctl = new AbortController();
      running.current = ctl;
      try {
        await takeBatch(next, ctl.signal);
      } catch (e) {
        const said =
          e instanceof CollationFailed
            ? `${e.message} The results shown are from before this batch.`
            : 'Checking was cancelled: the results shown are from before it.';
        setProblems((p) => [said, ...p]);
        waiting.current = [];
      }
      running.current = null;
    }
    setBusy(null);
  };

  const takeBatch = async (all: File[], signal: AbortSignal) => {
    if (!all.length) return;
    const notes: string[] = [];
    const files = all.slice(0, MAX_FILES);
    if (all.length > MAX_FILES) notes.push(`Only the first ${MAX_FILES} files were read.`);
    setBusy({ done: 0, total: files.length, waiting: 0 });
    const inputs: InputFile[] = [];
    for (const f of files) {
      if (f.size > MAX_BYTES) {
        notes.push(`${f.name}: larger than 2 MB, not a results file; left out.`);
        continue;
      }
      try {
        inputs.push({ name: f.name, text: await f.text() });
      } catch {
        notes.push(`${f.name}: could not be read; left out.`);
      }
    }
    const merged = addBatch(classFiles.current, inputs);
    const c = await checker.current!.collate(
      merged,
      ({ done, current }) =>
        setBusy({ done, total: merged.length, file: current, waiting: waiting.current.length }),
      signal,
    );
    classFiles.current = merged;
    setResult(c);
    setProblems([...notes, ...c.problems]);
  };

  const onDrop = (e: DragEvent) => {
    e.preventDefault();
    setOver(false);
    void take(e.dataTransfer.files);
  };

  return (
    <main id="main" className="page results-page" tabIndex={-1} data-ready={ready ? '1' : '0'}>
      <div className="scene-header">
        <h1>Class results</h1>
        <a className="back-link" href="#/practice">
          ← Practice
        </a>
      </div>
      <p className="lead">
        Each student presses <strong>Download my results</strong> on a practice page and hands in the file.
        Drop all the files here: every answer is checked again from its seed and the typed text (so an edited
        verdict changes nothing), and the page shows the scores and the mistakes the class makes. The files
        never leave this page.
      </p>
      <div
        className={`drop-zone${over ? ' is-over' : ''}`}
        onDragOver={(e) => {
          e.preventDefault();
          setOver(true);
        }}
        onDragLeave={() => setOver(false)}
        onDrop={onDrop}
        data-testid="results-drop"
      >
        <p>Drop results files here, or</p>
        <label className="file-pick">
          choose files{' '}
          <input
            type="file"
            multiple
            accept=".json,application/json"
            data-testid="results-files"
            disabled={!ready || busy !== null}
            onChange={(e) => {
              void take(e.target.files);
              e.target.value = '';
            }}
          />
        </label>
      </div>
      <p role="status" data-testid="results-status">
        {!ready
          ? 'Loading the answer checker…'
          : busy
            ? `Checking ${busy.done} of ${busy.total} files${busy.file ? ` (${busy.file.slice(0, 80)})` : ''}…${busy.waiting ? ` ${busy.waiting} more waiting.` : ''}`
            : result
              ? `${result.files} file${result.files === 1 ? '' : 's'}, ${result.students.length} student${result.students.length === 1 ? '' : 's'}, ${result.attempts} checked attempt${result.attempts === 1 ? '' : 's'}.`
              : 'No files yet.'}
      </p>
      {busy ? (
        <button type="button" data-testid="results-cancel" onClick={() => running.current?.abort()}>
          Cancel
        </button>
      ) : null}
      {problems.length ? (
        <div className="notice notice-warn" data-testid="results-problems">
          <ul>
            {problems.slice(0, 50).map((p, i) => (
              <li key={i}>{p}</li>
            ))}
          </ul>
          {problems.length > 50 ? <p>…and {problems.length - 50} more.</p> : null}
        </div>
      ) : null}
      {result ? <Report c={result} /> : null}
    </main>
  );
}

function Report({ c }: { c: Collation }) {
  const qs = c.questions.filter((q) => q.attempts > 0);
  return (
    <div
      data-testid="results-report"
      data-files={c.files}
      data-attempts={c.attempts}
      data-students={c.students.length}
    >
      <p>
        <button
          type="button"
          onClick={() => downloadFile('class-results.csv', studentsCsv(c), 'text/csv')}
          data-testid="export-csv"
        >
          Export students (CSV)
        </button>{' '}
        <button
          type="button"
          onClick={() => downloadFile('class-mistakes.csv', mistakesCsv(c), 'text/csv')}
          data-testid="export-mistakes-csv"
        >
          Export mistakes (CSV)
        </button>
      </p>
      {qs.map((q) => (
        <QuestionBlock key={q.question} q={q} />
      ))}
      <section className="results-panel" aria-labelledby="students-title">
        <h2 id="students-title">Students</h2>
        {/* wider than a phone: it scrolls in its own box, which the keyboard can reach */}
        <ScrollBox label="Students, best score per question">
          <table className="results-table" data-testid="students-table">
            <thead>
              <tr>
                <th scope="col">Student</th>
                <th scope="col">Attempts</th>
                {QUESTION_IDS.map((q) => (
                  <th key={q} scope="col">
                    Q{questionMeta(q).n}
                  </th>
                ))}
              </tr>
            </thead>
            <tbody>
              {c.students.map((s, i) => (
                <tr key={`${s.file}-${i}`} data-testid="student-row">
                  <th scope="row" title={s.file}>
                    {s.student}
                  </th>
                  <td>{s.attempts}</td>
                  {QUESTION_IDS.map((q) => {
                    const b = s.best[q];
                    return (
                      <td
                        key={q}
                        data-testid={`student-${i}-${q}`}
                        data-value={b ? `${b.score}/${b.max}` : ''}
                      >
                        {b ? `${b.score}/${b.max}` : '—'}
                      </td>
                    );
                  })}
                </tr>
              ))}
            </tbody>
          </table>
        </ScrollBox>
      </section>
    </div>
  );
}

function QuestionBlock({ q }: { q: QuestionStats }) {
  const info = questionMeta(q.question);
  const mistakes = Object.entries(q.mistakes).sort((a, b) => b[1] - a[1] || (a[0] < b[0] ? -1 : 1));
  return (
    <section
      className="results-panel"
      aria-labelledby={`rq-${q.question}`}
      data-testid={`results-${q.question}`}
    >
      <h2 id={`rq-${q.question}`}>
        Q{info.n} {info.title}
      </h2>
      <p>
        <span data-testid={`attempts-${q.question}`} data-value={q.attempts}>
          {q.attempts} attempt{q.attempts === 1 ? '' : 's'}
        </span>{' '}
        by {q.students} student{q.students === 1 ? '' : 's'}; mean best score{' '}
        <strong data-testid={`mean-${q.question}`} data-value={q.meanBest}>
          {pct(q.meanBest)}
        </strong>
        ; {q.correct} of {q.answers} answers correct.
        {q.disagreements ? (
          <span className="notice-inline" data-testid={`disagree-${q.question}`} data-value={q.disagreements}>
            {' '}
            {q.disagreements} answer{q.disagreements === 1 ? '' : 's'} marked correct in a file did not check
            as correct (edited or from an older checker); the recomputed verdict counts.
          </span>
        ) : null}
      </p>
      {mistakes.length ? (
        <>
          <MistakeChart mistakes={mistakes} label={`Named mistakes in Q${info.n}`} />
          <table className="results-table">
            <caption className="sr-only">Named mistakes in Q{info.n} and how often they occur</caption>
            <thead>
              <tr>
                <th scope="col">Named mistake</th>
                <th scope="col">Occurrences</th>
              </tr>
            </thead>
            <tbody>
              {mistakes.map(([m, n]) => (
                <tr key={m}>
                  <th scope="row">
                    <code>{m}</code>
                  </th>
                  <td data-testid={`mistake-${q.question}-${m}`} data-value={n}>
                    {n}
                  </td>
                </tr>
              ))}
            </tbody>
          </table>
        </>
      ) : (
        <p className="muted">No named mistakes.</p>
      )}
    </section>
  );
}

/** A horizontal bar chart of mistake counts (plain SVG; the table beside it has the numbers). */
function MistakeChart({ mistakes, label }: { mistakes: [string, number][]; label: string }) {
  const rowH = 24;
  const labelW = 190;
  const barW = 380;
  const max = Math.max(1, ...mistakes.map(([, n]) => n));
  const h = mistakes.length * rowH + 8;
  return (
    <svg
      className="mistake-chart"
      viewBox={`0 0 ${labelW + barW + 50} ${h}`}
      width="100%"
      style={{ maxWidth: `${labelW + barW + 50}px` }}
      role="img"
      aria-label={`${label}: ${mistakes.map(([m, n]) => `${m} ${n}`).join(', ')}`}
    >
      {mistakes.map(([m, n], i) => {
        const y = 4 + i * rowH;
        const w = Math.max(2, (n / max) * barW);
        return (
          <g key={m}>
            <text x={labelW - 6} y={y + rowH / 2 + 4} textAnchor="end" className="chart-label">
              {m.length > 28 ? `${m.slice(0, 27)}…` : m}
            </text>
            <rect x={labelW} y={y + 3} width={w} height={rowH - 6} className="chart-bar" rx={2} />
            <text x={labelW + w + 6} y={y + rowH / 2 + 4} className="chart-value">
              {n}
            </text>
          </g>
        );
      })}
    </svg>
  );
}
