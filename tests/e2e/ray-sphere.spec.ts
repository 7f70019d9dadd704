// #/ray-sphere in the browser: the readouts wired to the scene's model (links, the sweep's step,
// the case and precision presets, bad input, dragging a handle, the folds the link remembers, the
// t_min survey cast after the page mounts), and the float32 paths: the precision switch and the
// WebGL2 shader (SwiftShader in headless Chromium) against the emulation, with and without WebGL2.
// Elsewhere: the roots themselves (every case, both methods, the precision presets against mathjs
// BigNumber) are unit tests (tests/core/geometry/raySphere.test.ts,
// tests/scenes/ray-sphere/model.test.ts, precisionF32.test.ts, sweep.test.ts); the exam's worked
// steps, key note and Δ beside a, b, c are rendered in Node (tests/render/examParts.test.tsx); the
// page as a whole, its parts in order and play, pause and the link's t are in catalogue.spec.ts;
// the accessibility tree and the keyboard in ray-sphere-a11y.spec.ts.
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/ray-sphere/params';
import { checkInputs } from '../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../src/scenes/ray-sphere/model';
import { makeSweep, paramsAt, sweepAt } from '../../src/scenes/ray-sphere/sweep';

type V = [number, number, number];
const fr = Math.fround;

/** The model behind a link's query at timeline position t (the link's own t when not given). */
function modelOf(query: string, t?: number) {
  const p = parseParams(schema, query).values;
  const sw = makeSweep(checkInputs(p), p.sweep, p.extent);
  return { m: computeModel(paramsAt(p, sw, t ?? p.t)), s: sweepAt(sw, t ?? p.t) };
}

/**
 * Every root readout equals the model's, digit for digit ('none' where it has none). A link opened
 * on the page that is already open renders as a transition, a moment later: the readouts are read
 * once Δ and the hit show the link's values.
 */
async function expectReadouts(page: Page, query: string, t?: number) {
  const r = modelOf(query, t).m.chosen!;
  const num = (x: number | null) => (x === null ? 'none' : String(x));
  await waitForReadout(page, 'discriminant', (v) => Number(v) === r.discriminant);
  await waitForReadout(page, 't-hit', (v) => v === num(r.tHit));
  expect(await readout(page, 'case'), query).toBe(r.case);
  expect(await readoutNumber(page, 'a'), query).toBe(r.a);
  expect(await readoutNumber(page, 'b'), query).toBe(r.b);
  expect(await readoutNumber(page, 'c'), query).toBe(r.c);
  expect(await readoutNumber(page, 'discriminant'), query).toBe(r.discriminant);
  expect(await readout(page, 't0'), query).toBe(num(r.t0));
  expect(await readout(page, 't1'), query).toBe(num(r.t1));
  expect(await readout(page, 't-hit'), query).toBe(num(r.tHit));
}

const q = (o: V, d: V, c: V, r: number, method = 'stable') =>
  `o=${o.join(',')}&d=${d.join(',')}&c=${c.join(',')}&r=${r}&method=${method}`;

