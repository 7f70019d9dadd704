// The shared 3D viewport (src/three): keyboard orbit and zoom, a visible focus ring, "Reset view",
// a labelled axis triad, and no animation frames while idle. Checked on #/ray-sphere and #/hemisphere
// (on a touch screen: the view waits to be asked). Space on a view's button in classroom mode: stage.spec.ts.
// Its orbit and zoom buttons (the single-pointer alternative to dragging) move the camera by mouse,
// touch and keyboard and are at least 24 × 24 (on #/area-light); on every scene with a 3D view they
// never lie over each other, the scene's overlays, the axis labels or the stage's buttons (on #/area-light
// at 320 px and in classroom mode at 1280 px).
import AxeBuilder from '@axe-core/playwright';
import type { Locator, Page } from '@playwright/test';
import { SCENES } from '../../src/kit/catalogue';
import { test, expect, openScene, countAnimationFrames } from './fixtures';

const ORBITS = ['Orbit left', 'Orbit right', 'Orbit up', 'Orbit down'] as const;

/** The scene's first 3D view, scrolled to and started; null when the scene has none. */
async function firstView(page: Page, hash: string): Promise<Locator | null> {
  await openScene(page, hash);
  const vp = page.locator('.viewport').first();
  if ((await vp.count()) === 0) return null;
  await vp.scrollIntoViewIfNeeded();
  const start = vp.locator('.viewport-start');
  if (await start.count()) await start.click();
  await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 60_000 });
  await expect(vp.locator('.viewport-triad')).toHaveAttribute('data-distance', /\d/);
  await vp.scrollIntoViewIfNeeded();
  return vp;
}

/** The camera as the triad draws it (x axis on screen, distance): changes when the camera moves. */
async function camera(vp: Locator): Promise<{ x: string; d: number }> {
  const t = vp.locator('.viewport-triad');
  return { x: (await t.getAttribute('data-x-axis')) ?? '', d: Number(await t.getAttribute('data-distance')) };
}

