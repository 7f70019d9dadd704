/**
 * Practice mode (its own lazy chunk): `#/practice` (the six questions with the student's progress),
 * `#/practice/q1` … `#/practice/q6` with `seed` (one variant: givens, answer fields, "Check",
 * mistake-aware verdicts, the worked solution and a link to the scene), and the printable worksheet
 * `#/practice/sheet?seed=…&q=1,3,5&count=…`.
 *
 * Contract (README): givens `data-testid="given-NAME"` with full-precision `data-value`; inputs
 * `answer-NAME`; verdicts `verdict-NAME` with `data-value` correct | incorrect | mistake:<id> |
 * invalid; expected answers `expected-NAME` once shown. Every verdict is also announced to the page
 * as `rml:practice-verdict` (a CustomEvent on window) for the host-page API.
 */
import { Superscripted } from '../ui/Superscripted';
import { useCallback, useEffect, useMemo, useState, type FormEvent } from 'react';
import { MathTex } from '../ui/MathTex';
import { IntInput } from '../ui/IntInput';
import { queryProblems, shellExtras, type ShellFlags } from '../kit/shell';
import { expectedText, FORMULA_POLICY, NUMERIC_POLICY } from './check';
import {
  allAnswers,
  fmt,
  QUESTION_IDS,
  type AnswerSpec,
  type Given,
  type Part,
  type QuestionId,
  type Variant,
} from './model';
import {
  applyCheck,
  forfeitedAnswers,
  gradeAnswers,
  partDone,
  revealPart,
  SCORING,
  sessionScore,
  showHint,
  type AnswerProgress,
  type PartProgress,
  type Session,
} from './session';
import { loadScores, recordScore, type Scores } from './scores';
import { QUESTIONS, isQuestionId, questionInfo } from './questions';
import { loadProgress, recordCheck, type Progress } from './progress';
import { extensionCheck, extensionInput, extensionRestore, extensionSeed, practiceSlot } from './extensions';
import { openingAnswers, saveDraft } from './drafts';
import { loadSession, saveSession, withStored } from './sessionStore';
import { resetPractice } from './reset';
import { RouteNotice } from '../ui/RouteNotice';
import { ParamNotice, TextList } from './ParamNotice';
import Sheet from './Sheet';
import { SolutionSteps } from './SolutionSteps';
import './practice.css';

interface Props {
  path: string;
  query: string;
  flags: ShellFlags;
}

const MAX_SEED = 0xffffffff;

function randomSeed(): number {
  const a = new Uint32Array(1);
  crypto.getRandomValues(a);
  return a[0] % 100000; // short numbers read well in a link ("variant 17")
}

function extras(flags: ShellFlags): string {
  const e = shellExtras(flags);
  return Object.entries(e)
    .filter(([, v]) => v !== undefined)
    .map(([k, v]) => `&${k}=${v}`)
    .join('');
}

/** Parse a seed parameter: an integer in [0, 2³² − 1], else null with a message. */
function parseSeed(raw: string | null): { seed: number | null; problem: string | null } {
  if (raw === null) return { seed: null, problem: null };
  const s = raw.trim();
  if (/^\d{1,10}$/.test(s) && Number(s) <= MAX_SEED) return { seed: Number(s), problem: null };
  return {
    seed: null,
    problem: `seed ${JSON.stringify(s.slice(0, 24))} is not a whole number from 0 to ${MAX_SEED}; a new variant was drawn instead.`,
  };
}

