import { useEffect } from 'react';
import { PAGES, QUESTIONS, sceneById } from '../kit/catalogue';
import { sceneLoader } from '../scenes/registry';
import type { ShellFlags } from '../kit/shell';
import { RouteNotice } from '../ui/RouteNotice';
import './home.css';

function withFlags(query: string, flags: ShellFlags): string {
  const parts = query ? [query] : [];
  if (flags.present) parts.push('present=1');
  if (flags.theme) parts.push(`theme=${flags.theme}`);
  return parts.length ? `?${parts.join('&')}` : '';
}

/** The home page: the six exam questions, each linked to the scene that teaches it. */
export function Home({ flags, query = '' }: { flags: ShellFlags; query?: string }) {
  useEffect(() => {
    document.title = 'Render Math Lab';
  }, []);
  return (
    <main id="main" className="page home" tabIndex={-1}>
      <RouteNotice flags={flags} query={query} />
      <h1>The mathematics of rendering, one question at a time</h1>
      <p className="lead">
        Six questions from a Computer Graphics final exam, each turned into a scene you can push on: change a
        number and every figure, plot and picture is recomputed on the spot. Share or embed any configuration
        by its link.
      </p>
      <p className="home-practice">
        <a href={`#/practice${withFlags('', flags)}`} data-testid="practice-link">
          Practice
        </a>
        : test yourself on fresh variants of every question — answers checked, classic mistakes named, worked
        solutions with your numbers.
      </p>
      <p className="home-practice">
        <a href={`#${PAGES.deck.path}${withFlags('', flags)}`} data-testid="deck-link">
          {PAGES.deck.title}
        </a>
        : play the guide’s questions as slides, or build your own from any scene’s view.
      </p>
      <ol className="question-list">
        {QUESTIONS.map((q) => {
          const scene = sceneById(q.scene);
          const built = sceneLoader(scene.id) !== null;
          // land on the question's first part (Q2 opens the hemisphere page at 2a, not at Q1)
          const part = scene.parts.find((p) => p.startsWith(String(q.n)));
          const base = q.query ?? scene.examQuery;
          const href = `#${scene.path}${withFlags([base, part ? `part=${part}` : ''].filter(Boolean).join('&'), flags)}`;
          return (
            <li key={q.n} className={`question-card${built ? '' : ' planned'}`}>
              <div className="question-head">
                <span className="question-number">Q{q.n}</span>
                <h2>{built ? <a href={href}>{q.title}</a> : q.title}</h2>
              </div>
              <p>{q.text}</p>
              <p className="question-scene">
                {built ? (
                  <>
                    Opens{' '}
                    <a href={href} aria-label={`${scene.title} (${scene.questions})`}>
                      {scene.title}
                    </a>{' '}
                    ({scene.questions})
                  </>
                ) : (
                  <span className="badge">Scene not built yet</span>
                )}
              </p>
            </li>
          );
        })}
      </ol>
    </main>
  );
}