test.describe('shared 3D viewport', () => {
  test('an idle 3D view requests no animation frames; arrows orbit, + / − zoom, Reset view and Home restore; focus is visible; axes are labelled', async ({
    page,
  }) => {
    test.setTimeout(120_000);
    await countAnimationFrames(page);
    await openScene(page, '#/ray-sphere?open=view3d');
    const vp = page.getByTestId('view-3d');
    await vp.scrollIntoViewIfNeeded();
    await expect(vp).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
    const triad = page.getByTestId('view-3d-axes');
    await expect(triad).toHaveAttribute('data-distance', /\d/);
    // x, y, z labelled; no φ = 0 on this scene (it has no azimuth)
    const labels = await triad.locator('text').allTextContents();
    expect(labels.sort()).toEqual(['x', 'y', 'z']);
    const home = { d: await triad.getAttribute('data-distance'), x: await triad.getAttribute('data-x-axis') };

    await test.step('an idle 3D view requests no animation frames; one key press renders once', async () => {
      type Frames = { __raf: number; __rafPending: number };
      const frames = () =>
        page.evaluate(() => {
          const w = window as unknown as Frames;
          return { __raf: w.__raf, __rafPending: w.__rafPending };
        });
      // once lazy panels have settled, no frame is requested: no render loop runs
      await expect.poll(async () => (await frames()).__rafPending, { timeout: 30_000 }).toBe(0);
      // one key press renders once (a frame or few), then nothing is requested again
      await vp.focus();
      const before = (await frames()).__raf;
      await page.keyboard.press('ArrowRight');
      await expect.poll(async () => (await frames()).__raf - before).toBeGreaterThanOrEqual(1);
      await expect.poll(async () => (await frames()).__rafPending).toBe(0);
      const after = (await frames()).__raf;
      expect(after - before).toBeLessThanOrEqual(3);
    });
    await page.getByTestId('view-3d-reset').click();
    await expect.poll(() => triad.getAttribute('data-x-axis')).toBe(home.x);

    await test.step('arrows orbit, + / − zoom, Reset view and Home restore; focus is visible', async () => {
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
      expect(await page.evaluate(() => window.scrollY), 'arrow keys do not scroll the page').toBe(
        scrollBefore,
      );
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
  });

  // the view and its buttons are the shared viewport's (src/three), the same on every scene: checked on one
  test(`area-light at 320 px, and at 1280 px with present=1: the view's buttons, its axis labels and the stage's buttons never overlap; in classroom mode the axis labels are drawn at 18 px or more; the orbit and zoom buttons move the camera by mouse and keyboard`, async ({
    page,
  }) => {
    const s = SCENES.find((x) => x.id === 'area-light')!;
    test.setTimeout(240_000);
    const found: string[] = [];
    // the narrowest phone and the classroom screen: the two ends of the view's sizes
    for (const [present, width] of [
      [false, 320],
      [true, 1280],
    ] as const) {
      await page.setViewportSize({ width, height: width === 1280 ? 720 : 740 });
      const vp = await firstView(page, `#${s.path}${present ? '?present=1' : ''}`);
      test.skip(vp === null, `${s.id} has no 3D view`);
      const where = `${width} px${present ? ', present=1' : ''}`;
      found.push(
        ...(await vp!.evaluate((view, where) => {
          const box = (el: Element) => el.getBoundingClientRect();
          const name = (el: Element) =>
            (el.getAttribute('aria-label') ?? el.textContent ?? '').trim().slice(0, 24) || el.tagName;
          const visible = (el: Element) => {
            const r = box(el);
            return r.width > 0 && r.height > 0 && getComputedStyle(el).visibility !== 'hidden';
          };
          const meets = (a: DOMRect, b: DOMRect) =>
            a.left < b.right - 0.5 &&
            b.left < a.right - 0.5 &&
            a.top < b.bottom - 0.5 &&
            b.top < a.bottom - 0.5;
          // the view's own buttons and the scene's overlays on it (legends, "Frame the scene")
          const overlays = [...view.children].filter(
            (el) => !el.matches('canvas, .viewport-triad, .viewport-tools, .viewport-msg') && visible(el),
          );
          const buttons = [...view.querySelectorAll('.viewport-tools button'), ...overlays].filter(visible);
          const labels = [...view.querySelectorAll('.viewport-triad text')].filter(visible);
          const stage = view.closest('[data-testid="scene-stage"]');
          const stageButtons = stage ? [...stage.querySelectorAll(':scope > .stage-bar > button')] : [];
          const fullscreen = document.querySelector('[data-testid="fullscreen"]');
          if (fullscreen && !stageButtons.includes(fullscreen)) stageButtons.push(fullscreen);
          const out: string[] = [];
          const v = box(view);
          buttons.forEach((a, i) => {
            const r = box(a);
            if (
              r.left < v.left - 0.5 ||
              r.right > v.right + 0.5 ||
              r.top < v.top - 0.5 ||
              r.bottom > v.bottom + 0.5
            )
              out.push(`${where}: "${name(a)}" reaches outside the view`);
            for (const b of buttons.slice(i + 1))
              if (meets(r, box(b))) out.push(`${where}: "${name(a)}" over "${name(b)}"`);
            for (const l of labels)
              if (meets(r, box(l))) out.push(`${where}: "${name(a)}" over the axis label "${name(l)}"`);
            for (const b of stageButtons.filter(visible))
              if (meets(r, box(b))) out.push(`${where}: "${name(a)}" over the stage's "${name(b)}"`);
          });
          return out;
        }, where)),
      );
      if (present) {
        const sizes = await vp!.locator('.viewport-triad').evaluate((svg) => {
          const s = svg as SVGSVGElement;
          // the text's font size in the drawing's units, times the drawing's scale on screen
          const scale = s.getBoundingClientRect().width / s.viewBox.baseVal.width;
          return [...s.querySelectorAll('text')].map((t) => ({
            text: t.textContent,
            computed: parseFloat(getComputedStyle(t).fontSize),
            drawn: parseFloat(getComputedStyle(t).fontSize) * scale,
          }));
        });
        expect(sizes.length).toBeGreaterThanOrEqual(3);
        for (const z of sizes) {
          expect(z.drawn, `${z.text} on screen`).toBeGreaterThanOrEqual(17.9);
          expect(z.computed, `${z.text} font-size`).toBeGreaterThanOrEqual(17.9);
        }
      }
    }
    expect(found).toEqual([]);

    await test.step('the orbit and zoom buttons move the camera by mouse and keyboard; Reset view returns', async () => {
      // on the classroom screen the loop above left open, the view started
      const vp: Locator | null = page.locator('.viewport').first();
      const home = await camera(vp!);
      // each button is named, at least 24 × 24 CSS px, and moves the camera one step
      for (const name of ORBITS) {
        const b = vp!.getByRole('button', { name, exact: true });
        const box = (await b.boundingBox())!;
        expect(box.width, `${name} width`).toBeGreaterThanOrEqual(24);
        expect(box.height, `${name} height`).toBeGreaterThanOrEqual(24);
        const before = await camera(vp!);
        await b.click();
        await expect
          .poll(async () => (await camera(vp!)).x, { message: `${name} orbits` })
          .not.toBe(before.x);
        expect((await camera(vp!)).d, 'orbiting keeps the distance').toBeCloseTo(home.d, 3);
      }
      await vp!.getByRole('button', { name: 'Zoom in', exact: true }).click();
      await expect.poll(async () => (await camera(vp!)).d).toBeCloseTo(home.d / 1.15, 3);
      // by keyboard: Enter on Zoom out, Space on Orbit left
      await vp!.getByRole('button', { name: 'Zoom out', exact: true }).focus();
      await page.keyboard.press('Enter');
      await expect.poll(async () => (await camera(vp!)).d).toBeCloseTo(home.d, 3);
      const before = await camera(vp!);
      await vp!.getByRole('button', { name: 'Orbit left', exact: true }).focus();
      await page.keyboard.press('Space');
      await expect.poll(async () => (await camera(vp!)).x).not.toBe(before.x);
      await vp!.getByRole('button', { name: 'Reset view', exact: true }).click();
      await expect.poll(async () => (await camera(vp!)).x).toBe(home.x);
      expect((await camera(vp!)).d).toBeCloseTo(home.d, 3);
    });
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
      // (in the page, as the whole-page pass runs axe: tests/e2e/wholePage.ts says why)
      const axe = await new AxeBuilder({ page })
        .include('[data-testid="hemisphere-3d"]')
        .setLegacyMode(true)
        .analyze();
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
      // a tap on an orbit button orbits (the single-pointer alternative to a swipe)
      const triadX = () => page.getByTestId('hemisphere-3d-axes').getAttribute('data-x-axis');
      const before = await triadX();
      await page.getByTestId('hemisphere-3d-up').tap();
      await expect.poll(triadX).not.toBe(before);

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
