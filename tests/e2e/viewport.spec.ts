// The shared 3D viewport (src/three): keyboard orbit and zoom, a visible focus ring, "Reset view",
// a labelled axis triad, and no animation frames while idle. Checked on #/ray-sphere and #/hemisphere.
import AxeBuilder from '@axe-core/playwright';
import { test, expect, openScene, countAnimationFrames } from './fixtures';

test.describe('shared 3D viewport', () => {
  test('arrows orbit, + / − zoom, Reset view and Home restore; focus is visible; axes are labelled', async ({
    page,
  }) => {
    await openScene(page, '#/ray-sphere');
    const vp = page.getByTestId('view-3d');
    await vp.scrollIntoViewIfNeeded();
    await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
    const triad = page.getByTestId('view-3d-axes');
    await expect(triad).toHaveAttribute('data-distance', /\d/);
    // x, y, z labelled; no φ = 0 on this scene (it has no azimuth)
    const labels = await triad.locator('text').allTextContents();
    expect(labels.sort()).toEqual(['x', 'y', 'z']);
    const home = { d: await triad.getAttribute('data-distance'), x: await triad.getAttribute('data-x-axis') };

    await vp.focus();
    // the focus ring is drawn (keyboard focus → :focus-visible)
    await page.keyboard.press('Shift+Tab');
    await page.keyboard.press('Tab');
    await expect(vp).toBeFocused();
    const outline = await vp.evaluate((el) => {
      const s = getComputedStyle(el);
      return { style: s.outlineStyle, width: parseFloat(s.outlineWidth) };
    });
    expect(outline.style).not.toBe('none');
    expect(outline.width).toBeGreaterThanOrEqual(2);

    const scrollBefore = await page.evaluate(() => window.scrollY);
    await page.keyboard.press('ArrowLeft');
    await expect.poll(() => triad.getAttribute('data-x-axis')).not.toBe(home.x);
    expect(await page.evaluate(() => window.scrollY), 'arrow keys do not scroll the page').toBe(scrollBefore);
    // the distance is unchanged by orbiting; + brings the camera closer by 1/1.15
    expect(Number(await triad.getAttribute('data-distance'))).toBeCloseTo(Number(home.d), 3);
    await page.keyboard.press('+');
    await expect
      .poll(async () => Number(await triad.getAttribute('data-distance')))
      .toBeCloseTo(Number(home.d) / 1.15, 3);
    await page.keyboard.press('-');
    await page.keyboard.press('-');
    await expect
      .poll(async () => Number(await triad.getAttribute('data-distance')))
      .toBeCloseTo(Number(home.d) * 1.15, 3);

    await page.getByTestId('view-3d-reset').click();
    await expect.poll(() => triad.getAttribute('data-x-axis')).toBe(home.x);
    await expect(triad).toHaveAttribute('data-distance', home.d!);

    await vp.focus();
    await page.keyboard.press('ArrowUp');
    await expect.poll(() => triad.getAttribute('data-x-axis')).not.toBe(home.x);
    await page.keyboard.press('Home');
    await expect.poll(() => triad.getAttribute('data-x-axis')).toBe(home.x);

    // the hint says how, and the accessible name too
    await expect(page.locator('.viewport-hint').first()).toContainText('← → ↑ ↓ orbit');
    await expect(vp).toHaveAttribute('aria-label', /arrow keys to orbit/);
  });

  test('the hemisphere view marks φ = 0 on the x axis', async ({ page }) => {
    await openScene(page, '#/hemisphere?n=64');
    const vp = page.getByTestId('hemisphere-3d');
    await vp.scrollIntoViewIfNeeded();
    await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
    const x = page.getByTestId('hemisphere-3d-axes').locator('g[data-axis="x"] text');
    await expect(x).toHaveText(['x', 'φ = 0']);
  });

  test('an idle 3D view requests no animation frames', async ({ page }) => {
    await countAnimationFrames(page);
    await openScene(page, '#/ray-sphere');
    const vp = page.getByTestId('view-3d');
    await vp.scrollIntoViewIfNeeded();
    await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
    await expect(page.getByTestId('view-3d-axes')).toHaveAttribute('data-distance', /\d/);
    // let lazy panels settle, then count over a quiet second
    await expect
      .poll(
        async () => {
          const a = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
          await page.evaluate(() => new Promise((r) => setTimeout(r, 1000)));
          const b = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
          return b - a;
        },
        { timeout: 30_000, intervals: [0] },
      )
      .toBe(0);
    // one key press renders once, then it is quiet again
    await vp.focus();
    const before = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
    await page.keyboard.press('ArrowRight');
    await page.evaluate(() => new Promise((r) => setTimeout(r, 800)));
    const after = await page.evaluate(() => (window as unknown as { __raf: number }).__raf);
    expect(after - before).toBeGreaterThanOrEqual(1);
    expect(after - before).toBeLessThanOrEqual(3);
  });

  test.describe('on a touch screen', () => {
    test.use({ viewport: { width: 412, height: 823 }, isMobile: true, hasTouch: true });

    test('the 3D view waits to be asked: no three.js until a tap; the page scrolls through it; Enter starts it too', async ({
      page,
    }) => {
      test.setTimeout(120_000);
      const threeRequests: string[] = [];
      page.on('request', (r) => {
        if (/vendor-three/.test(r.url())) threeRequests.push(r.url());
      });
      await openScene(page, '#/hemisphere?n=64');
      const vp = page.getByTestId('hemisphere-3d');
      await vp.scrollIntoViewIfNeeded();
      await expect(vp).toHaveAttribute('data-status', 'idle');
      await expect(vp).toHaveAttribute('aria-label', /press Enter to start/);
      // it says what it would show, and swipes over it scroll the page (no touch capture)
      await expect(vp.locator('.viewport-poster')).toContainText('upper hemisphere');
      expect(await vp.evaluate((el) => getComputedStyle(el).touchAction)).toBe('auto');
      expect(threeRequests, 'three.js is not loaded before it is asked for').toEqual([]);
      // the waiting view is accessible (its button, its text's contrast)
      const axe = await new AxeBuilder({ page }).include('[data-testid="hemisphere-3d"]').analyze();
      expect(
        axe.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => v.id),
      ).toEqual([]);
      await page.getByTestId('hemisphere-3d-start').tap();
      await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
      expect(threeRequests.length).toBeGreaterThan(0);
      // the keyboard's place is kept on the view, which now orbits
      await expect(vp).toBeFocused();
      await expect(page.getByTestId('hemisphere-3d-axes')).toHaveAttribute('data-distance', /\d/);
      expect(await vp.evaluate((el) => getComputedStyle(el).touchAction)).toBe('none');

      // another scene: focusing the idle view and pressing Enter starts it (no pointer needed)
      await openScene(page, '#/area-light');
      const al = page.locator('.viewport').first();
      await al.scrollIntoViewIfNeeded();
      await expect(al).toHaveAttribute('data-status', 'idle');
      // the scene's overlays act on the view: none is offered before it starts
      await expect(page.locator('.al-frame')).toHaveCount(0);
      await al.focus();
      await page.keyboard.press('Enter');
      await expect(al).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
      await expect(page.locator('.al-frame')).toHaveCount(1);
    });
  });
});
