/**
 * The host-page API, driven from the README's example page (examples/host.html) served on a second
 * local port, i.e. from another origin than the app: set → readouts change, get, change events on
 * a drag, an error naming a bad value, requests from a window that is not the parent ignored, and
 * the height message (only height and scene) following the content both ways.
 */
import { createServer, type Server } from 'node:http';
import { readFile } from 'node:fs/promises';
import { resolve } from 'node:path';
import type { Frame, Page } from '@playwright/test';
import { test, expect } from './fixtures';
import { SCENES, invalidValues, sceneSchema } from './sceneSchemas';

const appPort = Number(process.env.E2E_PORT ?? 4317);
let hostPort = 0; // an ephemeral port, chosen by the system (no clash with parallel runs)
let hostOrigin = '';
let server: Server;

test.beforeAll(async () => {
  const file = resolve('examples/host.html');
  server = createServer(async (req, res) => {
    if ((req.url ?? '').split('?')[0] === '/host.html') {
      res.writeHead(200, { 'content-type': 'text/html; charset=utf-8', 'cache-control': 'no-store' });
      res.end(await readFile(file));
    } else {
      res.writeHead(404);
      res.end();
    }
  });
  await new Promise<void>((ok) => server.listen(0, '127.0.0.1', ok));
  hostPort = (server.address() as { port: number }).port;
  hostOrigin = `http://127.0.0.1:${hostPort}`;
});
test.afterAll(async () => {
  await new Promise<void>((ok) => server.close(() => ok()));
});

type Reply = {
  protocol: string;
  version: number;
  id: unknown;
  type: string;
  ok: boolean;
  error?: string;
  state?: { scene: string; params: Record<string, unknown>; query: string };
};
type Msg = Record<string, unknown>;

async function openHost(page: Page, sceneHash: string): Promise<Frame> {
  const src = `http://127.0.0.1:${appPort}/app/${sceneHash}`;
  await page.goto(`${hostOrigin}/host.html?src=${encodeURIComponent(src)}`);
  const frame = page.frameLocator('#scene');
  await expect(frame.getByTestId('copy-link')).toBeVisible({ timeout: 30000 });
  const f = page.frames().find((x) => x.url().startsWith(`http://127.0.0.1:${appPort}/`));
  expect(f).toBeTruthy();
  // the scene's later sections mount, and its formulas are typeset, in idle time: wait for both
  // (src/ui/Deferred.tsx, src/ui/MathTex.tsx), so heights measured from here on are final
  await expect(frame.locator('[data-deferred="pending"], .math-pending')).toHaveCount(0, { timeout: 30000 });
  return f!;
}

const api = <T>(page: Page, fn: string, arg?: unknown) =>
  page.evaluate(
    ([fn, arg]) =>
      (window as unknown as { rml: Record<string, (a?: unknown) => Promise<unknown>> }).rml[fn as string](
        arg,
      ),
    [fn, arg] as const,
  ) as Promise<T>;

