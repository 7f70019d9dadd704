import { Suspense, useEffect, useMemo, type ReactNode } from 'react';
import { useHashRoute } from './useHashRoute';
import { parseShellFlags } from '../kit/shell';
import { useTheme } from './theme';
import { usePostHeight } from './embedHeight';
import { useHostApi } from './hostBridge';
import { Home } from './Home';
import { SceneHost } from './SceneHost';
import { findScene } from '../kit/catalogue';
import { ShortcutProvider } from '../ui/shortcuts';
import { lazyPage } from '../ui/lazyPage';
import { DECK_HOST } from './SlideScene';

// Practice mode is its own lazy chunk (src/practice): nothing of it loads on the other routes.
// Every lazy route recovers from a stale deploy or says it could not load (src/ui/lazyPage.tsx).
const PracticeRoute = lazyPage(
  // with the parts other features show on the practice pages (results download, LMS packages)
  () =>
    Promise.all([
      import('../practice/PracticeRoute'),
      import('../results/slots'),
      import('../lms/slots'),
    ]).then(([m]) => m),
  'Practice',
);

// The teacher's guide (#/guide) is its own lazy chunk.
const Guide = lazyPage(() => import('../guide/Guide'), 'The guide');

// The accessibility statement and its worked example (#/accessibility): its own lazy chunk.
const AccessibilityPage = lazyPage(() => import('./AccessibilityPage'), 'The accessibility page');

// The lecture deck (#/deck) is its own lazy chunk.
const DeckPage = lazyPage(() => import('../deck/DeckPage'), 'The lecture deck');

// The class results page (#/results) is its own lazy chunk.
const ResultsRoute = lazyPage(() => import('../results/ResultsRoute'), 'The class results page');

/** A route whose page loads as its own chunk, with a "Loading …" status until it has. */
function LazyRoute({ loading, children }: { loading: string; children: ReactNode }) {
  return (
    <Suspense
      fallback={
        <main id="main" className="page route-pending" tabIndex={-1}>
          <p className="loading" role="status">
            {loading}
          </p>
        </main>
      }
    >
      {children}
    </Suspense>
  );
}

export function App() {
  const route = useHashRoute();
  // memoised: SceneHost's setParams and effects depend on it, so it must not change per render
  const flags = useMemo(() => parseShellFlags(route.query), [route.query]);
  const theme = useTheme(flags.theme);
  const scene = findScene(route.path);
  usePostHeight(flags.embed, scene?.id ?? null, flags.origins);
  useHostApi(flags.origins);

  useEffect(() => {
    const cl = document.documentElement.classList;
    cl.toggle('present', flags.present);
    cl.toggle('embed', flags.embed);
  }, [flags.present, flags.embed]);

  let body;
  if (route.path === '/') body = <Home flags={flags} query={route.query} />;
  else if (route.path === '/practice' || route.path.startsWith('/practice/'))
    body = (
      <LazyRoute loading="Loading practice…">
        <PracticeRoute path={route.path} query={route.query} flags={flags} />
      </LazyRoute>
    );
  else if (route.path === '/guide')
    body = (
      <LazyRoute key="guide" loading="Loading the teacher’s guide…">
        <Guide flags={flags} query={route.query} />
      </LazyRoute>
    );
  else if (route.path === '/accessibility')
    body = (
      <LazyRoute key="accessibility" loading="Loading the accessibility statement…">
        <AccessibilityPage flags={flags} query={route.query} />
      </LazyRoute>
    );
  else if (route.path === '/deck')
    body = (
      <LazyRoute key="deck" loading="Loading the deck…">
        {/* another deck link (typed, pasted, Present / Edit) opens afresh; the deck's own rewrites do not */}
        <DeckPage key={route.query} flags={flags} query={route.query} theme={theme} host={DECK_HOST} />
      </LazyRoute>
    );
  else if (route.path === '/results')
    body = (
      <LazyRoute key="results" loading="Loading the class results page…">
        <ResultsRoute />
      </LazyRoute>
    );
  else if (scene)
    body = <SceneHost key={scene.id} info={scene} query={route.query} flags={flags} theme={theme} />;
  else
    body = (
      <main id="main" className="page">
        <h1>Page not found</h1>
        <p role="status">
          There is no page at <code>#{route.path.slice(0, 80)}</code>.{' '}
          <a href="#/">Go to the list of scenes</a>.
        </p>
      </main>
    );

  return (
    <ShortcutProvider active={flags.present}>
      <a
        className="skip-link"
        href="#main"
        onClick={(e) => {
          e.preventDefault();
          document.getElementById('main')?.focus();
        }}
      >
        Skip to content
      </a>
      {flags.embed ? null : <SiteHeader present={flags.present} />}
      {body}
      {flags.embed ? null : (
        <footer className="site-footer">
          <p>
            Render Math Lab — every figure is computed live in your browser, and nothing is fetched from
            anywhere but this site, so a copy of the build works offline.
            {flags.present ? ' Classroom mode: press ? for shortcuts.' : ''}{' '}
            <a href="#/accessibility">Accessibility</a>
          </p>
        </footer>
      )}
    </ShortcutProvider>
  );
}

function SiteHeader({ present }: { present: boolean }) {
  return (
    <header className="site-header">
      <a href={present ? '#/?present=1' : '#/'} className="brand">
        <span className="brand-mark" aria-hidden="true">
          ◐
        </span>{' '}
        Render Math Lab
      </a>
      <a href={present ? '#/guide?present=1' : '#/guide'} className="guide-link">
        Teacher’s guide
      </a>
    </header>
  );
}
