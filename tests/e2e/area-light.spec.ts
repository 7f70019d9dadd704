/**
 * Browser tests of #/area-light: for several placements of the light the chosen estimator agrees
 * with the analytic reference within 3σ (read from data-value), and the solid angle matches a
 * closed form computed here (the corner formula by inclusion–exclusion in the light's own frame,
 * independent of the app's Van Oosterom–Strackee code); bad input gives a message and a fallback.
 */
import AxeBuilder from '@axe-core/playwright';
import { test, expect, openScene, readout, readoutNumber, countAnimationFrames } from './fixtures';
import { defaultValues, parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/area-light/params';
import { animationFrame, animationLength, sampleRun } from '../../src/scenes/area-light/animation';
import { buildModel, givenSamples } from '../../src/scenes/area-light/model';
import { patchModel } from '../../src/scenes/area-light/patch';
import type { LightStrategy } from '../../src/core/lights';

type V3 = [number, number, number];

/**
 * Solid angle of a w × h rectangle (centre c, tilt t degrees about its x axis; frame as in the
 * contract: ex = (1,0,0), ey = (0,cos t, sin t), n = (0, sin t, −cos t)) seen from p:
 * Ω = |F(x1,y1) − F(x0,y1) − F(x1,y0) + F(x0,y0)|, F(a,b) = atan(ab / (d √(a²+b²+d²))).
 */
function closedFormOmega(p: V3, c: V3, w: number, h: number, tiltDeg: number): number {
  const t = (tiltDeg * Math.PI) / 180;
  const ex: V3 = [1, 0, 0],
    ey: V3 = [0, Math.cos(t), Math.sin(t)],
    n: V3 = [0, Math.sin(t), -Math.cos(t)];
  const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const rel: V3 = [c[0] - p[0], c[1] - p[1], c[2] - p[2]];
  const d = Math.abs(dot(rel, n));
  const cx = dot(rel, ex),
    cy = dot(rel, ey);
  const F = (a: number, b: number) => Math.atan((a * b) / (d * Math.sqrt(a * a + b * b + d * d)));
  const x0 = cx - w / 2,
    x1 = cx + w / 2,
    y0 = cy - h / 2,
    y1 = cy + h / 2;
  return Math.abs(F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0));
}

const placements: Array<{
  name: string;
  p: V3;
  lc: V3;
  ls: [number, number];
  tilt: number;
  strategy: string;
  zero?: boolean;
}> = [
  { name: 'overhead', p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 0, strategy: 'area' },
  {
    name: 'off-axis, solid-angle sampling',
    p: [0.2, -0.4, 0],
    lc: [0.9, 0.3, 1.5],
    ls: [1.2, 0.8],
    tilt: 0,
    strategy: 'solid-angle',
  },
  { name: 'tilted', p: [0, 0, 0], lc: [0, 1, 1.5], ls: [1.5, 1], tilt: -45, strategy: 'area' },
  {
    name: 'partly below the horizon',
    p: [0, 0, 0],
    lc: [0, 1, 0.2],
    ls: [1, 1],
    tilt: -90,
    strategy: 'solid-angle',
  },
  {
    name: 'near, cosine sampling',
    p: [0.1, 0, 0],
    lc: [0, 0, 0.25],
    ls: [2, 2],
    tilt: 0,
    strategy: 'cosine',
  },
  { name: 'facing away', p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 180, strategy: 'area', zero: true },
];

for (const pl of placements) {
  test(`${pl.name}: estimate within 3σ of the reference, Ω equals its closed form`, async ({ page }) => {
    const q = `p=${pl.p.join(',')}&lc=${pl.lc.join(',')}&ls=${pl.ls.join(',')}&tilt=${pl.tilt}&strategy=${pl.strategy}&n=4096&seed=7`;
    await openScene(page, `#/area-light?${q}`);
    await expect(page.locator('[role=alert]')).toHaveCount(0);
    const ref = await readoutNumber(page, 'reference');
    const est = await readoutNumber(page, 'estimate');
    const omega = await readoutNumber(page, 'solid-angle');
    const expected = closedFormOmega(pl.p, pl.lc, pl.ls[0], pl.ls[1], pl.tilt);
    expect(Math.abs(omega - expected) / expected).toBeLessThan(1e-12);
    if (pl.zero) {
      expect(ref).toBe(0);
      expect(est).toBe(0);
      await expect(page.getByText(/faces away/)).toBeVisible();
    } else {
      const se = await readoutNumber(page, 'stderr');
      expect(ref).toBeGreaterThan(0);
      expect(se).toBeGreaterThan(0);
      expect(Math.abs(est - ref)).toBeLessThanOrEqual(3 * se);
      // the other two strategies, shown in the table, agree as well
      for (const s of ['area', 'solid-angle', 'cosine']) {
        const e = await readoutNumber(page, `estimate-${s}`);
        const es = await readoutNumber(page, `stderr-${s}`);
        expect(Math.abs(e - ref), s).toBeLessThanOrEqual(3 * es);
      }
    }
  });
}

