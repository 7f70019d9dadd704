/**
 * Browser tests of #/area-light: for several placements of the light the chosen estimator agrees
 * with the analytic reference within 3σ (read from data-value), and the solid angle matches a
 * closed form computed here (the corner formula by inclusion–exclusion in the light's own frame,
 * independent of the app's Van Oosterom–Strackee code); bad input gives a message and a fallback.
 */
import AxeBuilder from '@axe-core/playwright';
import { test, expect, openScene, readout, readoutNumber } from './fixtures';

type V3 = [number, number, number];

/**
 * Solid angle of a w × h rectangle (centre c, tilt t degrees about its x axis; frame as in the
 * contract: ex = (1,0,0), ey = (0,cos t, sin t), n = (0, sin t, −cos t)) seen from p:
 * Ω = |F(x1,y1) − F(x0,y1) − F(x1,y0) + F(x0,y0)|, F(a,b) = atan(ab / (d √(a²+b²+d²))).
 */
function closedFormOmega(p: V3, c: V3, w: number, h: number, tiltDeg: number): number {
  const t = (tiltDeg * Math.PI) / 180;
  const ex: V3 = [1, 0, 0], ey: V3 = [0, Math.cos(t), Math.sin(t)], n: V3 = [0, Math.sin(t), -Math.cos(t)];
  const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const rel: V3 = [c[0] - p[0], c[1] - p[1], c[2] - p[2]];
  const d = Math.abs(dot(rel, n));
  const cx = dot(rel, ex), cy = dot(rel, ey);
  const F = (a: number, b: number) => Math.atan((a * b) / (d * Math.sqrt(a * a + b * b + d * d)));
  const x0 = cx - w / 2, x1 = cx + w / 2, y0 = cy - h / 2, y1 = cy + h / 2;
  return Math.abs(F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0));
}

const placements: Array<{ name: string; p: V3; lc: V3; ls: [number, number]; tilt: number; strategy: string; zero?: boolean }> = [
  { name: 'overhead', p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 0, strategy: 'area' },
  { name: 'off-axis, solid-angle sampling', p: [0.2, -0.4, 0], lc: [0.9, 0.3, 1.5], ls: [1.2, 0.8], tilt: 0, strategy: 'solid-angle' },
  { name: 'tilted', p: [0, 0, 0], lc: [0, 1, 1.5], ls: [1.5, 1], tilt: -45, strategy: 'area' },
  { name: 'partly below the horizon', p: [0, 0, 0], lc: [0, 1, 0.2], ls: [1, 1], tilt: -90, strategy: 'solid-angle' },
  { name: 'near, cosine sampling', p: [0.1, 0, 0], lc: [0, 0, 0.25], ls: [2, 2], tilt: 0, strategy: 'cosine' },
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
  await openScene(page, '#/area-light?lc=0.7,-0.3,1.5&ls=1.2,0.8');
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
  expect(await readoutNumber(page, 'solid-angle')).toBeCloseTo(closedFormOmega([0, 0, 0], [0, 0, 2], 1, 1, 0), 12);
});

test('shading point on the light: a clear message and a safe fallback', async ({ page }) => {
  await openScene(page, '#/area-light?p=0.1,0.1,2');
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

test('dark theme: no serious or critical axe violations (the highlighted KaTeX boxes keep dark text)', async ({ page }) => {
  await openScene(page, '#/area-light?theme=dark&occluder=1');
  await page.waitForTimeout(2000);
  const r = await new AxeBuilder({ page }).analyze();
  const bad = r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => v.id);
  expect(bad).toEqual([]);
});

test('a tiny, distant light (10⁶ away): Ω matches A cos θ_l / r² (exact to O((size/d)²)) to 1e-11; estimates exact', async ({ page }) => {
  await openScene(page, '#/area-light?lc=3,-2,1000000&ls=1,0.5&strategy=solid-angle&n=512');
  const omega = await readoutNumber(page, 'solid-angle');
  // The corner formula's four terms cancel at this distance, so the check is the small-patch limit,
  // whose own error is O((size/d)²) ≈ 1e-12.
  const d = 1e6, cx = 3, cy = -2, w = 1, h = 0.5;
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
