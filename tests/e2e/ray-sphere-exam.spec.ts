// #/ray-sphere, exam first and the sweep animation on the shared timeline.
// Expected values are computed here, by the scene's own pure model or by plain arithmetic.
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { checkInputs } from '../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../src/scenes/ray-sphere/model';
import { makeSweep, paramsAt, sweepAt } from '../../src/scenes/ray-sphere/sweep';
import type { RaySphereParams } from '../../src/scenes/ray-sphere/params';

type V = [number, number, number];
const P = (o: V, d: V, extra = '') => `#/ray-sphere?o=${o.join(',')}&d=${d.join(',')}&c=0,0,0&r=1${extra}`;

/** The scene's model at timeline position t, computed in the test. */
function modelAt(
  p: {
    o: V;
    d: V;
    c?: V;
    r?: number;
    sweep?: 'offset' | 'rotate';
    extent?: number;
    method?: 'stable' | 'naive';
  },
  t: number,
) {
  const params: RaySphereParams = {
    o: p.o,
    d: p.d,
    c: p.c ?? [0, 0, 0],
    r: p.r ?? 1,
    method: p.method ?? 'stable',
    precision: 'f64',
    sweep: p.sweep ?? 'offset',
    extent: p.extent ?? 2.5,
    t,
    play: false,
  };
  const sw = makeSweep(checkInputs(params), params.sweep as 'offset' | 'rotate', params.extent);
  return { m: computeModel(paramsAt(params, sw, t)), s: sweepAt(sw, t) };
}

async function expectReadoutsAt(
  page: import('@playwright/test').Page,
  want: ReturnType<typeof modelAt>['m'],
) {
  const r = want.chosen!;
  expect(await readoutNumber(page, 'a')).toBe(r.a);
  expect(await readoutNumber(page, 'b')).toBe(r.b);
  expect(await readoutNumber(page, 'c')).toBe(r.c);
  expect(await readoutNumber(page, 'discriminant')).toBe(r.discriminant);
  expect(await readout(page, 'case')).toBe(r.case);
  expect(await readout(page, 't-hit')).toBe(r.tHit === null ? 'none' : String(r.tHit));
}

test.describe('exam first', () => {
  test('question, then the figure, the derivation with live numbers, the live answer, then explore further', async ({
    page,
  }) => {
    const o: V = [-3, 0.3, 0.2];
    await openScene(page, P(o, [1, 0, 0]));
    const part = page.getByTestId('part-5');
    await expect(part).toContainText('The exam asks');
    await expect(part.locator('.exam-asks')).toContainText('centre C');
    await expect(part.locator('.exam-asks')).toContainText('Δ ≥ 0');
    // live numbers: c = |o − C|² − r² = 8.13, t-hit = 3 − √0.87 (8 significant digits)
    const c = 9 + 0.09 + 0.04 - 1;
    await expect(page.getByTestId('step-numbers')).toContainText(String(Number(c.toPrecision(6))));
    const hit = 3 - Math.sqrt(1 - 0.13);
    await expect(page.getByTestId('step-hit')).toContainText(String(Number(hit.toPrecision(8))));
    await expect(page.getByTestId('step-conditions')).toContainText('Δ ≥ 0');
    await expect(page.getByTestId('step-conditions')).toContainText('t ≥ 0');
    await expect(page.getByTestId('step-substitute')).toContainText('C');
    // t_min: the live example and the survey say self-intersection happens with t ≥ 0, never with t > t_min
    await expect(page.getByTestId('step-tmin')).toContainText('shadow acne');
    const survey = page.getByTestId('tmin-survey');
    // its rays are cast in short tasks after the derivation mounts: wait for the counts
    await expect(survey).toHaveAttribute('data-count', /^[1-9]\d*$/, { timeout: 30_000 });
    expect(Number(await survey.getAttribute('data-zero'))).toBeGreaterThan(0);
    expect(Number(await survey.getAttribute('data-tmin'))).toBe(0);
    await expect(page.getByTestId('tmin-example')).toContainText('p itself');
    await expect(page.getByTestId('q5-keynote')).toContainText('Ray Tracing in One Weekend');
    // page order
    const y = async (id: string) => (await page.getByTestId(id).boundingBox())!.y;
    const order = [
      await y('part-5'),
      await y('cross-section'),
      await y('derivation'),
      await y('live-answer'),
      await y('explore-further'),
    ];
    expect([...order].sort((a, b) => a - b)).toEqual(order);
  });

  test('Δ beside a, b, c: b² − 4ac of the shown numbers, and which method computed which', async ({
    page,
  }) => {
    await openScene(page, P([-3, -1.2, 0.6], [1, 0.4, -0.15]));
    const [a, b, c] = [
      await readoutNumber(page, 'a'),
      await readoutNumber(page, 'b'),
      await readoutNumber(page, 'c'),
    ];
    expect(await readoutNumber(page, 'disc-abc')).toBe(b * b - 4 * a * c);
    await expect(page.getByTestId('disc-method-note')).toContainText('robust form');
    // the textbook method: Δ is exactly b² − 4ac of the numbers shown, and there is no second readout
    await page.getByTestId('method').selectOption('naive');
    await waitForReadout(page, 'discriminant', (v) => Number(v) === b * b - 4 * a * c);
    await expect(page.getByTestId('disc-abc')).toHaveCount(0);
    await expect(page.getByTestId('disc-method-note')).toContainText('textbook way');
    // far sphere, robust: the two differ and the page says by how much
    await page.getByTestId('method').selectOption('stable');
    await page.getByTestId('preset-far').click();
    await waitForReadout(page, 'case', (v) => v === 'two-hits');
    expect(await readoutNumber(page, 'disc-abc')).not.toBe(await readoutNumber(page, 'discriminant'));
    await expect(page.getByTestId('disc-method-note')).toContainText('differs from b² − 4ac');
  });

  test('the centre is C on the figure; the URL parameter c still sets it and the c readout stays the constant term', async ({
    page,
  }) => {
    await openScene(page, '#/ray-sphere?o=-3,0,0&d=1,0,0&c=0,0.5,0&r=1');
    await expect(page.getByTestId('handle-c')).toHaveAttribute('aria-label', /sphere centre C/);
    await expect(page.getByTestId('cross-section').locator('text', { hasText: /^C$/ })).toHaveCount(1);
    expect(await readoutNumber(page, 'c')).toBe(9 + 0.25 - 1);
  });
});