test('a horizontal light also shows the aligned closed form, equal to Ω', async ({ page }) => {
  // tilt=0: the light is parallel to the floor (the default light is tilted)
  await openScene(page, '#/area-light?lc=0.7,-0.3,1.5&ls=1.2,0.8&tilt=0');
  const a = await readoutNumber(page, 'solid-angle');
  const b = await readoutNumber(page, 'solid-angle-closed');
  expect(Math.abs(a - b) / a).toBeLessThan(1e-13);
  expect(await readout(page, 'reference-occluded')).toBe('none');
});

test('the occluder lowers the estimate; the occluded reference is shown and matched', async ({ page }) => {
  await openScene(page, '#/area-light?occluder=1&strategy=solid-angle&n=20000&seed=3');
  const ref = await readoutNumber(page, 'reference');
  const occ = await readoutNumber(page, 'reference-occluded');
  const est = await readoutNumber(page, 'estimate');
  const se = await readoutNumber(page, 'stderr');
  expect(occ).toBeLessThan(ref);
  expect(Math.abs(est - occ)).toBeLessThanOrEqual(3 * se);
});

test('zero-size light: a clear message and the 1 × 1 fallback', async ({ page }) => {
  await openScene(page, '#/area-light?ls=0,0');
  await expect(page.getByRole('alert')).toContainText('no area');
  expect(await readoutNumber(page, 'reference')).toBeGreaterThan(0);
  // the 1 × 1 fallback where the default light is
  expect(await readoutNumber(page, 'solid-angle')).toBeCloseTo(
    closedFormOmega([...schema.p.default], [...schema.lc.default], 1, 1, schema.tilt.default),
    12,
  );
});

test('shading point on the light: a clear message and a safe fallback', async ({ page }) => {
  // a point on the exam's light (centred at 0,0,2, parallel to the floor)
  await openScene(page, '#/area-light?p=0.1,0.1,2&lc=0,0,2&tilt=0');
  await expect(page.getByRole('alert')).toContainText('on the light');
  expect(await readoutNumber(page, 'reference')).toBeGreaterThan(0);
  expect(await readoutNumber(page, 'estimate')).toBeGreaterThan(0);
});

test('non-finite and malformed values: the notice names them, figures stay finite', async ({ page }) => {
  await openScene(page, '#/area-light?p=NaN,0,0&L=Infinity&tilt=abc&n=-4&ls=1');
  const notice = page.getByRole('status').filter({ hasText: 'tilt' }).first();
  await expect(notice).toBeVisible();
  for (const name of ['p', 'L', 'tilt', 'n', 'ls']) await expect(notice).toContainText(name);
  for (const id of ['reference', 'estimate', 'solid-angle']) await readoutNumber(page, id);
  // n = −4 is clamped to 1: one sample has no spread, so the standard error does not apply.
  expect(await readout(page, 'stderr')).toBe('none');
});

test('changing the strategy updates the URL and the estimate; the floor images finish', async ({ page }) => {
  await openScene(page, '#/area-light?n=2048');
  const before = await readout(page, 'estimate');
  await page.getByTestId('strategy').selectOption('cosine');
  await expect(page).toHaveURL(/strategy=cosine/);
  await expect(page.getByTestId('estimate')).not.toHaveAttribute('data-value', before);
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByText(/64 samples per pixel \(done\)/)).toBeVisible({ timeout: 30000 });
  for (const s of ['area', 'solid-angle', 'cosine']) await readoutNumber(page, `image-rmse-${s}`);
});