test('the example host page sets, gets and subscribes; bad values answer an error naming them', async ({
  page,
}) => {
  const frame = await openHost(page, '#/texture?embed=1');
  const bilinear = () => frame.getByTestId('bilinear').first().getAttribute('data-value');
  const before = await bilinear();

  // get: the scene's parameters, typed
  const got = await api<Reply>(page, 'get');
  expect(got).toMatchObject({
    protocol: 'render-math-lab',
    version: 1,
    type: 'reply',
    ok: true,
    id: expect.stringMatching(/^req-/),
  });
  expect(got.state!.scene).toBe('texture');
  expect(got.state!.params.u).toBe(0.4);
  expect(got.state!.params.wrap).toBe('clamp');

  // subscribe, then set: the readouts change, and get returns the new values
  const sub = await api<Reply>(page, 'subscribe');
  expect(sub.ok).toBe(true);
  const set = await api<Reply>(page, 'set', { u: 0.7, v: 0.3, wrap: 'repeat' });
  expect(set.ok, set.error).toBe(true);
  expect(set.state!.params).toMatchObject({ u: 0.7, v: 0.3, wrap: 'repeat' });
  await expect.poll(bilinear).not.toBe(before);
  const after = await bilinear();
  await expect(frame.getByTestId('u-slider')).toHaveValue('0.7');
  const got2 = await api<Reply>(page, 'get');
  expect(got2.state!.params).toMatchObject({ u: 0.7, v: 0.3, wrap: 'repeat' });
  expect(got2.state!.query).toContain('u=0.7');
  // the host's change was announced as an event caused by the host
  const events = () =>
    page.evaluate(() =>
      (window as unknown as { rml: { received: Msg[] } }).rml.received.filter((m) => m.type === 'event'),
    );
  await expect
    .poll(async () => (await events()).some((e) => e.event === 'change' && e.cause === 'host'))
    .toBe(true);

  // a bad value: an error naming it, and nothing applied (not even the good value beside it)
  const bad = await api<Reply>(page, 'set', { u: 0.1, wrap: 'sideways' });
  expect(bad.ok).toBe(false);
  expect(bad.error).toContain('wrap');
  expect(bad.error).toContain('sideways');
  const bad2 = await api<Reply>(page, 'set', { u: 'abc' });
  expect(bad2.ok).toBe(false);
  expect(bad2.error).toMatch(/u .*abc/);
  const bad3 = await api<Reply>(page, 'set', { nonsense: 1, toString: 2 });
  expect(bad3.ok).toBe(false);
  expect(bad3.error).toContain('nonsense');
  expect(bad3.error).toContain('toString');
  expect((await api<Reply>(page, 'get')).state!.params.u).toBe(0.7);
  expect(await bilinear()).toBe(after);

  // play/pause are sets of the animation's play parameter (the texture scene has the shared timeline;
  // the next test drives it in detail)
  const play = await api<Reply>(page, 'play');
  expect(play.ok, play.error).toBe(true);
  expect(play.state!.params.play).toBe(true);
  const pause = await api<Reply>(page, 'pause');
  expect(pause.ok, pause.error).toBe(true);
  expect(pause.state!.params.play).toBe(false);

  // a user drag in the scene: change events carrying the new state
  const n0 = (await events()).filter((e) => e.cause === 'user').length;
  const grid = frame.getByTestId('texel-grid');
  await grid.scrollIntoViewIfNeeded();
  const box = (await grid.boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.75, box.y + box.height * 0.25, { steps: 5 });
  await page.mouse.up();
  await expect
    .poll(async () => (await events()).filter((e) => e.cause === 'user').length)
    .toBeGreaterThan(n0);
  const last = (await events()).filter((e) => e.cause === 'user').at(-1) as {
    state: { scene: string; params: { u: number } };
  };
  expect(last.state.scene).toBe('texture');
  expect(last.state.params.u).toBeCloseTo(-0.08 + 1.16 * 0.75, 1);
  expect((await api<Reply>(page, 'get')).state!.params.u).toBe(last.state.params.u);

  // a practice verdict (the practice pages dispatch rml:practice-verdict) reaches the subscriber as
  // plain data; only the four fields, strings capped
  const f = page.frames().find((x) => x.url().startsWith(`http://127.0.0.1:${appPort}/`))!;
  await f.evaluate(() =>
    window.dispatchEvent(
      new CustomEvent('rml:practice-verdict', {
        detail: { question: 'Q3b', seed: 42, name: 'bilinear', verdict: 'correct', extra: '<img src=x>' },
      }),
    ),
  );
  await expect
    .poll(async () => (await events()).find((e) => e.event === 'practice-verdict')?.verdict ?? null)
    .toEqual({ question: 'Q3b', seed: 42, name: 'bilinear', verdict: 'correct' });
});

