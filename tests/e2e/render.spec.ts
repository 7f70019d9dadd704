// #/render in the browser, one page opened once and then led by links: the pixel inspector's
// readouts are the core's inspector for the same link (computed here in Node), the progressive CPU
// render runs in workers to its spp while the page answers input, the equal-time, spread and
// Welch folds mount on open, run their workers and follow the link, and the GPU renderer (the
// default; SwiftShader here) draws the image, agrees with the CPU's in the compare fold, holds
// where a pause leaves it (t), and gives way to the CPU, with a notice, where it cannot run. The
// steps that test the CPU side (the inspector, the workers, the folds) name renderer=cpu, so that
// no shader compiles beside them. The estimators, the renderer and the page's logic are unit tests
// (tests/core/render/, tests/scenes/render/), the folds' markup Node tests (tests/render/); the page
// as a reader meets it, every fold open, is in wcag.spec.ts; the FLIP of downloaded images is
// checked on #/area-light (area-light.spec.ts).
import { test, expect, followLinkAnew, openScene, readout, waitForReadout } from './fixtures';
import { parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/render/params';
import { buildRenderModel } from '../../src/scenes/render/model';
import { inspectArgs, inspectOptions } from '../../src/scenes/render/jobArgs';
import { inspectPixel } from '../../src/core/render/inspector';
import { buildScene } from '../../src/core/render/scene';
import { recordFirstScreen } from './firstScreen';

test('render lab: the pixel inspector, the progressive render in workers, and the equal-time and spread folds', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await test.step('the pixel readouts are the core inspector’s for the link', async () => {
    const query = 'px=64,60&pn=1024&spp=1&res=128&renderer=cpu';
    const m = buildRenderModel(parseParams(schema, query).values);
    const a = inspectArgs(m)!;
    const want = inspectPixel(buildScene(m.spec), m.view, a.px[0], a.px[1], inspectOptions(a));
    expect(want.hit).toBe('sphere');
    await openScene(page, `#/render?${query}`);
    await expect(page.getByTestId('pixel-inspector')).toBeVisible({ timeout: 15_000 });
    expect(await readout(page, 'pixel-hit')).toBe(want.hit);
    expect(await readout(page, 'pixel-reference-kind')).toBe(want.referenceKind);
    // numbers agree to the last few ulps: the browser's Math.sin, Math.pow … may round differently from Node's
    const expected: Record<string, readonly number[]> = {
      'pixel-o': want.o,
      'pixel-d': want.d,
      'pixel-discriminant': [want.discriminant!],
      'pixel-t': [want.t!],
      'pixel-p': want.p!,
      'pixel-u': [want.u!],
      'pixel-v': [want.v!],
      'pixel-texel': [want.texel!],
      'pixel-estimate': [want.estimate],
      'pixel-stderr': [want.stderr],
      'pixel-n': [want.n],
      'pixel-reference': [want.reference],
    };
    for (const [id, xs] of Object.entries(expected)) {
      const got = (await readout(page, id)).split(',').map(Number);
      expect(got.length, id).toBe(xs.length);
      got.forEach((g, k) =>
        expect(Math.abs(g - xs[k]), `${id}[${k}] = ${g}, core ${xs[k]}`).toBeLessThanOrEqual(
          1e-12 * Math.max(1, Math.abs(xs[k])),
        ),
      );
    }
    await expect(page.getByTestId('pixel-samples').locator('tbody tr')).toHaveCount(want.rows.length);
  });

  await test.step('the progressive render reaches spp in workers while the page answers input', async () => {
    await openScene(page, '#/render?res=64&spp=8&renderer=cpu');
    await expect(page.getByTestId('renderer')).toHaveAttribute('data-value', 'cpu');
    // input while the workers render: a click on the image opens its pixel, the settings unfold
    const canvas = page.getByTestId('render-canvas');
    await canvas.click({ position: { x: 5, y: 5 } });
    await page.getByText('Settings', { exact: true }).click();
    await expect(page.getByTestId('render-settings')).toHaveAttribute('open', '');
    await expect(page.getByTestId('pixel-hit')).toHaveAttribute('data-value', /^(floor|none|light|sphere)$/);
    // (the render runs while the image is on screen: bring it back after the settings unfold)
    await canvas.scrollIntoViewIfNeeded();
    // (the status first: where the run stops short, it says whether it waits for the screen)
    await expect(page.getByTestId('render-status')).toHaveText(/^Done: 8 samples per pixel\.$/, {
      timeout: 15_000,
    });
    await expect(page.getByTestId('spp')).toHaveAttribute('data-value', '8');
    expect(Number(await readout(page, 'samples-per-second'))).toBeGreaterThan(0);
    // the canvas holds the image: its pixels are not all black
    const lit = await canvas.evaluate((c: HTMLCanvasElement) => {
      const d = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let k = 0; k < d.length; k += 4) if (d[k] > 0) n++;
      return n;
    });
    expect(lit).toBeGreaterThan(64 * 64 * 0.5);
    await expect(page.getByTestId('render-description')).toContainText('after 8 samples per pixel');
    // the finished image measured against the reference: FLIP of the pixels shown, and its downloads
    await page.getByTestId('measure-details').locator('summary').click();
    const flip = Number(
      await waitForReadout(page, 'flip-mean', (v) => Number.isFinite(Number(v)) && v !== '', 30_000),
    );
    expect(flip > 0 && flip < 1, `flip-mean = ${flip}`).toBe(true);
  });

  await test.step('equal time and the error from independent runs: folds that mount on open and stay open in the link', async () => {
    await openScene(page, '#/render?res=32&spp=1&renderer=cpu');
    const fold = page.getByTestId('fold-equal-time');
    await expect(fold).not.toHaveAttribute('open', /.*/);
    await expect(page.getByTestId('equal-time')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=equal-time(&|$)/);
    await page.getByTestId('et-budget').selectOption('250');
    await expect(page).toHaveURL(/[?&]et=250(&|$)/);
    await expect(page.getByTestId('et-status')).toHaveText(/^Done: 7 strategies/, { timeout: 60_000 });
    const ranking = (await page.getByTestId('et-ranking').getAttribute('data-value'))!.split(',');
    expect(ranking).toHaveLength(7);
    const errors = await Promise.all(ranking.map(async (s) => Number(await readout(page, `et-relmse-${s}`))));
    for (const e of errors) expect(Number.isFinite(e) && e > 0).toBe(true);
    expect([...errors].sort((a, b) => a - b)).toEqual(errors);
    await expect(page.getByTestId('et-plot')).toBeVisible();
    // and each strategy's perceived error, FLIP of the images as shown, with its own plot
    for (const s of ranking) {
      const f = Number(await readout(page, `et-flip-${s}`));
      expect(f > 0 && f < 1, `et-flip-${s} = ${f}`).toBe(true);
    }
    await expect(page.getByTestId('et-flip-plot')).toBeVisible();
    // the error without a reference: K runs in a worker; an unbiased estimator's spread predicts its error
    await page.getByTestId('fold-spread').locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=equal-time,spread(&|$)/);
    await expect(page.getByTestId('spread-status')).toHaveText(/^Done: 8 runs/, { timeout: 60_000 });
    const expected = Number(await readout(page, 'spread-expected-mse'));
    const measured = Number(await readout(page, 'spread-measured-mse'));
    expect(expected).toBeGreaterThan(0);
    expect(measured / expected).toBeGreaterThan(0.5);
    expect(measured / expected).toBeLessThan(1.5);
    // a link opens the folds it names and only those (here the Welch fold alone: the equal-time
    // runs are not started again)
    await openScene(page, '#/render?res=32&spp=1&renderer=cpu&open=welch');
    await expect(page.getByTestId('fold-welch')).toHaveAttribute('open', '');
    await expect(page.getByTestId('fold-equal-time')).not.toHaveAttribute('open', /.*/);
    await expect(page.getByTestId('fold-spread')).not.toHaveAttribute('open', /.*/);
    // two estimators pixel by pixel: the page's (mis-power) and area sampling agree
    await expect(page.getByTestId('welch-status')).toHaveText(/^Done: 8 runs/, { timeout: 60_000 });
    await expect(page.getByTestId('welch-verdict')).toHaveAttribute('data-value', 'pass');
    expect(Number(await readout(page, 'welch-rejected'))).toBe(0);
    // (that the fold's run follows the link, its bias and its other strategy, and that a biased
    // estimator fails: tests/render/welchFold.test.tsx and tests/core/render/welchCompare.test.ts)
  });

  await test.step('the GPU renderer: the default, a paused link holds where it says, its image agrees with the CPU’s within its noise, and a pause writes where the run is', async () => {
    // a paused link followed anew (the lab mounts from the link alone): the GPU's image holds at t.
    // (The shader compiles once, here, about 3 s on SwiftShader; the links below keep the image's
    // size, so the lab keeps its GPU worker.)
    await followLinkAnew(page, '#/render?res=32&spp=4096&play=0&t=5');
    await expect(page.getByTestId('render-status')).toHaveText(
      'Paused at 5 of 4096 samples per pixel (play=0, t=5).',
      { timeout: 30_000 },
    );
    await expect(page.getByTestId('renderer')).toHaveAttribute('data-value', 'gpu');
    // the exam scene with mis-power: the image, then both renderers side by side
    await openScene(page, '#/render?res=32&spp=8&px=16,14&open=compare');
    await page.evaluate(() => window.scrollTo(0, 0));
    await expect(page.getByTestId('renderer')).toHaveAttribute('data-value', 'gpu');
    await expect(page.getByTestId('render-gpu-unavailable')).toHaveCount(0);
    await expect(page.getByTestId('render-status')).toHaveText(/^Done: 8 samples per pixel\.$/, {
      timeout: 30_000,
    });
    // not blank: the sums read back from the float target have a positive mean and an error
    await expect(page.getByTestId('render-description')).toContainText('after 8 samples per pixel');
    const mean = Number(
      /Mean brightness ([0-9.]+)/.exec(await page.getByTestId('render-description').innerText())?.[1],
    );
    expect(mean).toBeGreaterThan(0.005);
    expect(Number(await waitForReadout(page, 'rel-mse', (v) => v !== 'none'))).toBeGreaterThan(0);
    await expect(page.getByTestId('compare-verdict')).toHaveAttribute('data-value', 'pass', {
      timeout: 30_000,
    });
    expect(Number(await readout(page, 'compare-chi2-p'))).toBeGreaterThanOrEqual(0.001);
    // one pixel of the GPU's image, read back, against the CPU's in the fold's terms
    expect(Math.abs(Number(await readout(page, 'compare-pixel-z')))).toBeLessThan(4);
    expect(Number(await readout(page, 'compare-pixel-gpu'))).toBeGreaterThan(0);
    // the main image's price of float32 at its last read-back (a number, not none, on the GPU)
    expect(Number(await readout(page, 'f32-naive-error'))).toBeGreaterThanOrEqual(0);
    const f32 = Number(await readout(page, 'compare-f32-naive-error'));
    expect(f32 >= 0 && f32 < 1e-5, `compare-f32-naive-error = ${f32}`).toBe(true);
    // the white furnace under cosine sampling at three bounces: 1 at every sample on both sides
    await openScene(page, '#/render?scene=furnace&strategy=cosine&bounces=3&res=32&spp=2&open=compare');
    await expect(page.getByTestId('compare-verdict')).toHaveAttribute('data-value', 'pass', {
      timeout: 30_000,
    });
    expect(Number(await readout(page, 'compare-pixel-gpu'))).toBe(1);
    expect(Number(await readout(page, 'compare-max-abs-z'))).toBe(0);
    // pausing writes where the run is (t, samples per pixel) into the link: a paused link like the
    // one followed at the start of this step
    await openScene(page, '#/render?res=32&spp=4096&open=settings');
    await page.evaluate(() => window.scrollTo(0, 0));
    await expect.poll(() => readout(page, 'spp').then(Number), { timeout: 15_000 }).toBeGreaterThan(2);
    await page.getByTestId('set-play').click();
    await page.evaluate(() => window.scrollTo(0, 0));
    await expect(page).toHaveURL(/[?&]play=0(&|$)/);
    // (frames made while the pause travelled to the GPU's worker move t to where the image holds)
    const linkT = () => Number(/[?&]t=(\d+)/.exec(page.url())?.[1]);
    await expect
      .poll(async () => linkT() === Number(await readout(page, 'spp')), { timeout: 15_000 })
      .toBe(true);
    const t = linkT();
    expect(t).toBeGreaterThan(2);
    await expect(page.getByTestId('render-status')).toHaveText(
      `Paused at ${t} of 4096 samples per pixel (play=0, t=${t}).`,
    );
    // where the shader cannot run (here: no OffscreenCanvas), the CPU draws and the page says why
    // (a fresh load, so that the script runs first; not a link followed on the open page, which
    // would start the shader again first)
    await page.addInitScript(() => Object.defineProperty(window, 'OffscreenCanvas', { value: undefined }));
    await page.goto('about:blank');
    await openScene(page, '#/render?res=32&spp=2');
    await expect(page.getByTestId('render-gpu-unavailable')).toContainText('OffscreenCanvas');
    await expect(page.getByTestId('renderer')).toHaveAttribute('data-value', 'cpu');
    await expect(page.getByTestId('f32-naive-error')).toHaveAttribute('data-value', 'none');
    await expect(page.getByTestId('render-status')).toHaveText(/^Done: 2 samples per pixel\.$/, {
      timeout: 30_000,
    });
  });
});

