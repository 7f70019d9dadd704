import { useEffect } from 'react';
import { SCENES, sceneLoader } from '../scenes/registry';
import { RouteNotice } from './RouteNotice';
import type { ShellFlags } from './route';

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
      <ol className="question-list">
        {EXAM_QUESTIONS.map((q) => {
          const scene = SCENES.find((s) => s.id === q.scene)!;
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

const EXAM_QUESTIONS: { n: number; title: string; text: string; scene: string; query?: string }[] = [
  {
    n: 1,
    title: 'Sampling a hemisphere PDF',
    text: 'Normalize p(ω) = k cos θ e^φ, find its marginals and CDFs, and invert them to draw directions.',
    scene: 'hemisphere',
    query: 'lobe=exam',
  },
  {
    n: 2,
    title: 'Monte Carlo estimators on the hemisphere',
    text: 'Uniform and importance-sampled estimators of ∫ f dω, and why both are unbiased.',
    scene: 'hemisphere',
    query: 'lobe=exam&f=cos(theta)',
  },
  {
    n: 3,
    title: 'Texture lookup',
    text: 'Nearest neighbour and bilinear lookup at (0.4, 0.24), and the spherical (u, v) mapping.',
    scene: 'texture',
    query: 'u=0.4&v=0.24',
  },
  {
    n: 4,
    title: 'Monte Carlo integration of (x + 2)²',
    text: 'Uniform against importance sampling with four given samples, and how each converges.',
    scene: 'monte-carlo',
    query: 'samples=1.16,1.98,0.54,1.26',
  },
  {
    n: 5,
    title: 'Ray–sphere intersection',
    text: 'The quadratic, its discriminant, which root is the hit, and floating-point robustness.',
    scene: 'ray-sphere',
  },
  {
    n: 6,
    title: 'Solid angle and area lights',
    text: 'dω = dA cos θ_l / r², the rendering equation over a light’s area, and area-light sampling.',
    scene: 'area-light',
  },
];