export default function PracticeRoute({ path, query, flags }: Props) {
  const sp = useMemo(() => new URLSearchParams(query), [query]);
  const sub = path.slice('/practice'.length).replace(/^\//, '');
  if (sub === '') return <PracticeHome flags={flags} query={query} />;
  if (sub === 'sheet') return <Sheet sp={sp} flags={flags} />;
  if (isQuestionId(sub)) return <QuestionRoute key={sub} q={sub} sp={sp} flags={flags} />;
  return (
    <main id="main" className="page practice" tabIndex={-1}>
      <h1>Page not found</h1>
      <p role="status">
        There is no practice page <code>{sub.slice(0, 40)}</code>.{' '}
        <a href="#/practice">See the practice questions</a>.
      </p>
    </main>
  );
}

// ---------------------------------------------------------------------------------------------
// #/practice

function PracticeHome({ flags, query }: { flags: ShellFlags; query: string }) {
  const [progress, setProgress] = useState<Progress>(() => loadProgress());
  const [scores, setScores] = useState<Scores>(() => loadScores());
  const [status, setStatus] = useState('');
  const [sheetQs, setSheetQs] = useState<Record<QuestionId, boolean>>(
    () => Object.fromEntries(QUESTION_IDS.map((q) => [q, true])) as Record<QuestionId, boolean>,
  );
  const [count, setCount] = useState(1);
  const [withSolutions, setWithSolutions] = useState(false);
  const [sheetSeedText, setSheetSeedText] = useState('1');
  useEffect(() => {
    document.title = 'Practice — Render Math Lab';
  }, []);
  const chosen = QUESTION_IDS.filter((q) => sheetQs[q]).map((q) => q.slice(1));
  const seedOk = /^\d{1,10}$/.test(sheetSeedText.trim()) && Number(sheetSeedText) <= MAX_SEED;
  const sheetHref = `#/practice/sheet?seed=${seedOk ? Number(sheetSeedText) : 1}&q=${chosen.join(',') || '1'}&count=${count}${withSolutions ? '&solutions=1' : ''}${extras(flags)}`;
  return (
    <main id="main" className="page practice practice-home" tabIndex={-1}>
      <div className="scene-header">
        <h1>Practice: new variants of every exam question</h1>
        <a className="back-link" href={flags.present ? '#/?present=1' : '#/'}>
          ← All scenes
        </a>
      </div>
      <RouteNotice flags={flags} query={query} />
      <p className="lead">
        Each question draws fresh numbers from a seed, checks your answers the way the key grades them, names
        the classic mistakes, and then shows the worked solution of your variant. The same seed always gives
        the same variant, so a link like <code>#/practice/q3?seed=17</code> is “variant 17” for everyone.
      </p>
      <ol className="question-list practice-list">
        {QUESTIONS.map((q) => {
          const p = progress[q.id];
          return (
            <li key={q.id} className="question-card">
              <div className="question-head">
                <span className="question-number">Q{q.n}</span>
                <h2>
                  <a href={`#/practice/${q.id}?seed=${randomSeed()}${extras(flags)}`}>{q.title}</a>
                </h2>
              </div>
              <p>{q.blurb}</p>
              <p
                className="practice-progress"
                data-testid={`progress-${q.id}`}
                data-attempted={p.attempted.length}
                data-correct={p.correct.length}
              >
                {p.attempted.length === 0
                  ? 'Not tried yet.'
                  : `${p.attempted.length} variant${p.attempted.length === 1 ? '' : 's'} tried, ${p.correct.length} fully correct.`}
              </p>
              <BestScores q={q.id} scores={scores} flags={flags} />
            </li>
          );
        })}
      </ol>
      <p>
        <button
          type="button"
          data-testid="reset-progress"
          onClick={() => {
            setProgress(resetPractice());
            setScores(loadScores());
            setStatus('Progress cleared.');
          }}
        >
          Reset progress
        </button>{' '}
        <span role="status">{status}</span>{' '}
        <span className="muted">Progress is kept in this browser only.</span>
      </p>
      <Slot name="home-footer" />
      <section className="panel sheet-builder" aria-labelledby="sheet-title">
        <h2 id="sheet-title">Worksheet for a class (printable)</h2>
        <fieldset>
          <legend>Questions</legend>
          {QUESTIONS.map((q) => (
            <label key={q.id} className="check-label">
              <input
                type="checkbox"
                checked={sheetQs[q.id]}
                onChange={(e) => setSheetQs({ ...sheetQs, [q.id]: e.target.checked })}
              />{' '}
              Q{q.n}
            </label>
          ))}
        </fieldset>
        <label>
          Variants of each <IntInput min={1} max={10} value={count} fallback={1} onChange={setCount} />
        </label>{' '}
        <label>
          Seed{' '}
          <input
            type="text"
            inputMode="numeric"
            value={sheetSeedText}
            onChange={(e) => setSheetSeedText(e.target.value)}
            aria-invalid={!seedOk}
            size={10}
          />
        </label>{' '}
        <label className="check-label">
          <input
            type="checkbox"
            checked={withSolutions}
            onChange={(e) => setWithSolutions(e.target.checked)}
          />{' '}
          with worked solutions
        </label>{' '}
        <a href={sheetHref}>Open the worksheet</a>
        {!seedOk ? (
          <p className="notice notice-warn">
            The seed must be a whole number from 0 to {MAX_SEED}; the link uses 1.
          </p>
        ) : null}
      </section>
    </main>
  );
}

/** The best marks kept for a question's variants (the three best, linked). */
function BestScores({ q, scores, flags }: { q: QuestionId; scores: Scores; flags: ShellFlags }) {
  const list = Object.entries(scores[q]).sort((a, b) => b[1] - a[1]);
  if (!list.length) return null;
  return (
    <p className="practice-best muted" data-testid={`best-${q}`} data-count={list.length}>
      Best marks:{' '}
      {list.slice(0, 3).map(([seed, score], i) => (
        <span key={seed}>
          {i ? ', ' : ''}
          <a href={`#/practice/${q}?seed=${seed}${extras(flags)}`}>variant {seed}</a>{' '}
          {Math.round(score * 100)} %
        </span>
      ))}
      {list.length > 3 ? ` (and ${list.length - 3} more)` : ''}.
    </p>
  );
}

// ---------------------------------------------------------------------------------------------
// #/practice/qN

function QuestionRoute({ q, sp, flags }: { q: QuestionId; sp: URLSearchParams; flags: ShellFlags }) {
  const parsed = parseSeed(sp.get('seed'));
  const [fallback] = useState(() => randomSeed());
  // an extension (the LMS runtime in a package) fixes each learner's variant, whatever the link says
  const seed = extensionSeed(q) ?? parsed.seed ?? fallback;
  const problems = [
    ...flags.problems.map((p) => `${p.name} ${p.message}`),
    ...queryProblems(sp.toString(), ['seed']).map((p) => `${p.name} ${p.message}`),
    ...(parsed.problem ? [parsed.problem] : []),
  ];
  // a link without a (valid) seed gets one, so the page's URL names its variant
  useEffect(() => {
    if (parsed.seed !== null) return;
    try {
      const keep = new URLSearchParams(sp);
      keep.set('seed', String(seed));
      window.history.replaceState(window.history.state, '', `#/practice/${q}?${keep.toString()}`);
    } catch {
      /* sandboxed: the seed still lives in the page */
    }
  }, [parsed.seed, seed, q, sp]);
  const variant = useMemo(() => questionInfo(q).generate(seed), [q, seed]);
  return <QuestionPage key={`${q}-${seed}`} variant={variant} flags={flags} problems={problems} />;
}

function QuestionPage({
  variant,
  flags,
  problems,
}: {
  variant: Variant;
  flags: ShellFlags;
  problems: string[];
}) {
  const info = questionInfo(variant.question);
  // typed answers survive a reload of the tab (drafts.ts); else an extension (the LMS runtime in a
  // package) may hand back the learner's saved answers
  const [inputs, setInputs] = useState<Record<string, string>>(() =>
    openingAnswers(variant.question, variant.seed, () => extensionRestore(variant.question, variant.seed)),
  );
  useEffect(() => {
    saveDraft(variant.question, variant.seed, inputs);
    extensionInput(variant.question, variant.seed, inputs);
  }, [inputs, variant.question, variant.seed]);
  // attempts, shown answers and best marks survive reloads and other tabs (sessionStore.ts)
  const [session, setSession] = useState<Session>(() => loadSession(variant));
  useEffect(() => {
    saveSession(variant, session);
  }, [variant, session]);
  const [checking, setChecking] = useState(false);
  const [summary, setSummary] = useState('');
  useEffect(() => {
    document.title = `Practice Q${info.n} (variant ${variant.seed}) — Render Math Lab`;
  }, [info.n, variant.seed]);

  const check = useCallback(
    async (e?: FormEvent) => {
      e?.preventDefault();
      setChecking(true);
      const verdicts = await gradeAnswers(variant, inputs);
      const before = withStored(variant, session);
      const next = applyCheck(variant, before, inputs, verdicts);
      for (const p of variant.parts)
        for (const a of p.answers) {
          const v = verdicts[a.name];
          if (!v) continue;
          window.dispatchEvent(
            new CustomEvent('rml:practice-verdict', {
              detail: {
                question: variant.question,
                seed: variant.seed,
                name: a.name,
                verdict: v.value,
                part: p.id,
                attempt: next.parts[p.id].attempts,
                credit: next.answers[a.name].last,
              },
            }),
          );
        }
      setSession(next);
      setChecking(false);
      const answers = allAnswers(variant);
      const vals = Object.values(verdicts);
      if (vals.length === 0) {
        setSummary('Nothing to check yet: type an answer first.');
        return;
      }
      const nCorrect = answers.filter((a) => next.answers[a.name].verdict?.value === 'correct').length;
      const score = sessionScore(variant, next);
      setSummary(
        `${nCorrect} of ${answers.length} correct · ${fmtMarks(score.marks)} of ${score.total} marks (best kept).`,
      );
      recordCheck(variant.question, variant.seed, nCorrect === answers.length);
      recordScore(variant.question, variant.seed, score.marks / score.total);
      extensionCheck({
        question: variant.question,
        seed: variant.seed,
        answers: answers.map((a) => ({
          name: a.name,
          response: inputs[a.name] ?? '',
          verdict: verdicts[a.name]?.value ?? 'blank',
          message: verdicts[a.name]?.message ?? '',
        })),
        time: new Date().toISOString(),
        marks: { earned: score.marks, total: score.total },
        forfeited: forfeitedAnswers(variant, before),
      });
    },
    [variant, inputs, session],
  );

  const newVariant = () => {
    let s = randomSeed();
    if (s === variant.seed) s = (s + 1) % 100000;
    window.location.hash = `#/practice/${variant.question}?seed=${s}${extras(flags)}`;
  };
  const sceneHref = `${variant.sceneHref}${extras(flags)}`;
  const allShown = variant.parts.every((p) => session.parts[p.id].revealed || partDone(p, session));
  const next = nextSteps(variant, session);

  return (
    <main id="main" className={`page practice practice-question practice-${variant.question}`} tabIndex={-1}>
      <div className={flags.embed ? 'scene-header compact' : 'scene-header'}>
        <h1>
          <span className="question-tag">Practice Q{info.n}</span> {variant.title}
        </h1>
        {flags.embed ? (
          <a
            className="open-full"
            href={`${window.location.pathname}#/practice/${variant.question}?seed=${variant.seed}`}
            target="_blank"
            rel="noopener"
          >
            Open in Render Math Lab ↗
          </a>
        ) : (
          <a className="back-link" href={`#/practice${flags.present ? '?present=1' : ''}`}>
            ← All practice questions
          </a>
        )}
      </div>
      <ParamNotice problems={problems} heading />
      <div className="variant-bar">
        <span>
          Variant <strong data-testid="variant-seed">{variant.seed}</strong>
        </span>
        <button type="button" onClick={newVariant} data-testid="new-variant">
          New variant
        </button>
        <a href={sceneHref}>{variant.sceneLabel} ↗</a>
      </div>
      <section className="panel practice-statement" aria-labelledby="statement-title">
        <h2 id="statement-title">The question</h2>
        <p>
          <Superscripted text={variant.statement} />
        </p>
        <Givens givens={variant.givens} testIds />
      </section>
      <form className="panel practice-answers" onSubmit={check} noValidate aria-labelledby="answers-title">
        <h2 id="answers-title">Your answers</h2>
        <p className="muted practice-howto">
          Answer any part and press <strong>Check</strong>: only what you typed is graded. Each part has a
          hint and its own <strong>Show answer</strong>.
        </p>
        <details className="policy" data-testid="policy">
          <summary>How answers are checked and marked</summary>
          <p>{withCode(NUMERIC_POLICY.text)}</p>
          <p>{withCode(FORMULA_POLICY.text)}</p>
          <p>
            Classic mistakes the key deducts marks for are recognised and named. Where the key accepts another
            convention (the grid read with v′ = 1 − v in Q3), it is accepted and said so, as long as every
            answer of the variant uses the same one.
          </p>
          <p data-testid="scoring-policy">{SCORING.text}</p>
        </details>
        {variant.parts.map((part) => (
          <PartBlock
            key={part.id}
            part={part}
            progress={session.parts[part.id]}
            answers={session.answers}
            inputs={inputs}
            onInput={(name, t) => setInputs((s) => ({ ...s, [name]: t }))}
            onHint={() => setSession((s) => showHint(s, part.id))}
            onReveal={() => setSession((s) => revealPart(s, part.id))}
            stepsBelow={allShown}
          />
        ))}
        <div className="practice-actions">
          <button type="submit" className="primary" disabled={checking}>
            Check
          </button>
          <span role="status" className="practice-summary" data-testid="practice-summary">
            {checking ? 'Checking…' : summary}
          </span>
        </div>
        {next.length && !checking && summary ? (
          <div className="practice-next" data-testid="practice-next">
            <strong>What next:</strong>
            <TextList items={next} />
          </div>
        ) : null}
        <p className="practice-giveup">
          <button
            type="button"
            onClick={() => setSession((s) => variant.parts.reduce((acc, p) => revealPart(acc, p.id), s))}
            data-testid="show-solution"
          >
            Show all answers and the worked solution
          </button>{' '}
          <span className="muted">(parts not yet right then earn no more marks)</span>
        </p>
      </form>
      <Slot name="question-footer" />
      {allShown ? (
        <section className="panel practice-solution" aria-labelledby="solution-title" data-testid="solution">
          <h2 id="solution-title">Worked solution of variant {variant.seed}</h2>
          <SolutionSteps steps={variant.solution} />
          {variant.notes.map((n) => (
            <p key={n} className="muted">
              {n}
            </p>
          ))}
          <p>
            <a href={sceneHref} data-testid="scene-link">
              {variant.sceneLabel} ↗
            </a>
          </p>
        </section>
      ) : null}
    </main>
  );
}

function fmtMarks(x: number): string {
  return String(Math.round(x * 100) / 100);
}

/** What the student could do next: the parts to retry, with the hint or answer on offer. */
function nextSteps(v: Variant, s: Session): string[] {
  const out: string[] = [];
  for (const p of v.parts) {
    const st = s.parts[p.id];
    const tried = p.answers.filter((a) => s.answers[a.name].verdict);
    const wrong = tried.filter((a) => s.answers[a.name].verdict!.value !== 'correct');
    const name = `(${p.id})`;
    if (wrong.length) {
      const labels = wrong.map((a) => a.label).join(', ');
      out.push(
        st.revealed
          ? `${name} ${labels}: compare with the answer shown under the part.`
          : `${name} ${labels}: read the message, ${st.hint ? 'use the hint, ' : 'take the hint, '}and check again (${SCORING.revealAfter - st.wrong} wrong ${SCORING.revealAfter - st.wrong === 1 ? 'attempt' : 'attempts'} left before the answer is shown).`,
      );
    } else if (tried.length && tried.length < p.answers.length)
      out.push(`${name} The rest of this part is not answered yet.`);
  }
  const untouched = v.parts.filter((p) => p.answers.every((a) => !s.answers[a.name].verdict));
  if (untouched.length && untouched.length < v.parts.length)
    out.push(`Not answered yet: ${untouched.map((p) => `(${p.id})`).join(', ')}.`);
  if (!out.length && v.parts.every((p) => partDone(p, s)))
    out.push('Every answer is right. Try a new variant, or open the scene to see it move.');
  return out;
}

/** Text whose typed examples stand between backticks, with those set as code. */
function withCode(text: string) {
  return text.split('`').map((t, i) => (i % 2 ? <code key={i}>{t}</code> : t));
}

function PartBlock({
  part,
  progress,
  answers,
  inputs,
  onInput,
  onHint,
  onReveal,
  stepsBelow,
}: {
  part: Part;
  progress: PartProgress;
  answers: Session['answers'];
  inputs: Record<string, string>;
  onInput: (name: string, text: string) => void;
  onHint: () => void;
  onReveal: () => void;
  /** The whole worked solution is shown below the form: the part's step is not repeated here. */
  stepsBelow: boolean;
}) {
  const done = part.answers.every((a) => answers[a.name].verdict?.value === 'correct');
  const open = progress.revealed !== null || done;
  const marks = part.answers.reduce((m, a) => m + answers[a.name].best, 0);
  const left = SCORING.revealAfter - progress.wrong;
  return (
    <fieldset className="practice-part" data-testid={`part-${part.id}`}>
      <legend>
        <Superscripted text={part.prompt} />
      </legend>
      {part.answers.map((a) => (
        <AnswerRow
          key={a.name}
          spec={a}
          value={inputs[a.name] ?? ''}
          onChange={(t) => onInput(a.name, t)}
          progress={answers[a.name]}
          revealed={open}
        />
      ))}
      <div className="part-tools">
        <span
          className="part-status"
          data-testid={`attempts-${part.id}`}
          data-attempts={progress.attempts}
          data-wrong={progress.wrong}
        >
          {progress.attempts === 0
            ? 'Not checked yet.'
            : `${progress.attempts} attempt${progress.attempts === 1 ? '' : 's'}, ${progress.wrong} wrong · ${fmtMarks(marks)} of ${part.answers.length} mark${part.answers.length === 1 ? '' : 's'}`}
          {progress.revealed === 'attempts' ? ' · answer shown after 3 wrong attempts' : ''}
          {progress.revealed === 'asked' ? ' · answer shown' : ''}
          {!open && progress.wrong > 0
            ? ` · ${left} wrong attempt${left === 1 ? '' : 's'} before the answer is shown`
            : ''}
        </span>
        {!progress.hint && !open ? (
          <button type="button" onClick={onHint} data-testid={`hint-${part.id}`}>
            Hint
          </button>
        ) : null}
        {progress.revealed === null && !done ? (
          <button type="button" onClick={onReveal} data-testid={`show-answer-${part.id}`}>
            Show answer
          </button>
        ) : null}
      </div>
      {progress.hint && !open ? (
        <div className="part-hint" data-testid={`hint-text-${part.id}`}>
          <strong>Hint:</strong> <SolutionSteps steps={part.hint} />
        </div>
      ) : null}
      {open && !stepsBelow ? (
        <div className="part-solution" data-testid={`part-solution-${part.id}`}>
          <h3 className="part-solution-title">Worked step</h3>
          <SolutionSteps steps={part.steps} />
        </div>
      ) : null}
    </fieldset>
  );
}

function answerHint(spec: Exclude<AnswerSpec, { kind: 'choice' }>): string {
  if (spec.kind === 'formula') return `formula in ${spec.variables.join(', ')}`;
  return 'number, expression or none';
}

/** The option a stored answer names (a draft typed before choices were lists: "two hits"), or ''. */
function choiceValue(options: readonly string[], text: string): string {
  const s = text.trim().toLowerCase().replace(/\s+/g, '-');
  return options.includes(s) ? s : '';
}

function verdictTag(value: string): string {
  if (value === 'correct') return '✓ correct';
  if (value === 'consistent') return '≈ follow-through';
  if (value.startsWith('mistake:')) return `✗ ${value}`;
  if (value === 'invalid') return '? not graded';
  return '✗ incorrect';
}

function AnswerRow({
  spec,
  value,
  onChange,
  progress,
  revealed,
}: {
  spec: AnswerSpec;
  value: string;
  onChange: (t: string) => void;
  progress: AnswerProgress;
  revealed: boolean;
}) {
  const id = `answer-${spec.name}`;
  const exp = expectedText(spec);
  const verdict = progress.verdict;
  const kind = verdict ? (verdict.value.startsWith('mistake:') ? 'mistake' : verdict.value) : null;
  // What the answer's control carries whether it is a choice or typed text.
  const control = {
    id,
    'data-testid': id,
    'aria-describedby': verdict ? `verdict-${spec.name}` : undefined,
    'aria-invalid': verdict && verdict.value !== 'correct' ? true : undefined,
  };
  return (
    <div className={`answer-row${kind ? ` is-${kind}` : ''}`}>
      <label htmlFor={id} className="answer-label">
        <Superscripted text={spec.label} />
      </label>
      {spec.kind === 'choice' ? (
        // a choice is chosen from its options (graded as the option's name), never typed
        <select
          {...control}
          value={choiceValue(spec.options, value)}
          onChange={(e) => onChange(e.target.value)}
        >
          <option value="">Choose…</option>
          {spec.options.map((o) => (
            <option key={o} value={o}>
              {o.replace(/-/g, ' ')}
            </option>
          ))}
        </select>
      ) : (
        <input
          {...control}
          type="text"
          value={value}
          onChange={(e) => onChange(e.target.value)}
          autoComplete="off"
          autoCapitalize="off"
          spellCheck={false}
          placeholder={answerHint(spec)}
        />
      )}
      {verdict ? (
        <p
          className={`verdict verdict-${kind}`}
          id={`verdict-${spec.name}`}
          data-testid={`verdict-${spec.name}`}
          data-value={verdict.value}
          data-credit={progress.last}
        >
          <span className="verdict-tag">{verdictTag(verdict.value)}</span>{' '}
          <Superscripted text={verdict.message} />
          {verdict.value !== 'invalid' &&
          verdict.value !== 'incorrect' &&
          !verdict.value.startsWith('mistake:') ? (
            <span className="verdict-credit"> (+{fmtMarks(progress.last)} mark)</span>
          ) : null}
        </p>
      ) : null}
      {revealed ? (
        <p className="expected">
          Expected:{' '}
          <output data-testid={`expected-${spec.name}`} data-value={exp} title={exp}>
            {spec.tex ? (
              <MathTex tex={spec.tex} />
            ) : spec.kind === 'number' && spec.expected !== null ? (
              fmt(spec.expected, 6)
            ) : (
              // the answer as one would type it (expression syntax)
              <code>{exp}</code>
            )}
          </output>
        </p>
      ) : null}
    </div>
  );
}

function Givens({ givens, testIds }: { givens: Given[]; testIds: boolean }) {
  return (
    <dl className="givens">
      {givens.map((g) => (
        <div key={g.name} className={`given given-${g.name}`}>
          <dt>
            <Superscripted text={g.label} />
          </dt>
          <dd>
            {g.name === 'grid' ? (
              <GridTable text={g.value} testId={testIds ? `given-${g.name}` : undefined} />
            ) : (
              <span
                data-testid={testIds ? `given-${g.name}` : undefined}
                data-value={g.value}
                className="given-value"
              >
                {g.tex ? <MathTex tex={g.tex} /> : <Superscripted text={g.display} />}
              </span>
            )}
          </dd>
        </div>
      ))}
    </dl>
  );
}

function GridTable({ text, testId }: { text: string; testId?: string }) {
  const rows = text.split(';').map((r) => r.split(','));
  const n = rows.length;
  return (
    <div className="grid-scroll">
      <table className="grid-table" data-testid={testId} data-value={text}>
        <caption className="sr-only">
          Texel values: rows from v = 1 (top) to v = 0 (bottom), columns from u = 0 to u = 1
        </caption>
        <tbody>
          {rows.map((r, k) => (
            <tr key={k}>
              <th scope="row">{fmt(1 - k / (n - 1), 3)}</th>
              {r.map((x, i) => (
                <td key={i}>{x}</td>
              ))}
            </tr>
          ))}
          <tr>
            <th scope="row" className="axis-corner">
              v ↑ u →
            </th>
            {rows[0].map((_, i) => (
              <th key={i} scope="col">
                {fmt(i / (n - 1), 3)}
              </th>
            ))}
          </tr>
        </tbody>
      </table>
    </div>
  );
}

/** What another feature shows in this place of the page (extensions.ts), if any. */
function Slot({ name }: { name: 'home-footer' | 'question-footer' }) {
  const C = practiceSlot(name);
  return C ? <C /> : null;
}