test('for a reader who only looks, the lab’s workers (the render, the reference) start once the page has settled', async ({
  page,
}) => {
  // (a page recorded for its first screen has a reader who only looks: ./firstScreen.ts)
  await recordFirstScreen(page);
  await page.addInitScript(() => {
    const made: { url: string; settled: boolean }[] = [];
    (window as unknown as { __workers: typeof made }).__workers = made;
    const Native = window.Worker;
    window.Worker = class extends Native {
      constructor(url: string | URL, options?: WorkerOptions) {
        super(url, options);
        made.push({ url: String(url), settled: document.documentElement.hasAttribute('data-settled') });
      }
    };
  });
  await page.goto('./#/render?renderer=cpu&res=32&spp=1');
  await expect(page.getByTestId('render-status')).toHaveText(/^Done: 1 samples per pixel\.$/, {
    timeout: 30_000,
  });
  await expect(page.getByTestId('rel-mse')).not.toHaveAttribute('data-value', 'none');
  const made = await page.evaluate(
    () => (window as unknown as { __workers: { url: string; settled: boolean }[] }).__workers,
  );
  const lab = made.filter((w) => /render\.worker|gpu\.worker/.test(w.url));
  expect(lab.length, 'the lab’s workers were made').toBeGreaterThan(0);
  expect(
    lab.filter((w) => !w.settled),
    'workers made before the page settled',
  ).toEqual([]);
});