test('large n is estimated in a worker without blocking; the result agrees within 3σ', async ({ page }) => {
  await openScene(page, '#/area-light?n=300000&strategy=cosine&seed=5');
  const { waitForReadout } = await import('./fixtures');
  await waitForReadout(page, 'estimate', (v) => v !== 'none' && Number.isFinite(Number(v)), 30000);
  // the page stays responsive meanwhile: a control reacts at once
  await expect(page.getByTestId('strategy')).toBeEnabled();
  const ref = await readoutNumber(page, 'reference');
  const est = await readoutNumber(page, 'estimate');
  const se = await readoutNumber(page, 'stderr');
  expect(se).toBeGreaterThan(0);
  expect(Math.abs(est - ref)).toBeLessThanOrEqual(3 * se);
});

test('dark theme: no serious or critical axe violations (the highlighted KaTeX boxes keep dark text)', async ({
  page,
}) => {
  test.setTimeout(240_000); // a full-page axe scan of a long page on a busy 2-core machine
  await openScene(page, '#/area-light?theme=dark&occluder=1');
  await page.waitForTimeout(2000);
  const r = await new AxeBuilder({ page }).analyze();
  const bad = r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => v.id);
  expect(bad).toEqual([]);
});

test('a tiny, distant light (10⁶ away): Ω matches A cos θ_l / r² (exact to O((size/d)²)) to 1e-11; estimates exact', async ({
  page,
}) => {
  // tilt=0: the light parallel to the floor, so cos θₗ = d / r below
  await openScene(page, '#/area-light?lc=3,-2,1000000&ls=1,0.5&tilt=0&strategy=solid-angle&n=512');
  const omega = await readoutNumber(page, 'solid-angle');
  // The corner formula's four terms cancel at this distance, so the check is the small-patch limit,
  // whose own error is O((size/d)²) ≈ 1e-12.
  const d = 1e6,
    cx = 3,
    cy = -2,
    w = 1,
    h = 0.5;
  const r = Math.hypot(cx, cy, d);
  const approx = (w * h * (d / r)) / (r * r);
  expect(Math.abs(omega - approx) / approx).toBeLessThan(1e-11);
  const ref = await readoutNumber(page, 'reference');
  const est = await readoutNumber(page, 'estimate');
  expect(Math.abs(est - ref) / ref).toBeLessThan(1e-9);
});

test('Q6(a): as the patch shrinks, dA cos θ_l / r² meets the exact solid angle', async ({ page }) => {
  await openScene(page, '#/area-light?psize=0.5&ptilt=30');
  const big = Math.abs(await readoutNumber(page, 'patch-rel-error'));
  await openScene(page, '#/area-light?psize=0.0005&ptilt=30');
  const small = Math.abs(await readoutNumber(page, 'patch-rel-error'));
  expect(small).toBeLessThan(big / 1e5); // second order: (0.0005/0.5)² = 1e-6
  const exact = await readoutNumber(page, 'patch-exact');
  const approx = await readoutNumber(page, 'patch-approx');
  expect(Math.abs(exact - approx) / exact).toBeLessThan(1e-6);
});

// ------------------------------------------------------------------------------------------------
// Exam first and the animation.

/** The model computed here, in Node, from a query string (the same parser as the app). */
function modelFor(query: string) {
  const values = { ...defaultValues(schema), ...parseParams(schema, new URLSearchParams(query)).values };
  return { values, model: buildModel(values) };
}

