/**
 * The LMS runtime's entry, loaded by the app only when the launch page declares a package
 * (./config.ts, written by packages.ts): connects to the LMS (SCORM 1.2, SCORM 2004 or cmi5),
 * registers the practice extension that gives each learner their variants and reports every
 * check, opens the package's start page, and shows a one-line status. Without an LMS the package
 * runs as the normal practice pages, and the status says so.
 */
import { addPracticeExtension } from '../practice/extensions';
import { isQuestionId, type QuestionId } from '../practice/model';
import type { LmsConfig } from './config';
import { declaredLmsConfig } from './config';
import { setLearnerScope } from '../practice/learnerScope';

function readConfig(): LmsConfig | null {
  const c = declaredLmsConfig() as Partial<LmsConfig> | null;
  if (!c || typeof c !== 'object') return null;
  const kind = c.kind === 'scorm12' || c.kind === 'scorm2004' || c.kind === 'cmi5' ? c.kind : null;
  const questions = Array.isArray(c.questions)
    ? c.questions.filter((q): q is QuestionId => isQuestionId(String(q)))
    : [];
  if (!kind || !questions.length) return null;
  return {
    kind,
    questions,
    seed: Number.isInteger(c.seed) ? (c.seed as number) >>> 0 : 0,
    mastery: typeof c.mastery === 'number' && c.mastery > 0 && c.mastery <= 1 ? c.mastery : 0.8,
    version: typeof c.version === 'string' ? c.version.slice(0, 40) : '',
  };
}

/** The status when the LMS refused a check's values or its commit. */
const REFUSED =
  'The LMS did not accept your last check: your result may not be recorded. Check again, or tell your teacher.';

function showStatus(state: 'connected' | 'none' | 'finished' | 'error', text: string): void {
  let el = document.querySelector<HTMLElement>('[data-testid="lms-status"]');
  if (!el) {
    el = document.createElement('p');
    el.setAttribute('data-testid', 'lms-status');
    el.setAttribute('role', 'status');
    el.className = 'lms-status';
    el.style.cssText =
      'position:fixed;right:0.5rem;bottom:0.5rem;margin:0;padding:0.25rem 0.6rem;font:0.8rem/1.4 system-ui,sans-serif;border-radius:0.4rem;background:#1c1d21;color:#f7f6f2;opacity:0.9;z-index:50;max-width:30rem';
    document.body.appendChild(el);
  }
  el.dataset.state = state;
  el.textContent = text;
}

/** cmi5: an explicit "Finish" (Terminated), since a closing page may not get its last request out. */
function finishButton(onFinish: () => Promise<void>): void {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = 'Finish';
  b.setAttribute('data-testid', 'lms-finish');
  b.style.cssText =
    'position:fixed;right:0.5rem;bottom:2.6rem;z-index:50;font:0.85rem system-ui,sans-serif;padding:0.3rem 0.8rem';
  b.addEventListener('click', () => {
    b.disabled = true;
    void onFinish().finally(() => b.remove());
  });
  document.body.appendChild(b);
}

function openStart(questions: readonly QuestionId[], only: QuestionId | null): void {
  const h = window.location.hash;
  if (only) {
    if (!h.startsWith(`#/practice/${only}`)) window.location.hash = `#/practice/${only}`;
    return;
  }
  if (h === '' || h === '#' || h === '#/')
    window.location.hash = questions.length === 1 ? `#/practice/${questions[0]}` : '#/practice';
}

/** Connect and register; resolves when the first render may happen. Never throws. */
export async function startLms(): Promise<void> {
  const config = readConfig();
  if (!config) return;
  try {
    if (config.kind === 'cmi5') {
      const { connectCmi5 } = await import('./cmi5');
      const au = new URLSearchParams(window.location.search).get('rml-au');
      const only = au && isQuestionId(au) && config.questions.includes(au) ? au : null;
      const s = await connectCmi5(config, only ? [only] : config.questions);
      openStart(config.questions, only);
      if (!s) {
        showStatus('none', 'No cmi5 launch found: practising without reporting.');
        return;
      }
      setLearnerScope(s.learnerId);
      const connected = `Connected to the LMS (cmi5)${s.learnerName ? ` as ${s.learnerName}` : ''}: your checked answers are reported.`;
      addPracticeExtension(
        s.state.extension({
          onCheck: (r) =>
            void s.onCheck(r).then((ok) => showStatus(ok ? 'connected' : 'error', ok ? connected : REFUSED)),
          onInput: () => s.onInput(),
        }),
      );
      window.addEventListener('pagehide', () => void s.finish(), { once: true });
      finishButton(async () => {
        await s.finish();
        if (s.returnUrl) window.location.href = s.returnUrl;
        else showStatus('finished', 'Finished: your results are with the LMS. You can close this page.');
      });
      showStatus('connected', connected);
      return;
    }
    const { connectScorm } = await import('./scorm');
    const s = connectScorm(config);
    openStart(config.questions, null);
    if (!s) {
      showStatus('none', 'No LMS found: practising without reporting.');
      return;
    }
    setLearnerScope(s.learnerId);
    const connected = `Connected to the LMS (SCORM ${s.version})${s.learnerName ? ` as ${s.learnerName}` : ''}: your checked answers are reported.`;
    addPracticeExtension(
      s.state.extension({
        onCheck: (r) => {
          const ok = s.onCheck(r);
          showStatus(ok ? 'connected' : 'error', ok ? connected : REFUSED);
        },
        onInput: s.onInput,
      }),
    );
    const finish = () => s.finish();
    window.addEventListener('pagehide', finish, { once: true });
    window.addEventListener('beforeunload', finish, { once: true });
    showStatus('connected', connected);
  } catch (e) {
    showStatus(
      'error',
      `The LMS connection failed (${e instanceof Error ? e.message : String(e)}); practising without reporting.`,
    );
  }
}
