/**
 * The host-page API, driven from the README's example page (examples/host.html) served on a second
 * local port, i.e. from another origin than the app, on one embedded scene: set → readouts change,
 * get, change events on a drag, an error naming a bad value, the timeline driven by the host,
 * requests from a window that is not the parent ignored, the height message (only height and
 * scene) following the content both ways, and origin= (well-formed, malformed) deciding who is
 * answered. The validation itself is unit-tested (tests/app/hostApi.test.ts, hostCheck.test.ts,
 * tests/scenes/<id>/hostSet.test.ts); the pasted "Copy embed code" snippet: shell.spec.ts.
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

test('the example host page: set, get, subscribe, change events and errors; the timeline; invalid values; other windows ignored; the height both ways; origin=', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await page.setViewportSize({ width: 1400, height: 900 });
  const frame = await openHost(page, '#/texture?embed=1');
  const f = page.frames().find((x) => x.url().startsWith(`http://127.0.0.1:${appPort}/`))!;
  const bilinear = () => frame.getByTestId('bilinear').first().getAttribute('data-value');
  const events = () =>
    page.evaluate(() =>
      (window as unknown as { rml: { received: Msg[] } }).rml.received.filter((m) => m.type === 'event'),
    );
  // the host page sets the iframe's width (the scene's layout, and so its height, follows)
  const setWidth = (w: number) =>
    page.evaluate((w) => {
      (document.getElementById('scene') as HTMLIFrameElement).style.width = `${w}px`;
    }, w);

  await test.step('the example host page sets, gets and subscribes; bad values answer an error naming them', async () => {
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
    // the framed page may still be settling (parts mounting, formulas typeset above the grid):
    // measure the grid once it has stopped moving
    let box = (await grid.boundingBox())!;
    await expect
      .poll(async () => {
        const b = (await grid.boundingBox())!;
        const still = b.x === box.x && b.y === box.y && b.width === box.width;
        box = b;
        return still;
      })
      .toBe(true);
    await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.75, box.y + box.height * 0.25, { steps: 5 });
    await page.mouse.up();
    // the drag sends an event per step on its way; wait for the one where it ended
    type UserEvent = { state: { scene: string; params: { u: number } } };
    const userEvents = async () => (await events()).filter((e) => e.cause === 'user') as UserEvent[];
    await expect
      .poll(async () => {
        const user = await userEvents();
        return user.length > n0 ? user.at(-1)!.state.params.u : null;
      })
      .toBeCloseTo(-0.08 + 1.16 * 0.75, 1);
    const last = (await userEvents()).at(-1)!;
    expect(last.state.scene).toBe('texture');
    expect((await api<Reply>(page, 'get')).state!.params.u).toBe(last.state.params.u);

    // a practice verdict (the practice pages dispatch rml:practice-verdict) reaches the subscriber as
    // plain data; only the four fields, strings capped
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

  await test.step('the host drives the shared animation timeline: seek, play and pause', async () => {
    // from the start of the path
    expect((await api<Reply>(page, 'seek', 0)).ok).toBe(true);
    const timeline = frame.getByTestId('timeline').first();
    await expect(timeline).toBeVisible({ timeout: 30000 });
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

  await test.step('set fails, applying nothing, for every parameter’s invalid values', async () => {
    // every parameter of every scene against the invalid values its spec implies is a unit test
    // (tests/app/hostCheck.test.ts, the same validation the page runs), and so are the values a scene
    // would replace by a fallback (tests/scenes/<id>/hostSet.test.ts); here the wiring on one scene:
    // the page refuses them, applies nothing and shows no notice
    for (const scene of SCENES.filter((s) => s.id === 'texture')) {
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
  });

  await test.step('requests from a window that is not the parent are ignored; height messages carry no URL', async () => {
    const u = (await api<Reply>(page, 'get')).state!.params.u;
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
    expect(got.state!.params.u).toBe(u);
    const received = await page.evaluate(
      () => (window as unknown as { rml: { received: Msg[] } }).rml.received,
    );
    expect(received.some((m) => m.id === 'intruder')).toBe(false);
    await expect(frame.getByTestId('u-slider')).toHaveValue(String(u));

    // the height message: only type, height and scene
    const heights = received.filter((m) => m.type === 'render-math-lab:height');
    expect(heights.length).toBeGreaterThan(0);
    for (const h of heights) expect(Object.keys(h).sort()).toEqual(['height', 'scene', 'type']);
    expect(heights.at(-1)!.scene).toBe('texture');
    expect(JSON.stringify(received.filter((m) => m.type === 'render-math-lab:height'))).not.toContain('http');
  });

  await test.step('the posted height follows the content both ways: it shrinks as well as grows when the host resizes the iframe', async () => {
    const lastHeight = () =>
      page.evaluate(
        () =>
          ((window as unknown as { rml: { received: Msg[] } }).rml.received
            .filter((m) => m.type === 'render-math-lab:height')
            .at(-1)?.height as number | undefined) ?? 0,
      );
    // the embedded page's content height (what the posted height must follow)
    const content = () =>
      f.evaluate(() =>
        Math.ceil(document.getElementById('root')!.getBoundingClientRect().bottom + window.scrollY),
      );
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

  // origin= names who is answered: the link changes in the frame (a new hash, the same page)
  const navigateScene = (hash: string) =>
    page.evaluate((src) => {
      (document.getElementById('scene') as HTMLIFrameElement).src = src;
    }, `http://127.0.0.1:${appPort}/app/${hash}`);
  const heard = () =>
    page.evaluate(
      () =>
        (window as unknown as { rml: { received: Msg[] } }).rml.received.filter(
          (m) => m.type === 'render-math-lab:height' || m.type === 'reply',
        ).length,
    );
  /** Sends a request and says whether it was answered within 2.5 s. */
  const answered = (fn: 'get' | 'set') =>
    page.evaluate(
      (fn) =>
        Promise.race([
          (window as unknown as { rml: Record<string, (p?: unknown) => Promise<unknown>> }).rml[fn]({
            u: 0.9,
          }).then(() => 'answered'),
          new Promise((ok) => setTimeout(() => ok('ignored'), 2500)),
        ]),
      fn,
    );

  await test.step('with origin= the scene answers only that origin: no reply, no height message', async () => {
    await navigateScene(`#/texture?embed=1&origin=${encodeURIComponent('https://lms.example.edu')}`);
    // the new address is taken in a later task (a hashchange, then a render): until then the scene
    // still answers everyone, and a resize still posts its height to '*'. It has taken it once the
    // host page's own requests go unanswered.
    await expect.poll(() => answered('get'), { timeout: 30_000 }).toBe('ignored');
    await expect(frame.locator('[data-deferred="pending"], .math-pending')).toHaveCount(0, {
      timeout: 30000,
    });
    const n = await heard();
    // a height change would be posted: it goes to the allowed origin only
    await setWidth(1000);
    // the host page's own origin is not the allowed one: its request times out unanswered
    expect(await answered('get')).toBe('ignored');
    expect(await heard()).toBe(n);
  });

  await test.step('a malformed origin= never opens the scene up: nobody is answered, and the page says so', async () => {
    // which values are malformed is the parser's (tests/app/hostApi.test.ts, origin=); here the
    // wiring: one that names nobody (a wildcard) answers nobody
    await navigateScene(`#/texture?embed=1&origin=${encodeURIComponent('*')}`);
    await expect(frame.getByTestId('param-notice')).toContainText('no usable origin');
    const n = await heard();
    await setWidth(700);
    expect(await answered('set')).toBe('ignored');
    // nothing was applied, and no height message or reply was posted (to '*' or anywhere)
    expect(await heard()).toBe(n);
    expect(await f.evaluate(() => window.location.hash)).not.toContain('u=0.9');
  });
});