test('exam first: 6a, 6b, 6c in order before "Explore further", each with its derivation and live numbers', async ({
  page,
}) => {
  const q = 'psize=0.3&ptilt=40&seed=9&occluder=1';
  await openScene(page, `#/area-light?${q}`);
  const ids = ['part-6a', 'part-6b', 'part-6c', 'explore-further'];
  const tops: number[] = [];
  for (const id of ids) {
    const el = id === 'explore-further' ? page.getByTestId(id) : page.locator(`#${id}`);
    await expect(el).toBeVisible();
    tops.push((await el.boundingBox())!.y);
  }
  expect([...tops].sort((a, b) => a - b)).toEqual(tops);
  const { values, model } = modelFor(q);
  const patch = patchModel(model, values.pu, values.pv, values.psize, values.ptilt);
  // 6a: the similar-triangles steps, with dl, dω_l and the result for this patch
  const d6a = page.getByTestId('derivation-6a');
  await expect(d6a).toContainText('similar triangles');
  const dl = Math.sqrt(patch.area * patch.cosThetaL);
  await expect(page.getByTestId('step-6a-perp')).toContainText(`dl = ${Number(dl.toPrecision(4))}`);
  // dωₗ is written with a real subscript (dω<sub>l</sub>): its text is "dωl"
  await expect(page.getByTestId('step-6a-similar')).toContainText(
    `dωl = ${Number((dl / patch.r).toPrecision(4))}`,
  );
  await expect(page.getByTestId('step-6a-result')).toContainText(String(Number(patch.approx.toPrecision(6))));
  expect(await readoutNumber(page, 'patch-approx')).toBeCloseTo(patch.approx, 7);
  // 6b: the four steps (Jacobian J_T, then V, then cos θ_l / r²) with the Jacobian's value
  await expect(page.getByTestId('derivation-6b').locator('.katex')).toHaveCount(4);
  await expect(page.getByTestId('step-6b-jacobian')).toContainText(
    String(Number((patch.cosThetaL / patch.r ** 2).toPrecision(4))),
  );
  // 6c: p_A = 1/|A| and the four given samples' terms, their mean as the N = 4 estimate
  await expect(page.getByTestId('step-6c-pdf')).toContainText(
    `|A| = ${Number(model.light.area.toPrecision(4))}`,
  );
  const g = givenSamples(model, values.seed, 4);
  for (let i = 0; i < 4; i++) {
    const v = Number(await page.getByTestId(`given-term-${i + 1}`).getAttribute('data-value'));
    expect(v).toBeCloseTo(g.samples[i].term, 12);
  }
  expect(await readoutNumber(page, 'given-estimate')).toBeCloseTo(g.estimate, 6);
});

test('Q6(a) figure: drawn to scale by default, and its labels never overlap (several tilts, 375 px labels ≥ 12 px)', async ({
  page,
}) => {
  await page.setViewportSize({ width: 375, height: 800 });
  for (const ptilt of [0, 30, 60, 85, -45]) {
    for (const psize of [0.25, 0.9]) {
      await openScene(page, `#/area-light?ptilt=${ptilt}&psize=${psize}`);
      const fig = page.getByTestId('al-patch-figure');
      await fig.scrollIntoViewIfNeeded();
      if (psize === 0.25 && ptilt === 0) await expect(fig).toHaveAttribute('data-to-scale', '1');
      const boxes = await fig.locator('text').evaluateAll((els) =>
        els
          .filter((e) => getComputedStyle(e).display !== 'none')
          .map((e) => {
            const r = e.getBoundingClientRect();
            return {
              t: e.textContent,
              x0: r.left,
              x1: r.right,
              y0: r.top,
              y1: r.bottom,
              fs:
                parseFloat(getComputedStyle(e).fontSize) *
                ((e as SVGTextElement).ownerSVGElement!.getBoundingClientRect().width / 560),
            };
          }),
      );
      for (const b of boxes) expect(b.fs, `${b.t} font size`).toBeGreaterThanOrEqual(12);
      for (let i = 0; i < boxes.length; i++)
        for (let j = i + 1; j < boxes.length; j++) {
          const a = boxes[i],
            b = boxes[j];
          const overlap =
            Math.min(a.x1, b.x1) - Math.max(a.x0, b.x0) > 1 &&
            Math.min(a.y1, b.y1) - Math.max(a.y0, b.y0) > 1;
          expect(overlap, `tilt ${ptilt}, side ${psize}: "${a.t}" overlaps "${b.t}"`).toBe(false);
        }
    }
  }
});

test('dark theme: the Q6(b) highlight boxes turn dark with light text', async ({ page }) => {
  await openScene(page, '#/area-light?theme=dark');
  const bg = await page.locator('.al-hl-j').evaluate((e) => getComputedStyle(e).backgroundColor);
  const lum = (c: string) => {
    const [r, g, b] = c.match(/\d+/g)!.map(Number);
    return 0.2126 * r! + 0.7152 * g! + 0.0722 * b!;
  };
  expect(lum(bg)).toBeLessThan(110);
  // the KaTeX colour boxes follow the theme too
  const boxBg = await page
    .getByTestId('derivation-6b')
    .locator('.colorbox')
    .first()
    .evaluate((e) => getComputedStyle(e).backgroundColor);
  expect(lum(boxBg)).toBeLessThan(110);
});

