/**
 * What every scene of the catalogue shares, written once and run for each scene: the shared
 * timeline (reduced motion, no frames while paused or off screen, play / pause and the link),
 * the classroom first screen (present=1) and axe (WCAG 2.2 AA) in both themes at 1280 and 375 px.
 * A scene-specific check (its readouts against its model, its drags and keys) lives in that
 * scene's own spec.
 */
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { SCENES, type SceneInfo } from '../../src/kit/catalogue';
import { test, expect, openScene, countAnimationFrames } from './fixtures';

test.describe.configure({ timeout: 180_000 });

/** `#/path?query` with `extra` parameters appended. */
function link(s: SceneInfo, ...extra: string[]): string {
  const q = [s.examQuery, ...extra].filter(Boolean).join('&');
  return `#${s.path}${q ? `?${q}` : ''}`;
}

const frames = (page: Page) => page.evaluate(() => (window as unknown as { __raf: number }).__raf);

/**
 * Frames the page requested during one half-second window, measured inside the page. A
 * measurement interval, not a wait for a state: polled until it reads 0 (or never, which fails).
 */
function framesInWindow(page: Page): Promise<number> {
  return page.evaluate(async () => {
    const w = window as unknown as { __raf: number };
    const a = w.__raf;
    await new Promise((r) => setTimeout(r, 500));
    return w.__raf - a;
  });
}

/** Waits until the page requests no frame for a whole window (a settled, idle page). */
async function expectIdle(page: Page, what: string): Promise<void> {
  await expect.poll(() => framesInWindow(page), { timeout: 45_000, intervals: [0], message: what }).toBe(0);
}

const timelineT = async (page: Page) => Number(await page.getByTestId('timeline').getAttribute('data-t'));

/** Opens the page and waits until everything below the first screen has mounted (lazy sections). */
async function openWhole(page: Page, hash: string): Promise<void> {
  await openScene(page, hash);
  await page.evaluate(async () => {
    for (let y = 0, i = 0; y < document.body.scrollHeight && i < 200; y += innerHeight / 2, i++) {
      scrollTo(0, y);
      await new Promise((r) => setTimeout(r, 50));
    }
    scrollTo(0, 0);
  });
  await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
}