test.describe('sweep animation on the shared timeline', () => {
  test('play, pause: readouts equal the model at the paused t; the link restores them; step advances by 1/120', async ({
    page,
  }) => {
    const cfg = { o: [-3, 0.3, 0.2] as V, d: [1, 0, 0] as V, extent: 2 };
    await openScene(page, P(cfg.o, cfg.d, '&extent=2'));
    const tl = page.getByTestId('timeline');
    await expect(tl).toHaveAttribute('data-t', '0.5');
    await expectReadoutsAt(page, modelAt(cfg, 0.5).m);
    await page.getByTestId('timeline-play').click();
    await expect
      .poll(async () => Number(await tl.getAttribute('data-t')), { timeout: 20_000 })
      .toBeGreaterThan(0.56);
    await page.getByTestId('timeline-play').click();
    await expect(tl).toHaveAttribute('data-playing', '0');
    const t = Number(await tl.getAttribute('data-t'));
    const want = modelAt(cfg, t);
    await expectReadoutsAt(page, want.m);
    expect(await readoutNumber(page, 'sweep-x')).toBe(want.s.x);
    await expect(page).toHaveURL(new RegExp(`t=${String(t).replace('.', '\\.')}`));
    // the link restores exactly these readouts
    await page.goto(page.url());
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', String(t));
    await expectReadoutsAt(page, want.m);
    // step: one step forward, paused
    // (the sweep loops: a step past the end wraps to 0, as the timeline does; a slow machine may have
    // paused within the last step)
    await page.getByTestId('timeline-step').click();
    const stepped = t + 1 / 120 > 1 ? 0 : t + 1 / 120;
    await expect
      .poll(async () => Number(await page.getByTestId('timeline').getAttribute('data-t')))
      .toBeCloseTo(stepped, 12);
    const t2 = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    await expectReadoutsAt(page, modelAt(cfg, t2).m);
  });

  test('the case changes along the sweep: miss at the ends, two hits in the middle, Δ crossing zero twice', async ({
    page,
  }) => {
    const cfg = { o: [-3, 0.3, 0.2] as V, d: [1, 0, 0] as V, extent: 2 };
    for (const [t, name] of [
      [0, 'miss'],
      [0.5, 'two-hits'],
      [1, 'miss'],
    ] as const) {
      await openScene(page, P(cfg.o, cfg.d, `&extent=2&t=${t}`));
      expect(await readout(page, 'case')).toBe(name);
      expect(modelAt(cfg, t).m.chosen!.case).toBe(name);
    }
    await expect(page.getByTestId('delta-plot').locator('.mp-tangent-label')).toHaveCount(2);
    // rotating the direction instead keeps the origin
    await openScene(page, P(cfg.o, cfg.d, '&sweep=rotate&t=0.1'));
    const want = modelAt({ ...cfg, sweep: 'rotate', extent: 2.5 }, 0.1);
    await expectReadoutsAt(page, want.m);
    expect(want.s.o).toEqual(cfg.o);
  });

  test('far preset: the textbook Δ has the wrong sign across the sweep, the robust one crosses zero only at tangency', async ({
    page,
  }) => {
    await openScene(page, '#/ray-sphere');
    await page.getByTestId('preset-far').click();
    const wrong = page.getByTestId('sweep-naive-wrong');
    await expect(wrong).toBeVisible();
    expect(Number(await wrong.getAttribute('data-value'))).toBeGreaterThan(5);
    // the wrong-sign dots are one path; it says how many it draws (near-tangent ones included, which the note leaves out)
    expect(
      Number(await page.getByTestId('delta-plot').locator('.mp-naive.wrong').getAttribute('data-count')),
    ).toBeGreaterThanOrEqual(Number(await wrong.getAttribute('data-value')));
    await expect(page.getByTestId('delta-plot').locator('.mp-tangent-label')).toHaveCount(2);
  });
});