test('wiring: links, the sweep’s step, presets, bad input, a drag and the folds all give the model’s readouts', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await test.step('links: the exam’s ray, an oblique two-hit ray (textbook form), an origin inside', async () => {
    for (const query of [
      '',
      q([1, 2, 3], [0.3, -0.7, -2], [1.5, 1, -2], 1.7, 'naive'),
      q([0.2, -0.3, 0.1], [1, 0.5, 0], [0, 0, 0], 1),
    ]) {
      await openScene(page, `#/ray-sphere${query ? `?${query}` : ''}`);
      await expectReadouts(page, query);
      await expect(page.getByTestId('case-banner')).toContainText(/Δ/);
      // the figure's labels, hidden until its first frame is painted, are then placed: shown,
      // inside the figure, and clear of every handle's ring
      const cross = page.getByTestId('cross-section');
      await expect(cross).toHaveAttribute('data-labels', 'placed');
      const clash = await cross.evaluate((svg) => {
        const fig = svg.getBoundingClientRect();
        const out: string[] = [];
        const labels = [...svg.querySelectorAll<SVGTextElement>('text')].filter(
          (t) => t.getAttribute('display') !== 'none' && (t.textContent ?? '') !== '',
        );
        if (labels.length < 3) out.push(`${labels.length} labels shown`);
        for (const t of labels) {
          if (getComputedStyle(t).visibility !== 'visible') out.push(`${t.textContent} hidden`);
          const b = t.getBoundingClientRect();
          if (
            b.left < fig.left - 1 ||
            b.right > fig.right + 1 ||
            b.top < fig.top - 1 ||
            b.bottom > fig.bottom + 1
          )
            out.push(`${t.textContent} outside the figure`);
          for (const h of svg.querySelectorAll<SVGGElement>(
            '.rs-handle:not([display="none"]) .rs-handle-ring',
          )) {
            const r = h.getBoundingClientRect();
            const w = Math.min(b.right, r.right) - Math.max(b.left, r.left);
            const hh = Math.min(b.bottom, r.bottom) - Math.max(b.top, r.top);
            if (r.width > 0 && w > 1 && hh > 1) out.push(`${t.textContent} under a handle`);
          }
        }
        return out;
      });
      expect(clash, `labels of ${query || 'the exam’s ray'}`).toEqual([]);
    }
  });

  await test.step('the sweep: at t = 0.5 the model there (and sweep-x); a step advances t by 1/120', async () => {
    const query = 'o=-3,0.3,0.2&d=1,0,0&c=0,0,0&r=1&extent=2';
    await openScene(page, `#/ray-sphere?${query}`);
    const tl = page.getByTestId('timeline');
    await expect(tl).toHaveAttribute('data-t', '0.5');
    await expectReadouts(page, query, 0.5);
    expect(await readoutNumber(page, 'sweep-x')).toBe(modelOf(query, 0.5).s.x);
    await page.getByTestId('timeline-step').click();
    await expect.poll(async () => Number(await tl.getAttribute('data-t'))).toBeCloseTo(0.5 + 1 / 120, 12);
    const t = Number(await tl.getAttribute('data-t'));
    await expectReadouts(page, query, t);
    expect(await readoutNumber(page, 'sweep-x')).toBe(modelOf(query, t).s.x);
  });

  await test.step('case presets set the link and the readouts; Δ along the sweep is a fold written into the link', async () => {
    await openScene(page, '#/ray-sphere');
    await expectReadouts(page, '');
    // closed on load: nothing of it is mounted
    const fold = page.getByTestId('fold-delta');
    expect(await fold.evaluate((el) => (el as HTMLDetailsElement).open)).toBe(false);
    await expect(page.getByTestId('delta-figure')).toHaveCount(0);
    for (const name of ['miss', 'tangent', 'inside', 'behind', 'two-hits']) {
      await page.getByTestId(`preset-${name}`).click();
      await waitForReadout(page, 'case', (v) => v === name);
      await expect(page).toHaveURL(/o=/);
    }
    // opened by a click, it mounts and writes open=delta into the link (beside the preset's values)
    await fold.locator('summary').click();
    await expect(page.getByTestId('delta-figure')).toBeVisible();
    await expect(page).toHaveURL(/[?&]open=delta(&|$)/);
    await expect(page).toHaveURL(/o=/);
  });

  await test.step('precision preset “far”: robust readouts are the model’s; the textbook column says tangent', async () => {
    // the precision presets are under "More settings", the table under "Precision"
    await openScene(page, '#/ray-sphere?open=more,precision');
    await page.getByTestId('preset-far').click();
    await expect(page).toHaveURL(/c=100000000,0,0/);
    const query = page.url().slice(page.url().indexOf('?') + 1);
    const want = modelOf(query).m.chosen!.case;
    await waitForReadout(page, 'case', (v) => v === want);
    await expectReadouts(page, query);
    await expect(page.getByTestId('stable-case')).toHaveAttribute('data-value', want);
    await expect(page.getByTestId('ref-case')).toHaveAttribute('data-value', want);
    await expect(page.getByTestId('naive-case')).toHaveAttribute('data-value', 'tangent');
    // choosing the textbook method shows its wrong answer beside the right one
    await page.getByTestId('method').selectOption('naive');
    await waitForReadout(page, 'case', (v) => v === 'tangent');
    await expect(page.getByTestId('method-wrong')).toContainText(want);
    await expect(page).toHaveURL(/method=naive/);
  });

  await test.step('a bad value typed in a field is flagged and does not reach the model', async () => {
    await openScene(page, '#/ray-sphere?open=values');
    await expectReadouts(page, 'open=values');
    const before = await readout(page, 't0');
    const r = page.getByTestId('input-r');
    await r.fill('abc');
    await r.press('Enter');
    await expect(page.getByText('Enter a finite number')).toBeVisible();
    expect(await readout(page, 't0')).toBe(before);
    await r.fill('0.5');
    await r.press('Enter');
    await waitForReadout(page, 't0', (v) => v !== before);
    await expect(page).toHaveURL(/[?&]r=0\.5(&|$)/);
  });

  await test.step('dragging the origin handle up moves the ray and writes the link', async () => {
    await openScene(page, '#/ray-sphere?o=-3,0.3,0&d=1,0,0');
    await expectReadouts(page, 'o=-3,0.3,0&d=1,0,0');
    // a link opened on the same page keeps the scroll position: bring the figure into view
    const handle = page.getByTestId('handle-o');
    await handle.scrollIntoViewIfNeeded();
    const b = (await handle.boundingBox())!;
    const x = b.x + b.width / 2;
    const y = b.y + b.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 20; i++) await page.mouse.move(x, y - i * 4);
    await page.mouse.up();
    // straight up in the figure: only o's y grows; the readouts are the model's for the written link
    await expect(page).toHaveURL(/o=-3,(0\.[4-9]|[1-9])[\d.]*,0(&|$)/);
    const query = page.url().slice(page.url().indexOf('?') + 1);
    await expectReadouts(page, query);
  });

  await test.step('t_min: the survey, cast after the derivation mounts, finds self-hits with t ≥ 0 and none with t > t_min', async () => {
    await openScene(page, '#/ray-sphere?o=-3,0.3,0.2&d=1,0,0&c=0,0,0&r=1&open=tmin');
    await expectReadouts(page, 'o=-3,0.3,0.2&d=1,0,0&c=0,0,0&r=1');
    const survey = page.getByTestId('tmin-survey');
    await expect(survey).toHaveAttribute('data-count', /^[1-9]\d*$/, { timeout: 30_000 });
    expect(Number(await survey.getAttribute('data-zero'))).toBeGreaterThan(0);
    expect(Number(await survey.getAttribute('data-tmin'))).toBe(0);
    await expect(page.getByTestId('tmin-example')).toContainText('p itself');
  });
});

