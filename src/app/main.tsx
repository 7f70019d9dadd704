import { StrictMode, startTransition } from 'react';
import { createRoot } from 'react-dom/client';
import { App } from './App';
import '../ui/theme.css';
import '../ui/base.css';
import './shell.css';
// The shared components' styles, which nearly every page's first screen uses, go in the shell's
// stylesheet (inline in index.html) rather than in a stylesheet per chunk: on a phone each of
// those was one more request before a page's first paint. (Each component still imports its own;
// a style that only a fold or one page uses stays with that page.)
import '../ui/a11y.css';
import '../ui/ask.css';
import '../ui/controls.css';
import '../ui/exam.css';
import '../ui/fold.css';
import '../ui/layout.css';
import '../ui/math.css';
import '../ui/readout.css';
import '../ui/runningEstimate.css';
import '../ui/stage.css';
import '../ui/timeline.css';
import '../three/viewport.css';
// KaTeX's font faces (declared only: a font downloads when a formula first uses it). Declared
// here, not in KaTeX's lazily loaded stylesheet, whose arrival would otherwise restyle and lay out
// the whole page (scripts/katexCss.ts).
import 'katex/dist/katex.min.css?fonts';
import { readerActed, whenQuiet } from '../ui/whenQuiet';
import { findScene } from '../kit/catalogue';
import { sceneLoader } from '../scenes/registry';
import { parseHash } from '../kit/shell';
import { firstScreen } from './firstScreen';
import { afterPaint } from '../ui/afterPaint';
import { markBuildReplaced } from '../ui/staleBuild';
import { showUpdateNotice } from './updateNotice';
import { declaredLmsConfig } from '../lms/config';
import { fuzzRequest } from './fuzzGate';
import { keepFocusInView } from '../ui/focusInView';

// The opened scene's chunk is requested at once (index.html has already started downloading it:
// scripts/routePreload.ts), and the first render waits for it (firstRender below). A failure is
// the scene host's to report: its own import of the same module fails too.
const opened = findScene(parseHash(window.location.hash).path);
const openedScene: Promise<unknown> = opened
  ? (sceneLoader(opened.id)?.().catch(() => undefined) ?? Promise.resolve())
  : Promise.resolve();

// The reader's first key, press, wheel or touch ends the page's opening (../ui/whenQuiet
// openingDone): listened for from the start, so that one made before the scene has mounted counts.
void readerActed();

/**
 * The first render waits for the opened scene's chunk, so that the first paint shows the scene
 * whole. Rendering the shell first ("Loading the scene…") and the scene when its chunk came was two
 * first layouts of the page, the second a long task with the page already shown, and two changes
 * of the page's height, each of which shows and fades a phone's overlay scrollbar (a run of
 * frames). Where the chunk takes longer than FIRST_RENDER_WAIT_MS (a very slow connection), the
 * shell shows "Loading the scene…" meanwhile, as it does when a scene is opened from another page.
 */
const FIRST_RENDER_WAIT_MS = 2500;
async function firstRender(root: HTMLElement) {
  await Promise.race([openedScene, new Promise((r) => setTimeout(r, FIRST_RENDER_WAIT_MS))]);
  render(root);
}

const root = document.getElementById('root');
// Inside an LMS package (SCORM, cmi5) the launch page declares it (../lms/config.ts): the LMS
// runtime is loaded, and connects, before the first render (it decides the learner's variant seeds).
const declared = declaredLmsConfig();
const inLms = typeof declared === 'object' && declared !== null;
if (root && inLms)
  void import('../lms/launch')
    .then((m) => m.startLms())
    .catch(() => undefined)
    .finally(() => render(root));
else if (root) void firstRender(root);

function render(root: HTMLElement) {
  // a field reached with Tab stays on screen while the page settles around it (../ui/focusInView)
  keepFocusInView();
  const r = createRoot(root);
  // A transition: React renders the shell's first tree in slices that yield to the browser, not in
  // one task (on a phone, code that has never run yet is slow).
  startTransition(() =>
    r.render(
      <StrictMode>
        <App />
      </StrictMode>,
    ),
  );
}

// Fuzz mode (`#/…?fuzz=1&seed=7`, optional `fuzzn=300`): the self-driving fuzzer, a test tool,
// loaded lazily and only in a build that allows it (./fuzzGate.ts). The literal condition below
// is a constant false in a production build, so the fuzzer's chunk is not even emitted there.
let fuzzing = false;
function maybeFuzz() {
  if (fuzzing) return;
  const ask = fuzzRequest(import.meta.env, window.location.hash);
  if (!ask) return;
  fuzzing = true;
  void import('./fuzz').then((m) => m.startFuzz(ask));
}
if (import.meta.env.DEV || import.meta.env.VITE_RML_FUZZ === '1') {
  maybeFuzz();
  window.addEventListener('hashchange', maybeFuzz);
}

// Offline copy: register the service worker from a lazy chunk (not in development, not in the
// single-file build, not from file://) once the page has loaded, the opened scene's first screen
// has been painted (10 s at most), and the page has then been idle for 2 s: its install precaches
// the whole build, about a second of CPU on a worker thread that competed with a scene's load on a
// phone, and registering at 'load' put its chunks before a scene's first paint (../ui/whenQuiet).
if (
  import.meta.env.PROD &&
  import.meta.env.MODE !== 'single' &&
  !inLms &&
  'serviceWorker' in navigator &&
  /^https?:$/.test(window.location.protocol)
) {
  // A new build's worker taking over this page (another tab's Reload) does not reload it: its
  // reader may be typing. The page keeps running its build and says it was updated; a lazy chunk it
  // then cannot load (gone with the old build) reloads it onto the new one (src/ui/staleBuild.ts). The
  // first controllerchange of a page that loaded without a controller is the first install's claim.
  let controllers = navigator.serviceWorker.controller ? 1 : 0;
  navigator.serviceWorker.addEventListener('controllerchange', () => {
    controllers += 1;
    if (controllers < 2) return;
    markBuildReplaced();
    showUpdateNotice(() => window.location.reload());
  });
  const start = () =>
    void (opened ? firstScreen(10_000) : Promise.resolve())
      .then(afterPaint)
      .then(() => whenQuiet())
      .then(() => import('./pwa'))
      .then(
        (m) => m.registerPwa(),
        () => undefined,
      );
  if (document.readyState === 'complete') start();
  else window.addEventListener('load', start, { once: true });
}
