/**
 * cmi5 against a loopback test LRS (127.0.0.1 only, in this test): it serves the fetch URL (auth
 * token) and LMS.LaunchData, and records every statement. The AU is launched as an LMS would:
 * index.html?rml-au=q5 with endpoint, fetch, actor, registration and activityId. After a check and
 * Finish, the statements are Initialized, answered…, Passed or Failed, Completed, Terminated, each
 * cmi5-defined one carrying the context template (its session id and grouping), the registration
 * and the cmi5 category.
 */
import type { Server } from 'node:http';
import { test, expect, giveAnswer } from './fixtures';
import { haveSingle, packages, serve, unzip } from './lmsHost';
import { auId } from '../../src/lms/packages';
import { variantOf } from '../../src/lms/grade';
import { learnerSeed } from '../../src/lms/seeds';
import { expectedText } from '../../src/practice/check';
import { allAnswers } from '../../src/practice/model';

let ORIGIN = '';
const PKG_SEED = 5;
const REGISTRATION = '6b3d0f4e-5b4a-4d39-9f55-1f2a3c4d5e6f';
const SESSION = 'a1b2c3d4-0000-4000-8000-000000000001';
const COURSE = `https://render-math-lab.invalid/cmi5/${PKG_SEED}`;
const TOKEN = Buffer.from('au:secret').toString('base64');
const statements: Record<string, any>[] = [];
const stateDocs = new Map<string, unknown>();
const requests: string[] = [];
let server: Server | null = null;

const launchData = {
  contextTemplate: {
    contextActivities: { grouping: [{ objectType: 'Activity', id: `${COURSE}/q5` }] },
    extensions: { 'https://w3id.org/xapi/cmi5/context/extensions/sessionid': SESSION },
  },
  launchMode: 'Normal',
  launchMethod: 'AnyWindow',
  moveOn: 'CompletedAndPassed',
  masteryScore: 0.8,
};

test.beforeAll(async () => {
  test.skip(!haveSingle(), 'needs the single-file build (npm run build:single)');
  const files = new Map<string, Uint8Array | string>();
  const zip = unzip(packages(['q3', 'q5'], PKG_SEED)['practice-cmi5.zip']);
  for (const [name, bytes] of Object.entries(zip)) files.set(`/pkg/${name}`, bytes);
  files.set('/favicon.ico', '');
  ({ server, origin: ORIGIN } = await serve(files, (req, res, body) => {
    const url = new URL(req.url ?? '/', ORIGIN);
    requests.push(`${req.method} ${url.pathname}`);
    const json = (code: number, x: unknown) => {
      res.writeHead(code, { 'content-type': 'application/json', 'x-experience-api-version': '1.0.3' });
      res.end(JSON.stringify(x));
    };
    if (url.pathname === '/fetch' && req.method === 'POST') {
      json(200, { 'auth-token': TOKEN });
      return true;
    }
    if (!url.pathname.startsWith('/xapi/')) return false;
    if (req.headers.authorization !== `Basic ${TOKEN}`) {
      json(401, { error: 'no token' });
      return true;
    }
    if (url.pathname === '/xapi/activities/state') {
      // the state resource as xAPI 1.0.3 defines it: documents by stateId, a list without one
      const id = url.searchParams.get('stateId');
      if (req.method === 'GET' && id === 'LMS.LaunchData') json(200, launchData);
      else if (req.method === 'GET' && id === null) json(200, ['LMS.LaunchData', ...stateDocs.keys()]);
      else if (req.method === 'GET' && id !== null && stateDocs.has(id)) json(200, stateDocs.get(id));
      else if ((req.method === 'PUT' || req.method === 'POST') && id !== null) {
        stateDocs.set(id, JSON.parse(body));
        res.writeHead(204, { 'x-experience-api-version': '1.0.3' });
        res.end();
      } else json(404, {});
      return true;
    }
    if (url.pathname === '/xapi/agents/profile' && req.method === 'GET') {
      json(200, { languagePreference: 'en-US', audioPreference: 'on' });
      return true;
    }
    if (url.pathname === '/xapi/statements' && (req.method === 'POST' || req.method === 'PUT')) {
      const got = JSON.parse(body);
      const list = Array.isArray(got) ? got : [got];
      statements.push(...list);
      json(
        200,
        list.map((s: { id?: string }, i: number) => s.id ?? `id-${statements.length}-${i}`),
      );
      return true;
    }
    json(404, {});
    return true;
  }));
});