test('float32: the precision switch, the WebGL2 shader against the emulation, and shadow acne', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await test.step('precision=f32: the readouts are float32, the textbook test fails 10⁴ r away', async () => {
    // f = (−10⁴, −0.5, 0): in float32 c = 10⁸ − 0.75 rounds to 10⁸ and b² − 4ac = 0
    await openScene(
      page,
      '#/ray-sphere?o=0,0,0&d=1,0,0&c=10000,0.5,0&r=1&method=naive&precision=f32&open=more',
    );
    // a link opens the folds it names
    await expect(page.getByTestId('fold-more')).toHaveAttribute('open', '');
    expect(await readout(page, 'c')).toBe('100000000');
    expect(await readout(page, 'discriminant')).toBe('0');
    expect(await readout(page, 'case')).toBe('tangent');
    await expect(page.getByTestId('precision-note')).toBeVisible();
    await expect(page.getByTestId('method-wrong')).toContainText('two-hits');
    // the robust form in float32 gets it right; t₀ is a float32 value
    await page.getByTestId('method').selectOption('stable');
    await expect(page).not.toHaveURL(/method=/);
    await expect.poll(() => readout(page, 'case')).toBe('two-hits');
    expect(await readout(page, 'discriminant')).toBe('3');
    const t0 = Number(await readout(page, 't0'));
    expect(fr(t0)).toBe(t0);
    expect(Math.abs(t0 - (1e4 - Math.sqrt(0.75)))).toBeLessThan(2e-3);
    // switching back to float64: the same link without precision, double results
    await page.getByTestId('precision').selectOption('f64');
    await expect(page).not.toHaveURL(/precision=/);
    await expect.poll(() => readout(page, 'c')).toBe(String(1e8 - 0.75));
  });

  await test.step('the WebGL2 shader matches the emulation; at 10⁴ r the textbook image has holes, the robust none', async () => {
    await openScene(page, '#/ray-sphere');
    const details = page.getByTestId('gpu-details');
    await details.scrollIntoViewIfNeeded();
    // nothing of the panel exists until the disclosure is opened
    await expect(page.getByTestId('gpu-panel')).toHaveCount(0);
    await details.locator('summary').click();
    const panel = page.getByTestId('gpu-panel');
    await expect(panel).toBeVisible({ timeout: 30_000 });
    // SwiftShader offers WebGL2: the shader ran (no "no WebGL2" notice)
    await expect(page.getByTestId('gpu-unavailable')).toHaveCount(0);
    await expect(page.getByTestId('gpu-renderer')).not.toBeEmpty();
    const num = async (id: string) => Number(await readout(page, id));
    // at 10³ r (the opening distance) shader and emulation agree within 2 ulps on all but a few pixels
    expect(await num('image-shader-mismatch')).toBeLessThanOrEqual(0.01 * 96 * 96);
    await page.getByTestId('gpu-preset-far').click();
    await expect(panel).toHaveAttribute('data-dist', '10000');
    expect(await num('image-wrong-naive')).toBeGreaterThan(100);
    expect(await num('image-wrong-stable')).toBe(0);
    expect(await num('image-shader-mismatch')).toBeLessThanOrEqual(0.01 * 96 * 96);
    expect(await num('image-max-ulps-stable')).toBeLessThan(8);
    // the emulation agrees with the shader about the holes
    expect(await num('emu-wrong-stable')).toBe(0);
    expect(await num('emu-wrong-naive')).toBeGreaterThan(100);
  });

  await test.step('shadow acne in float32: self-hits at a small ε, none with pbrt’s offset', async () => {
    const acne = page.getByTestId('acne-panel');
    await acne.scrollIntoViewIfNeeded();
    await page.getByTestId('acne-dist-10000').click();
    await expect.poll(async () => Number(await readout(page, 'acne-fraction'))).toBeGreaterThan(0.1);
    await page.getByTestId('acne-pbrt').check();
    await expect.poll(async () => Number(await readout(page, 'acne-fraction'))).toBe(0);
    expect(Number(await readout(page, 'acne-lit'))).toBeGreaterThan(1000);
    // the ε needed grows with the distance; pbrt's offset never self-hits
    await expect(page.getByTestId('acne-table')).toBeVisible({ timeout: 30_000 });
    const need = async (D: number) =>
      Number(await page.getByTestId(`acne-need-${D}`).getAttribute('data-value'));
    expect(await need(1e4)).toBeGreaterThan(10 * (await need(10)));
    for (const D of [10, 100, 1000, 10000])
      await expect(page.getByTestId(`acne-pbrt-hits-${D}`)).toHaveAttribute('data-value', '0');
  });
});

test('without WebGL2 the GPU panel says so and shows the emulation', async ({ page }) => {
  await page.addInitScript(() => {
    const orig = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (
      this: HTMLCanvasElement,
      kind: string,
      ...rest: unknown[]
    ) {
      if (kind === 'webgl2') return null;
      return (orig as (...a: unknown[]) => unknown).call(this, kind, ...rest);
    } as typeof orig;
  });
  await openScene(page, '#/ray-sphere');
  const details = page.getByTestId('gpu-details');
  await details.scrollIntoViewIfNeeded();
  await details.locator('summary').click();
  await expect(page.getByTestId('gpu-unavailable')).toContainText('no WebGL2');
  await page.getByTestId('gpu-preset-far').click();
  expect(Number(await readout(page, 'image-wrong-naive'))).toBeGreaterThan(100);
  expect(await readout(page, 'image-shader-mismatch')).toBe('none');
});