for (const s of SCENES) {
  test.describe(s.id, () => {
    test('reduced motion: play=1 in the link starts paused, the position holds, no frame is requested', async ({
      page,
    }) => {
      await countAnimationFrames(page);
      await page.emulateMedia({ reducedMotion: 'reduce' });
      await openScene(page, link(s, 'play=1'));
      const tl = page.getByTestId('timeline');
      await expect(tl).toHaveAttribute('data-playing', '0');
      await expect(page.getByTestId('timeline-play')).toHaveAttribute('aria-pressed', 'false');
      const t0 = await tl.getAttribute('data-t');
      await expectIdle(page, `${s.id}: frames go on under reduced motion`);
      await expect(tl).toHaveAttribute('data-t', t0 ?? '');
      await expect(tl).toHaveAttribute('data-playing', '0');
    });

    test('paused: no frames; playing: frames, none while the figure is off screen; pause: the link restores the position', async ({
      page,
    }) => {
      await countAnimationFrames(page);
      await openScene(page, link(s));
      const tl = page.getByTestId('timeline');
      await expect(tl).toHaveAttribute('data-playing', '0');
      await expectIdle(page, `${s.id}: frames while paused`);
      const start = await timelineT(page);

      await tl.scrollIntoViewIfNeeded();
      await page.getByTestId('timeline-play').click();
      await expect(tl).toHaveAttribute('data-playing', '1');
      await expect(page.getByTestId('timeline-play')).toHaveAttribute('aria-pressed', 'true');
      await expect.poll(() => timelineT(page), { timeout: 30_000 }).not.toBe(start);
      const before = await frames(page);
      await expect.poll(() => frames(page), { timeout: 30_000 }).toBeGreaterThan(before + 3);

      // off screen (the page scrolled to its end), the timeline holds: playing, but no frames
      await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
      await expect(tl).not.toBeInViewport();
      await expectIdle(page, `${s.id}: frames while the figure is off screen`);
      await expect(tl).toHaveAttribute('data-playing', '1');
      const held = await timelineT(page);
      await tl.scrollIntoViewIfNeeded();
      await expect.poll(() => timelineT(page), { timeout: 30_000 }).not.toBe(held);

      // pause: the button, the state and the link say the same, and the link brings it back
      await page.getByTestId('timeline-play').click();
      await expect(tl).toHaveAttribute('data-playing', '0');
      await expect(page.getByTestId('timeline-play')).toHaveAttribute('aria-pressed', 'false');
      const t = await tl.getAttribute('data-t');
      expect(t).not.toBeNull();
      await expect(page).toHaveURL(new RegExp(`[?&]t=${t!.replace('.', '\\.')}(&|$)`));
      const key = await page.getByTestId(s.keyReadout).first().getAttribute('data-value');
      await expectIdle(page, `${s.id}: frames after pausing`);
      const url = page.url();
      await page.goto('about:blank');
      await page.goto(url);
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', t!);
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
      await expect(page.getByTestId(s.keyReadout).first()).toHaveAttribute('data-value', key ?? '');
    });

    test('present=1 at 1280×720: the stage, its figure and its transport are the first screen', async ({
      page,
    }) => {
      await page.setViewportSize({ width: 1280, height: 720 });
      await openScene(page, link(s, 'present=1'));
      await page.evaluate(() => window.scrollTo(0, 0));
      const stage = page.getByTestId('scene-stage');
      await expect(stage).toBeInViewport({ ratio: 1 });
      await expect(stage.getByTestId('timeline')).toBeInViewport({ ratio: 1 });
      const outside = await page.evaluate(() => {
        const out: string[] = [];
        for (const el of document.querySelectorAll('[data-testid="scene-stage"] .stage-body *')) {
          const r = el.getBoundingClientRect();
          if (r.width === 0 && r.height === 0) continue;
          if (el.closest('option, .sr-only')) continue;
          if (r.top < -1 || r.left < -1 || r.bottom > innerHeight + 1 || r.right > innerWidth + 1)
            out.push(`${el.tagName.toLowerCase()} ${(el as HTMLElement).dataset.testid ?? el.className}`);
        }
        return out.slice(0, 5);
      });
      expect(outside, `${s.id}: parts of the stage outside the first screen`).toEqual([]);
      const box = (await stage.boundingBox())!;
      expect(box.height, `${s.id}: the stage is ${Math.round(box.height)} px tall`).toBeGreaterThan(
        0.55 * 720,
      );
      await expect(page.getByTestId('controls-drawer')).toBeHidden();
    });

    for (const theme of ['light', 'dark'] as const) {
      test(`axe (WCAG 2.2 AA), ${theme} theme: clean at 1280 and at 375 px`, async ({ page }) => {
        test.setTimeout(480_000);
        const found: string[] = [];
        // one load per theme: the page is scanned wide, then narrowed to a phone's width (its
        // layout follows the viewport, as on a rotated tablet) and scanned again
        await page.setViewportSize({ width: 1280, height: 900 });
        await openWhole(page, link(s, `theme=${theme}`));
        for (const width of [1280, 375]) {
          if (width !== 1280) {
            await page.setViewportSize({ width, height: 812 });
            await expect
              .poll(() => page.evaluate(() => document.documentElement.clientWidth))
              .toBeLessThanOrEqual(width);
          }
          const r = await new AxeBuilder({ page })
            .withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'])
            .analyze();
          for (const v of r.violations)
            found.push(
              `${width} ${v.id}: ${v.nodes
                .slice(0, 4)
                .map((n) => n.target.join(' '))
                .join(', ')}`,
            );
        }
        expect(found).toEqual([]);
      });
    }
  });
}