test('requests from a window that is not the parent are ignored; height messages carry no URL', async ({
  page,
}) => {
  const frame = await openHost(page, '#/texture?embed=1&u=0.2');
  // a sibling frame of the host's origin (not the scene's parent) sends a set
  await page.evaluate(() => {
    const sib = document.createElement('iframe');
    sib.id = 'sibling';
    sib.srcdoc = '<p>other</p>';
    document.body.append(sib);
    return new Promise((ok) => (sib.onload = ok));
  });
  await page.evaluate(() => {
    const scene = (document.getElementById('scene') as HTMLIFrameElement).contentWindow!;
    const sib = (document.getElementById('sibling') as HTMLIFrameElement).contentWindow as Window & {
      eval: (s: string) => unknown;
    };
    (sib as unknown as { target: Window }).target = scene;
    sib.eval(
      `target.postMessage({ protocol: 'render-math-lab', version: 1, id: 'intruder', type: 'set', params: { u: 0.9 } }, '*')`,
    );
  });
  // a later request from the parent is answered; the intruder's never was, and changed nothing
  const got = await api<Reply>(page, 'get');
  expect(got.state!.params.u).toBe(0.2);
  const received = await page.evaluate(
    () => (window as unknown as { rml: { received: Msg[] } }).rml.received,
  );
  expect(received.some((m) => m.id === 'intruder')).toBe(false);
  await expect(frame.getByTestId('u-slider')).toHaveValue('0.2');

  // the height message: only type, height and scene
  const heights = received.filter((m) => m.type === 'render-math-lab:height');
  expect(heights.length).toBeGreaterThan(0);
  for (const h of heights) expect(Object.keys(h).sort()).toEqual(['height', 'scene', 'type']);
  expect(heights.at(-1)!.scene).toBe('texture');
  expect(JSON.stringify(received.filter((m) => m.type === 'render-math-lab:height'))).not.toContain('http');
});

test('with origin= the scene answers only that origin', async ({ page }) => {
  await openHost(page, `#/texture?embed=1&origin=${encodeURIComponent('https://lms.example.edu')}`);
  // the host page's own origin is not the allowed one: its request times out unanswered
  const r = await page.evaluate(() =>
    Promise.race([
      (window as unknown as { rml: { get: () => Promise<unknown> } }).rml.get().then(() => 'answered'),
      new Promise((ok) => setTimeout(() => ok('ignored'), 2500)),
    ]),
  );
  expect(r).toBe('ignored');
  // and no height message reaches it either (they go to the allowed origin only)
  const heights = await page.evaluate(
    () =>
      (window as unknown as { rml: { received: Msg[] } }).rml.received.filter(
        (m) => m.type === 'render-math-lab:height',
      ).length,
  );
  expect(heights).toBe(0);
});

test('a malformed origin= never opens the scene up: nobody is answered, and the page says so', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // which values are malformed is the parser's (tests/app/hostApi.test.ts, origin=); here the
  // wiring: one that names nobody (a wildcard) answers nobody
  for (const raw of ['*']) {
    await openHost(page, `#/texture?embed=1&origin=${encodeURIComponent(raw)}`);
    const frame = page.frameLocator('#scene');
    await expect(frame.getByTestId('param-notice'), raw).toContainText('no usable origin');
    const r = await page.evaluate(() =>
      Promise.race([
        (window as unknown as { rml: { set: (p: unknown) => Promise<unknown> } }).rml
          .set({ u: 0.9 })
          .then(() => 'answered'),
        new Promise((ok) => setTimeout(() => ok('ignored'), 2500)),
      ]),
    );
    expect(r, raw).toBe('ignored');
    // nothing was applied, and no height message was posted (to '*' or anywhere)
    const got = await page.evaluate(
      () =>
        (window as unknown as { rml: { received: Msg[] } }).rml.received.filter(
          (m) => m.type === 'render-math-lab:height' || m.type === 'reply',
        ).length,
    );
    expect(got, raw).toBe(0);
    const f = page.frames().find((x) => x.url().startsWith(`http://127.0.0.1:${appPort}/`))!;
    expect(await f.evaluate(() => window.location.hash), raw).not.toContain('u=0.9');
  }
});

