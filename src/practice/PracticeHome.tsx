import { useEffect, useState } from 'react';
import type { ShellFlags } from '../kit/shell';
import { RouteNotice } from '../ui/RouteNotice';
import { BestScores } from './BestScores';
import { flagSuffix, randomSeed } from './links';
import { loadProgress, type Progress } from './progress';
import { resetPractice } from './reset';
import { QUESTION_LIST } from './questionList';
import { loadScores, type Scores } from './scores';
import { SheetBuilder } from './SheetBuilder';
import { Slot } from './Slot';

/** `#/practice`: the six questions with the student's progress, and the worksheet builder. */
export function PracticeHome({ flags, query }: { flags: ShellFlags; query: string }) {
  const [progress, setProgress] = useState<Progress>(() => loadProgress());
  const [scores, setScores] = useState<Scores>(() => loadScores());
  const [status, setStatus] = useState('');
  useEffect(() => {
    document.title = 'Practice — Render Math Lab';
  }, []);
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
        {QUESTION_LIST.map((q) => {
          const p = progress[q.id];
          return (
            <li key={q.id} className="question-card">
              <div className="question-head">
                <span className="question-number">Q{q.n}</span>
                <h2>
                  <a href={`#/practice/${q.id}?seed=${randomSeed()}${flagSuffix(flags)}`}>{q.title}</a>
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
      <SheetBuilder flags={flags} />
    </main>
  );
}
