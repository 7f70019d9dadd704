/**
 * The cmi5 runtime (src/lms/cmi5.ts) against a loopback record store, in Node: a relaunch restores
 * the typed answers (checked or only typed), never sends Completed twice nor Failed after Passed,
 * and a store that refuses statements is reported.
 */
import { afterAll, beforeAll, beforeEach, describe, expect, it, vi } from 'vitest';
import { NodeXhr } from './nodeXhr';
import { recordStore, type RecordStore } from './recordStore';
import type { Cmi5Session } from '../../src/lms/cmi5';
import { checkRecord } from './checkRecord';
import { variantOf } from '../../src/lms/grade';
import { allAnswers } from '../../src/practice/model';

// the package's entry has no "main" Node resolves; its browser bundle is what the app ships
vi.mock('@xapi/cmi5', async () => await import('@xapi/cmi5/dist/Cmi5.esm.js'));

let store: RecordStore;
let connectCmi5: typeof import('../../src/lms/cmi5').connectCmi5;
const g = globalThis as unknown as { window?: unknown; XMLHttpRequest?: unknown };

beforeAll(async () => {
  store = await recordStore({ launchMode: 'Normal', contextTemplate: {}, masteryScore: 0.8 });
  g.XMLHttpRequest = NodeXhr;
  ({ connectCmi5 } = await import('../../src/lms/cmi5'));
});
afterAll(async () => {
  delete g.window;
  delete g.XMLHttpRequest;
  await store.close();
});
beforeEach(() => {
  store.statements.length = 0;
  store.state.clear();
  store.refuse.statements = false;
});

/** Launch the AU of q5 as an LMS does (the launch parameters in the address). */
async function launch(learner: string, registration = 'r-1'): Promise<Cmi5Session> {
  const qs = new URLSearchParams({
    'rml-au': 'q5',
    endpoint: `${store.origin}/xapi/`,
    fetch: `${store.origin}/fetch`,
    actor: JSON.stringify({
      objectType: 'Agent',
      name: 'L',
      account: { homePage: 'https://lms.test', name: learner },
    }),
    registration,
    activityId: 'https://render-math-lab.invalid/cmi5/5/q5',
  });
  g.window = { location: { search: `?${qs}`, href: `${store.origin}/pkg/index.html?${qs}` } };
  const s = await connectCmi5({ kind: 'cmi5', questions: ['q5'], seed: 5, mastery: 0.8, version: 't' }, [
    'q5',
  ]);
  expect(s).not.toBeNull();
  return s!;
}

/** A Check on the page with `right` answers right (the page's marks), through the extension. */
async function check(s: Cmi5Session, right: number): Promise<boolean> {
  const r = checkRecord('q5', s.state.byQuestion.get('q5')!.seed, right, right);
  let done: Promise<boolean> = Promise.resolve(false);
  s.state.extension({ onCheck: (x) => (done = s.onCheck(x)), onInput: s.onInput }).onCheck!(r);
  return done;
}

const verbs = () =>
  store.statements.map((x) =>
    String(x.verb?.id ?? '')
      .split('/')
      .pop(),
  );
const judged = () => verbs().filter((v) => v === 'passed' || v === 'failed' || v === 'completed');

describe('cmi5 against a loopback record store', () => {
  it('passed, then a relaunch and a worse check: no Failed, no second Completed, answers back', async () => {
    const s = await launch('u-1');
    const n = s.state.byQuestion.get('q5')!.max;
    expect(await check(s, n)).toBe(true);
    await s.finish();
    expect(judged()).toEqual(['passed', 'completed']);
    const typed = { ...s.state.byQuestion.get('q5')!.answers };
    const again = await launch('u-1');
    const seed = again.state.byQuestion.get('q5')!.seed;
    expect(
      again.state.extension({ onCheck: () => undefined, onInput: () => undefined }).restore!('q5', seed),
    ).toEqual(typed);
    expect(await check(again, 0)).toBe(true);
    await again.finish();
    expect(judged()).toEqual(['passed', 'completed']);
    expect(verbs().filter((v) => v === 'terminated')).toHaveLength(2);
  });

  it('failed, then passed on a relaunch, then failed again: each verdict once, in that order', async () => {
    const s = await launch('u-2');
    const n = s.state.byQuestion.get('q5')!.max;
    await check(s, 0);
    await s.finish();
    const s2 = await launch('u-2');
    await check(s2, n);
    await s2.finish();
    const s3 = await launch('u-2');
    await check(s3, 0);
    await s3.finish();
    expect(judged()).toEqual(['failed', 'completed', 'passed']);
  });

  it('answers typed but never checked come back after a crash; another registration starts afresh', async () => {
    const s = await launch('u-3');
    const seed = s.state.byQuestion.get('q5')!.seed;
    const names = allAnswers(variantOf('q5', seed)).map((a) => a.name);
    const typed = Object.fromEntries(names.map((name, i) => [name, `${i}.25`]));
    s.state.extension({ onCheck: () => undefined, onInput: s.onInput }).onInput!('q5', seed, typed);
    // no Finish: the page is gone once the state document is written
    await vi.waitFor(() => expect(store.state.size).toBe(1), { timeout: 10_000 });
    const again = await launch('u-3');
    const back = again.state.extension({ onCheck: () => undefined, onInput: () => undefined });
    expect(back.restore!('q5', seed)).toEqual(typed);
    const other = await launch('u-3', 'r-2');
    expect(
      other.state.extension({ onCheck: () => undefined, onInput: () => undefined }).restore!('q5', seed),
    ).toBeNull();
  });

  it('a record store that refuses statements is reported', async () => {
    const s = await launch('u-4');
    store.refuse.statements = true;
    expect(await check(s, 1)).toBe(false);
  });
});
