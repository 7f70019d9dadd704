import { useCallback, useEffect, useState, type FormEvent } from 'react';
import type { ParamProblem } from '../kit/params';
import type { ShellFlags } from '../kit/shell';
import { formatPlain } from '../ui/format';
import { Superscripted } from '../ui/Superscripted';
import { AnswerPolicy } from './AnswerPolicy';
import { openingAnswers, saveDraft } from './drafts';
import { loadSession, saveSession, withStored } from './sessionStore';
import { extensionCheck, extensionInput, extensionRestore } from './extensions';
import { Givens } from './Givens';
import { flagSuffix, randomSeed } from './links';
import { allAnswers, roundTo, type Variant } from './model';
import { nextSteps } from './nextSteps';
import { ParamNotice, TextList } from './ParamNotice';
import { PartBlock } from './PartBlock';
import { recordCheck } from './progress';
import { questionMeta } from './questionList';
import { recordScore } from './scores';
import {
  applyCheck,
  forfeitedAnswers,
  gradeAnswers,
  partDone,
  revealPart,
  sessionScore,
  showHint,
  type Session,
} from './session';
import { Slot } from './Slot';
import { SolutionSteps } from './SolutionSteps';

/**
 * One variant of a question: the statement and givens, a form with every part (Check grades what
 * was typed; each verdict is also announced as `rml:practice-verdict` on window for the host-page
 * API), what to do next, and the worked solution once every part is open.
 */
export function QuestionPage({
  variant,
  flags,
  problems,
}: {
  variant: Variant;
  flags: ShellFlags;
  problems: ParamProblem[];
}) {
  const info = questionMeta(variant.question);
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
        `${nCorrect} of ${answers.length} correct · ${formatPlain(roundTo(score.marks, 2))} of ${score.total} marks (best kept).`,
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
    window.location.hash = `#/practice/${variant.question}?seed=${s}${flagSuffix(flags)}`;
  };
  const sceneHref = `${variant.sceneHref}${flagSuffix(flags)}`;
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
        <Givens givens={variant.givens} />
      </section>
      <form className="panel practice-answers" onSubmit={check} noValidate aria-labelledby="answers-title">
        <h2 id="answers-title">Your answers</h2>
        <p className="muted practice-howto">
          Answer any part and press <strong>Check</strong>: only what you typed is graded. Each part has a
          hint and its own <strong>Show answer</strong>.
        </p>
        <AnswerPolicy />
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
