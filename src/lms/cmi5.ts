/**
 * cmi5 runtime of the practice package (one AU per question), through @xapi/cmi5: the AU reads
 * its launch parameters (endpoint, fetch, actor, registration, activityId) from its URL, fetches
 * the auth token, reads LMS.LaunchData (context template, launch mode, mastery score) and sends
 * Initialized. Each check sends one "answered" statement per typed answer (the named mistake in
 * its description); once the AU's question has been checked it sends Passed or Failed (scaled
 * score against the mastery score; Passed at most once, Failed not after Passed) and Completed
 * (once), all with the cmi5 context template the library adds. Leaving (the status bar's Finish
 * button, or closing the page) sends Terminated. In Browse or Review mode only Initialized,
 * answered and Terminated are sent, as cmi5 asks.
 *
 * The learner's state (typed answers, best marks) and what was already sent (Passed, Failed,
 * Completed) are kept in the record store's state document {@link STATE_ID} for the AU and the
 * registration, so a relaunch restores the answers and never sends Completed again, nor Failed
 * after Passed. A record store that keeps no state leaves each launch on its own.
 */
import Cmi5 from '@xapi/cmi5';
import type { CheckRecord } from '../practice/extensions';
import { expectedText } from '../practice/check';
import { allAnswers, type QuestionId } from '../practice/model';
import { mistakeOf, variantOf } from './grade';
import type { LmsConfig } from './config';
import { PracticeState } from './state';

export interface Cmi5Session {
  learnerId: string;
  learnerName: string;
  state: PracticeState;
  /** Report a check; resolves false when the record store refused a statement. */
  onCheck(r: CheckRecord): Promise<boolean>;
  /** The typed answers changed: kept in the state document after a pause in typing. */
  onInput(): void;
  finish(): Promise<void>;
  /** Where the LMS asked the learner to go after terminating (launch data returnURL). */
  returnUrl: string | null;
}

function learnerOf(actor: unknown): { id: string; name: string } {
  const a = (actor ?? {}) as {
    name?: unknown;
    mbox?: unknown;
    account?: { name?: unknown; homePage?: unknown };
  };
  const id =
    typeof a.account?.name === 'string'
      ? `${String(a.account.homePage ?? '')}|${a.account.name}`
      : typeof a.mbox === 'string'
        ? a.mbox
        : 'anonymous';
  return { id, name: typeof a.name === 'string' ? a.name : '' };
}

/** Connect, or null when the page was not launched by a cmi5 LMS. */
export async function connectCmi5(config: LmsConfig, questions: QuestionId[]): Promise<Cmi5Session | null> {
  if (!Cmi5.isCmiAvailable) return null;
  const cmi5 = new Cmi5();
  await cmi5.initialize();
  const data = cmi5.getLaunchData();
  const { id, name } = learnerOf(cmi5.getLaunchParameters().actor);
  const mastery =
    typeof data.masteryScore === 'number' && data.masteryScore > 0 && data.masteryScore <= 1
      ? data.masteryScore
      : config.mastery;
  const state = new PracticeState(questions, id, config.seed, mastery);
  const judged = data.launchMode === 'Normal';
  const params = cmi5.getLaunchParameters();
  const activityId = params.activityId;
  const doc = { agent: params.actor, activityId, stateId: STATE_ID, registration: params.registration };
  const sent = { passed: false, failed: false, completed: false };
  try {
    // ask which documents the store keeps before reading ours: a first launch then costs no 404
    const ids = await cmi5.xapi?.getStates({ agent: doc.agent, activityId, registration: doc.registration });
    const listed = Array.isArray(ids?.data) && ids.data.includes(STATE_ID);
    const r = listed ? await cmi5.xapi?.getState(doc) : undefined;
    const kept = readKept(r?.data);
    if (kept) {
      Object.assign(sent, kept.sent);
      state.restore(kept.state);
    }
  } catch {
    /* no state kept (a first launch, or a record store without the state resource) */
  }
  let finished = false;
  const keep = () =>
    cmi5.xapi?.setState({ ...doc, state: { v: 1, sent: { ...sent }, state: state.serialise(32_000) } });
  let queue: Promise<unknown> = Promise.resolve();
  const later = <T>(f: () => Promise<T>, failed: T): Promise<T> => {
    const p = queue.then(f).catch(() => failed);
    queue = p;
    return p;
  };
  let keepTimer: ReturnType<typeof setTimeout> | null = null;
  return {
    learnerId: id,
    learnerName: name,
    state,
    returnUrl: typeof data.returnURL === 'string' ? data.returnURL : null,
    onInput: () => {
      if (finished) return;
      if (keepTimer) clearTimeout(keepTimer);
      keepTimer = setTimeout(() => {
        keepTimer = null;
        void later(async () => void (await keep()), undefined);
      }, 1000);
    },
    onCheck: (r) =>
      later(async () => {
        if (finished) return true;
        const answers = allAnswers(variantOf(r.question, r.seed));
        for (const a of r.answers) {
          if (a.verdict === 'blank') continue;
          const spec = answers.find((x) => x.name === a.name);
          const mistake = mistakeOf(a.verdict);
          await cmi5.interactionFillIn(
            activityId,
            `${r.question}-${r.seed}-${a.name}`,
            [a.response.slice(0, 500)],
            spec ? [expectedText(spec)] : undefined,
            { 'en-US': `${r.question} ${a.name}` },
            { 'en-US': mistake ? `mistake ${mistake}: ${a.message}` : a.verdict },
            a.verdict === 'correct',
          );
        }
        const t = state.totals();
        if (judged && t.complete) {
          const score = { scaled: t.scaled, raw: t.raw, min: 0, max: t.max };
          if (t.passed && !sent.passed) {
            await cmi5.pass(score);
            sent.passed = true;
          } else if (!t.passed && !sent.passed && !sent.failed) {
            await cmi5.fail(score);
            sent.failed = true;
          }
          if (!sent.completed) {
            await cmi5.complete();
            sent.completed = true;
          }
        }
        await keep()?.catch(() => undefined);
        return true;
      }, false),
    finish: () =>
      later(async () => {
        if (finished) return;
        finished = true;
        if (keepTimer) clearTimeout(keepTimer);
        await keep()?.catch(() => undefined);
        await cmi5.terminate();
      }, undefined),
  };
}

/** The state document's id (one per AU and registration). */
export const STATE_ID = 'https://render-math-lab.invalid/practice-state';

/** A kept state document, or null when it is not one. */
function readKept(
  x: unknown,
): { sent: Record<'passed' | 'failed' | 'completed', boolean>; state: string } | null {
  const d = (typeof x === 'string' ? safeJson(x) : x) as
    { v?: unknown; sent?: Record<string, unknown>; state?: unknown } | null | undefined;
  if (!d || d.v !== 1 || typeof d.state !== 'string') return null;
  const s = d.sent ?? {};
  return {
    sent: { passed: s.passed === true, failed: s.failed === true, completed: s.completed === true },
    state: d.state,
  };
}

function safeJson(s: string): unknown {
  try {
    return JSON.parse(s);
  } catch {
    return null;
  }
}