test('set fails, applying nothing, for every parameter’s invalid values on every scene, and for values the scene would replace', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // every parameter of every scene against the invalid values its spec implies is a unit test
  // (tests/app/hostCheck.test.ts, the same validation the page runs); here the wiring on one scene:
  // the page refuses them, applies nothing and shows no notice
  for (const scene of SCENES.filter((s) => s.id === 'texture')) {
    await openHost(page, `#${scene.path}?embed=1`);
    const before = await api<Reply>(page, 'get');
    for (const [name, spec] of Object.entries(await sceneSchema(scene.id)))
      for (const bad of invalidValues(spec)) {
        const r = await api<Reply>(page, 'set', { [name]: bad });
        expect(r.ok, `${scene.id}: set ${name} = ${JSON.stringify(bad)}`).toBe(false);
        expect(r.error, `${scene.id}: set ${name} = ${JSON.stringify(bad)}`).toContain(name);
      }
    expect((await api<Reply>(page, 'get')).state, `${scene.id}: nothing applied`).toEqual(before.state);
    await expect(page.frameLocator('#scene').getByTestId('param-notice')).toHaveCount(0);
  }
  // a value the URL parser takes but the scene would replace by a fallback (its own check decides;
  // each scene's cases: tests/scenes/<id>/hostSet.test.ts), here a typed density that is no density
  await openHost(page, '#/hemisphere?embed=1');
  const before = await api<Reply>(page, 'get');
  for (const params of [
    { lobe: 'custom', pdf: '-1' },
    { lobe: 'custom', pdf: 'import(1)' },
  ]) {
    const r = await api<Reply>(page, 'set', params);
    expect(r.ok, JSON.stringify(params)).toBe(false);
    expect(r.error).toContain('pdf');
  }
  expect((await api<Reply>(page, 'get')).state, 'nothing applied').toEqual(before.state);
  await expect(page.frameLocator('#scene').getByTestId('param-notice')).toHaveCount(0);
  // a version sent as a string is told how to send it
  const v = await page.evaluate(
    () =>
      new Promise<Reply>((ok) => {
        const w = window as unknown as { rml: { received: Msg[] } };
        const frame = document.querySelector<HTMLIFrameElement>('#scene')!;
        const n = w.rml.received.length;
        frame.contentWindow!.postMessage(
          { protocol: 'render-math-lab', version: '1', id: 'v1', type: 'get' },
          '*',
        );
        const t = setInterval(() => {
          const m = w.rml.received.slice(n).find((x) => x.id === 'v1');
          if (m) {
            clearInterval(t);
            ok(m as unknown as Reply);
          }
        }, 50);
      }),
  );
  expect(v.ok).toBe(false);
  expect(v.error).toMatch(/"1" is a string; send version: 1/);
  // a usable change on the same page still applies
  const ok = await api<Reply>(page, 'set', { lobe: 'custom', pdf: 'cos(theta)' });
  expect(ok.ok, ok.error).toBe(true);
});

test('the posted height follows the content both ways: it shrinks as well as grows when the host resizes the iframe', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1400, height: 900 });
  await openHost(page, '#/texture?embed=1');
  const lastHeight = () =>
    page.evaluate(
      () =>
        ((window as unknown as { rml: { received: Msg[] } }).rml.received
          .filter((m) => m.type === 'render-math-lab:height')
          .at(-1)?.height as number | undefined) ?? 0,
    );
  const f = page.frames().find((x) => x.url().startsWith(`http://127.0.0.1:${appPort}/`))!;
  // the embedded page's content height (what the posted height must follow)
  const content = () =>
    f.evaluate(() =>
      Math.ceil(document.getElementById('root')!.getBoundingClientRect().bottom + window.scrollY),
    );
  const setWidth = (w: number) =>
    page.evaluate((w) => {
      (document.getElementById('scene') as HTMLIFrameElement).style.width = `${w}px`;
    }, w);
  // settle at a width: the posted height equals the content's height there
  const settle = async () => {
    await expect
      .poll(async () => Math.abs((await lastHeight()) - (await content())), { timeout: 20000 })
      .toBeLessThanOrEqual(1);
    return lastHeight();
  };
  await setWidth(380);
  const narrow = await settle();
  expect(narrow).toBeGreaterThan(1500);
  // the host page applies it: the iframe is as tall as the narrow layout
  await expect
    .poll(() =>
      page.evaluate(
        () => (document.getElementById('scene') as HTMLIFrameElement).getBoundingClientRect().height,
      ),
    )
    .toBeGreaterThan(narrow - 5);
  await setWidth(1300);
  const wide = await settle();
  expect(Math.abs(wide - narrow), 'the two layouts differ in height').toBeGreaterThan(50);
  // and back: one of the two steps made the content shorter, and the posted height followed it down
  await setWidth(380);
  const again = await settle();
  expect(again).toBeLessThanOrEqual(narrow + 1);
  expect(again).toBeGreaterThanOrEqual(narrow - 1);
});