for (const [w, h] of [
  [1920, 1080],
  [1280, 720],
] as const) {
  test(`present=1 at ${w}×${h}: the animation is on the first screen, and no plot's axis title is clipped`, async ({
    page,
  }) => {
    await page.setViewportSize({ width: w, height: h });
    await openScene(page, '#/area-light?present=1');
    // the animation's figure (the 3D view with the samples) starts on the first screen
    const stage = page.getByTestId('al-3d');
    await expect(stage).toBeVisible();
    expect((await stage.boundingBox())!.y).toBeLessThan(0.8 * h);
    const plots = page.locator('.js-plotly-plot');
    // plots mount when they come near the screen: walk down the page
    await expect
      .poll(
        async () => {
          await page.evaluate(() => window.scrollBy(0, window.innerHeight));
          return plots.count();
        },
        { timeout: 60000 },
      )
      .toBeGreaterThanOrEqual(3);
    for (let i = 0; i < (await plots.count()); i++) {
      const p = plots.nth(i);
      await p.scrollIntoViewIfNeeded();
      await expect(p.locator('.g-xtitle text, .g-ytitle text').first()).toBeAttached({ timeout: 30000 });
      const r = await p.evaluate((el) => {
        const box = el.getBoundingClientRect();
        return [...el.querySelectorAll('.g-xtitle text, .g-ytitle text, .gtitle')].map((t) => {
          const b = t.getBoundingClientRect();
          return {
            inside:
              b.left >= box.left - 1 &&
              b.right <= box.right + 1 &&
              b.top >= box.top - 1 &&
              b.bottom <= box.bottom + 1,
            text: t.textContent,
          };
        });
      });
      for (const t of r) expect(t.inside, `plot ${i}: "${t.text}"`).toBe(true);
    }
  });
}

/** Readouts of the animation at position t, computed here. */
function animAt(query: string, t: number) {
  const { values, model } = modelFor(query);
  const run = sampleRun(model, values.strategy as LightStrategy, animationLength(values.n), values.seed);
  return animationFrame(run, t);
}

test('animation: play, pause, and the readouts equal the model at the paused position; a link restores them; step adds one', async ({
  page,
}) => {
  const q = 'strategy=solid-angle&n=512&seed=21&t=0';
  await openScene(page, `#/area-light?${q}`);
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '0');
  const tl = page.getByTestId('timeline');
  await tl.getByRole('button', { name: /play/i }).click();
  await expect
    .poll(async () => Number(await page.getByTestId('anim-k').getAttribute('data-value')), { timeout: 20000 })
    .toBeGreaterThan(20);
  await tl.getByRole('button', { name: /pause/i }).click();
  await expect(tl).toHaveAttribute('data-playing', '0');
  await expect(page).toHaveURL(/[?&]t=\d+/);
  const t = Number(/[?&]t=(\d+)/.exec(page.url())![1]);
  const k = Number(await page.getByTestId('anim-k').getAttribute('data-value'));
  expect(k).toBe(t);
  const want = animAt(q.replace('t=0', `t=${t}`), t);
  expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(want.estimate, 6);
  expect(await readoutNumber(page, 'anim-stderr')).toBeCloseTo(want.stderr, 2);
  // the link with t and the seed reopens exactly there
  const url = page.url();
  const est = await readout(page, 'anim-estimate');
  await page.goto('about:blank');
  await openScene(page, url.slice(url.indexOf('#')));
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', String(t));
  expect(await readout(page, 'anim-estimate')).toBe(est);
  // step: one more sample
  await tl.getByRole('button', { name: /step/i }).click();
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', String(t + 1));
  expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(animAt(q, t + 1).estimate, 6);
});

test('animation: at the end the running estimate is the n-sample estimate; the floor images follow the timeline', async ({
  page,
}) => {
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area');
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '256');
  expect(await readout(page, 'anim-estimate')).toBe(await readout(page, 'estimate'));
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByText(/64 samples per pixel \(done\)/)).toBeVisible({ timeout: 30000 });
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area&t=64');
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByTestId('floor-spp')).toHaveAttribute('data-value', '16', { timeout: 30000 });
});

test('reduced motion: play=1 in the link starts paused; and no animation frames are requested while paused', async ({
  page,
}) => {
  await countAnimationFrames(page);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openScene(page, '#/area-light?play=1&t=10&n=512');
  const tl = page.getByTestId('timeline');
  await expect(tl).toHaveAttribute('data-playing', '0');
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '10');
  // let the 3D view and plots settle, then count frames over a quiet second
  await page.waitForLoadState('networkidle');
  await expect
    .poll(
      async () => {
        const a = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
        await page.waitForTimeout(1000);
        const b = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
        return b - a;
      },
      { timeout: 30000 },
    )
    .toBe(0);
});