// each test is its own learner's first launch
test.beforeEach(() => stateDocs.clear());

test.afterAll(async () => {
  await new Promise<void>((ok) => (server ? server.close(() => ok()) : ok()));
});

test('cmi5: Initialized, answered, Passed or Failed, Completed, Terminated with the context template', async ({
  page,
}) => {
  test.setTimeout(120_000);
  const actor = {
    objectType: 'Agent',
    name: 'Test Learner',
    account: { homePage: 'https://lms.test', name: 'u-42' },
  };
  const activityId = auId({ seed: PKG_SEED }, 'q5');
  const qs = new URLSearchParams({
    'rml-au': 'q5',
    endpoint: `${ORIGIN}/xapi/`,
    fetch: `${ORIGIN}/fetch`,
    actor: JSON.stringify(actor),
    registration: REGISTRATION,
    activityId,
  });
  await page.goto(`${ORIGIN}/pkg/index.html?${qs.toString()}`);
  await expect(page.getByTestId('lms-status')).toHaveAttribute('data-state', 'connected', {
    timeout: 30_000,
  });
  const seed = learnerSeed('https://lms.test|u-42', 'q5', PKG_SEED);
  await expect(page.getByTestId('variant-seed')).toHaveText(String(seed));
  const answers = allAnswers(variantOf('q5', seed));
  const wrong = answers.find((a) => a.kind === 'number' && a.mistakes.length > 0)!;
  const mistake = wrong.kind === 'number' ? wrong.mistakes[0] : null;
  for (const a of answers)
    await giveAnswer(page, a.name, a === wrong ? String(mistake!.value) : expectedText(a));
  await page.getByRole('button', { name: 'Check' }).click();
  await expect(page.getByTestId(`verdict-${wrong.name}`)).toHaveAttribute(
    'data-value',
    `mistake:${mistake!.id}`,
  );
  const verb = (s: Record<string, any>) =>
    String(s.verb?.id ?? '')
      .split('/')
      .pop();
  await expect.poll(() => statements.map(verb), { timeout: 30_000 }).toContain('completed');
  await page.getByTestId('lms-finish').click();
  await expect.poll(() => statements.map(verb), { timeout: 30_000 }).toContain('terminated');

  expect(requests).toContain('POST /fetch');
  expect(requests).toContain('GET /xapi/activities/state');
  const verbs = statements.map(verb);
  const n = answers.length;
  const pass = (n - 1) / n >= 0.8;
  expect(verbs).toEqual([
    'initialized',
    ...Array(n).fill('answered'),
    pass ? 'passed' : 'failed',
    'completed',
    'terminated',
  ]);

  const CMI5_CATEGORY = 'https://w3id.org/xapi/cmi5/context/categories/cmi5';
  for (const s of statements) {
    expect(s.actor.account.name).toBe('u-42');
    expect(s.object.id.startsWith(activityId)).toBe(true);
    expect(s.context.registration).toBe(REGISTRATION);
    expect(s.context.extensions['https://w3id.org/xapi/cmi5/context/extensions/sessionid']).toBe(SESSION);
    expect(s.context.contextActivities.grouping.map((g: { id: string }) => g.id)).toContain(`${COURSE}/q5`);
  }
  for (const s of statements.filter((x) => verb(x) !== 'answered'))
    expect(s.context.contextActivities.category.map((c: { id: string }) => c.id)).toContain(CMI5_CATEGORY);
  const judged = statements.find((s) => verb(s) === (pass ? 'passed' : 'failed'))!;
  expect(judged.result.score.scaled).toBeCloseTo((n - 1) / n, 5);
  expect(judged.result.score.raw).toBe(n - 1);
  expect(judged.result.score.max).toBe(n);
  const named = statements.find((s) => verb(s) === 'answered' && s.object.id.endsWith(`-${wrong.name}`));
  expect(named?.result.success).toBe(false);
  expect(named?.result.response).toBe(String(mistake!.value));
  expect(named?.object.definition.description['en-US']).toContain(`mistake ${mistake!.id}`);
});
