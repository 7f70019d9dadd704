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
 */
import Cmi5 from '@xapi/cmi5';
import type { CheckRecord } from '../practice/extensions';
import { expectedText } from '../practice/check';
import { allAnswers, type QuestionId } from '../practice/model';
import { mistakeOf, variantOf } from './grade';
import type { LmsConfig } from './packages';
import { PracticeState } from './state';

export interface Cmi5Session {
  learnerName: string;
  state: PracticeState;
  onCheck(r: CheckRecord): Promise<void>;
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
  let passed = false;
  let failed = false;
  let completed = false;
  let finished = false;
  const activityId = cmi5.getLaunchParameters().activityId;
  let queue: Promise<unknown> = Promise.resolve();
  const later = (f: () => Promise<unknown>) => {
    queue = queue.then(f).catch(() => undefined);
    return queue as Promise<void>;
  };
  return {
    learnerName: name,
    state,
    returnUrl: typeof data.returnURL === 'string' ? data.returnURL : null,
    onCheck: (r) =>
      later(async () => {
        if (finished) return;
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
        if (!judged || !t.complete) return;
        const score = { scaled: Math.round(t.scaled * 1e6) / 1e6, raw: t.raw, min: 0, max: t.max };
        if (t.passed && !passed) {
          passed = true;
          await cmi5.pass(score);
        } else if (!t.passed && !passed && !failed) {
          failed = true;
          await cmi5.fail(score);
        }
        if (!completed) {
          completed = true;
          await cmi5.complete();
        }
      }),
    finish: () =>
      later(async () => {
        if (finished) return;
        finished = true;
        await cmi5.terminate();
      }),
  };
}