test('"Copy embed code" gives an iframe with an id and the listener that sizes it', async ({
  page,
  context,
}) => {
  const app = await context.newPage();
  await app.goto(`http://127.0.0.1:${appPort}/app/#/texture?u=0.7`);
  await app.getByTestId('copy-embed').click();
  const code = await app.evaluate(() => navigator.clipboard.readText());
  await app.close();
  const id = /<iframe id="(rml-texture-[a-z0-9]+)"/.exec(code)?.[1];
  expect(id, code).toBeTruthy();
  expect(code).toContain('render-math-lab:height');
  expect(code).toContain(`getElementById('${id}')`);
  // pasted into a page as it is, the snippet sizes the iframe to the scene's content
  await page.setContent(`<!doctype html><body style="margin:0">${code}</body>`);
  const frame = page.frameLocator(`#${id}`);
  await expect(frame.getByTestId('bilinear').first()).toBeVisible({ timeout: 30000 });
  await expect(frame.getByTestId('u-slider')).toHaveValue('0.7');
  const f = page.frames().find((x) => x.url().includes('/app/'))!;
  const content = () =>
    f.evaluate(() =>
      Math.ceil(document.getElementById('root')!.getBoundingClientRect().bottom + window.scrollY),
    );
  await expect
    .poll(
      async () =>
        Math.abs(
          (await page.locator(`#${id}`).evaluate((el) => el.getBoundingClientRect().height)) -
            (await content()),
        ),
      { timeout: 20000 },
    )
    .toBeLessThanOrEqual(1);
  expect(await content()).toBeGreaterThan(720);
});

test('the host drives the shared animation timeline: seek, play and pause', async ({ page }) => {
  const frame = await openHost(page, '#/texture?embed=1');
  const timeline = frame.getByTestId('timeline').first();
  await expect(timeline).toBeVisible({ timeout: 30000 });
  const bilinear = () => frame.getByTestId('bilinear').first().getAttribute('data-value');
  const atStart = await bilinear();

  // seek: the timeline moves to t and the readouts follow the query's new position on the path
  const seek = await api<Reply>(page, 'seek', 0.5);
  expect(seek.ok, seek.error).toBe(true);
  expect(seek.state!.params.t).toBe(0.5);
  await expect(timeline).toHaveAttribute('data-t', '0.5');
  await expect.poll(bilinear).not.toBe(atStart);

  // play: the position advances; pause: it stops, and the paused position is the state's t
  const play = await api<Reply>(page, 'play');
  expect(play.ok, play.error).toBe(true);
  await expect(timeline).toHaveAttribute('data-playing', '1');
  await expect
    .poll(async () => Number(await timeline.getAttribute('data-t')), { timeout: 30000 })
    .not.toBe(0.5);
  const pause = await api<Reply>(page, 'pause');
  expect(pause.ok, pause.error).toBe(true);
  await expect(timeline).toHaveAttribute('data-playing', '0');
  const shown = Number(await timeline.getAttribute('data-t'));
  await expect.poll(async () => (await api<Reply>(page, 'get')).state!.params.t).toBe(shown);

  // a bad position is refused with a message naming t, and nothing moves
  const bad = await api<Reply>(page, 'seek', 7);
  expect(bad.ok).toBe(false);
  expect(bad.error).toMatch(/\bt\b/);
  await expect(timeline).toHaveAttribute('data-t', String(shown));
});