test.describe('layout', () => {
  // the projector's common size (the stage's general checks run for every scene in catalogue.spec.ts)
  for (const [w, h] of [[1280, 720]] as const) {
    test(`present=1 at ${w}×${h}: plot titles and labels inside their plots; the figure is on the first screen`, async ({
      page,
    }) => {
      await page.setViewportSize({ width: w, height: h });
      await openScene(page, '#/ray-sphere?present=1');
      // at least 150 px of the figure on the first screen
      const fig = (await page.getByTestId('cross-section').boundingBox())!;
      expect(fig.y + 150).toBeLessThan(h);
      for (const id of ['g-plot', 'delta-plot']) {
        const svg = page.getByTestId(id);
        const box = (await svg.boundingBox())!;
        for (const sel of ['.mp-title', '.mp-label']) {
          for (const t of await svg.locator(sel).all()) {
            const b = (await t.boundingBox())!;
            expect(b.x, `${id} ${sel} left`).toBeGreaterThanOrEqual(box.x - 0.5);
            expect(b.y, `${id} ${sel} top`).toBeGreaterThanOrEqual(box.y - 0.5);
            expect(b.x + b.width, `${id} ${sel} right`).toBeLessThanOrEqual(box.x + box.width + 0.5);
            expect(b.y + b.height, `${id} ${sel} bottom`).toBeLessThanOrEqual(box.y + box.height + 0.5);
          }
        }
      }
      // the Plotly plot under "explore further": axis titles inside the plot
      const ep = page.getByTestId('error-plot');
      await ep.scrollIntoViewIfNeeded();
      await expect(ep.locator('.xtitle')).toHaveCount(1, { timeout: 30_000 });
      const pb = (await ep.boundingBox())!;
      for (const sel of ['.xtitle', '.ytitle']) {
        const b = (await ep.locator(sel).boundingBox())!;
        expect(b.x).toBeGreaterThanOrEqual(pb.x - 0.5);
        expect(b.y).toBeGreaterThanOrEqual(pb.y - 0.5);
        expect(b.x + b.width).toBeLessThanOrEqual(pb.x + pb.width + 0.5);
        expect(b.y + b.height).toBeLessThanOrEqual(pb.y + pb.height + 0.5);
      }
    });
  }

  test('375 px: SVG labels ≥ 12 px, handles ≥ 24 px with a visible focus ring', async ({ page }) => {
    await page.setViewportSize({ width: 375, height: 800 });
    await openScene(page, '#/ray-sphere');
    const sizes = await page.evaluate(() => {
      const out: { cls: string; px: number }[] = [];
      for (const svg of document.querySelectorAll<SVGSVGElement>(
        '[data-testid=cross-section], [data-testid=g-plot], [data-testid=delta-plot]',
      )) {
        const scale = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
        for (const t of svg.querySelectorAll('text'))
          out.push({
            cls: `${svg.dataset.testid} ${t.getAttribute('class')}`,
            px: parseFloat(getComputedStyle(t).fontSize) * scale,
          });
      }
      return out;
    });
    expect(sizes.length).toBeGreaterThan(10);
    for (const s of sizes) expect(s.px, s.cls).toBeGreaterThanOrEqual(12);
    for (const id of ['handle-o', 'handle-tip', 'handle-c', 'handle-r']) {
      const b = (await page.getByTestId(id).boundingBox())!;
      expect(b.width, id).toBeGreaterThanOrEqual(24);
      expect(b.height, id).toBeGreaterThanOrEqual(24);
    }
    await page.keyboard.press('Tab');
    const h = page.getByTestId('handle-c');
    await h.focus();
    await expect(h).toBeFocused();
    const ring = await h.locator('.rs-handle-ring').evaluate((el) => getComputedStyle(el).stroke);
    expect(ring).not.toBe('none');
  });
});
