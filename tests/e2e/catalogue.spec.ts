/**
 * What every scene of the catalogue shares, written once and run for each scene, two tests
 * each: the whole page as a reader meets it (./wholePage.ts: axe in both themes and at both
 * widths, the WCAG criteria axe does not test, carets, formula wrapping); the shared timeline
 * (opened for a reader who only looks, the first screen first: ./firstScreen.ts; reduced motion,
 * no frames while paused or off screen, play / pause and the link, opened again in the same tab,
 * which mounts the scene anew from it), and on the
 * same page the lecture room (present=1 with ask=1: results held back until Reveal, then the
 * stage is the first screen, legible from the back of the room). A scene-specific check (its readouts against its
 * model, its drags and keys) lives in that scene's own spec.
 */
import type { Page } from '@playwright/test';
import { SCENES, type SceneInfo } from '../../src/kit/catalogue';
import { test, expect, openScene, countAnimationFrames, followLinkAnew } from './fixtures';
import { checkWholePage } from './wholePage';
import { firstScreen, recordFirstScreen } from './firstScreen';

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

for (const s of SCENES) {
  test.describe(s.id, () => {
    test('the whole page, calm as it opens (tab stops), light at 1280 px and, folds open, dark at 375 px: axe clean, targets, reflow, text spacing, focus, no caret, formulas whole', async ({
      page,
    }) => {
      test.setTimeout(240_000);
      await checkWholePage(page, link(s), { scene: s });
    });

    test('the first screen first, then the timeline: reduced motion holds play=1; paused, no frames; playing, none off screen; pause writes a link that restores it; then the room, present=1&ask=1: results held back until Reveal, the stage the first screen, its text ≥ 18 px', async ({
      page,
    }) => {
      await countAnimationFrames(page);
      await recordFirstScreen(page);
      // under reduced motion a link asking to play opens paused, and nothing is drawn
      await page.emulateMedia({ reducedMotion: 'reduce' });
      // opened for a reader who only looks: nothing far below the first screen is mounted or
      // typeset before the page settles; then, with no scroll, every section mounts
      await openScene(page, link(s, 'play=1'));
      await expect(page.locator('html[data-settled]')).toBeAttached({ timeout: 60_000 });
      const opening = await firstScreen(page);
      expect(await page.evaluate(() => scrollY), 'the page was not scrolled').toBe(0);
      expect(opening.early, `${s.id}: far sections or formulas done before the page settled`).toEqual([]);
      expect(opening.farSeen, `${s.id}: the page has work far below its first screen`).toBeGreaterThan(0);
      expect(opening.loadingShown, `${s.id}: the shell was shown before its scene`).toBe(false);
      const tl = page.getByTestId('timeline');
      await expect(tl).toHaveAttribute('data-playing', '0');
      await expect(page.getByTestId('timeline-play')).toHaveAttribute('aria-pressed', 'false');
      const start = await timelineT(page);
      await expectIdle(page, `${s.id}: frames go on under reduced motion`);
      expect(await timelineT(page)).toBe(start);
      await expect(tl).toHaveAttribute('data-playing', '0');

      // the reader's own Play still plays
      await page.emulateMedia({ reducedMotion: 'no-preference' });
      await tl.scrollIntoViewIfNeeded();
      const play = page.getByTestId('timeline-play');
      const width = (await play.boundingBox())!.width;
      await play.click();
      await expect(tl).toHaveAttribute('data-playing', '1');
      await expect(play).toHaveAttribute('aria-pressed', 'true');
      // Play and Pause are one width: the transport row does not shift
      expect(Math.abs((await play.boundingBox())!.width - width)).toBeLessThanOrEqual(0.5);
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
      await play.click();
      await expect(tl).toHaveAttribute('data-playing', '0');
      await expect(play).toHaveAttribute('aria-pressed', 'false');
      const t = await tl.getAttribute('data-t');
      expect(t).not.toBeNull();
      await expect(page).toHaveURL(new RegExp(`[?&]t=${t!.replace('.', '\\.')}(&|$)`));
      const key = await page.getByTestId(s.keyReadout).first().getAttribute('data-value');
      await expectIdle(page, `${s.id}: frames after pausing`);
      // the link opened in this tab: the scene is left and mounted again from the link at t = 0,
      // which must show 0 (the position comes from the link, not from memory), then the paused
      // link itself is followed on that page and brings the position back
      const address = new URL(page.url()).hash;
      await followLinkAnew(page, address.replace(/([?&])t=[^&]*/, '$1t=0'));
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', '0');
      await page.evaluate((h) => (location.hash = h), address);
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', t!);
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
      await expect(page.getByTestId(s.keyReadout).first()).toHaveAttribute('data-value', key ?? '');

      // the lecture room, on the same page: present=1&ask=1 at 1280×720 holds the results back at
      // t = 0 until Reveal; then the stage is the first screen, its text ≥ 18 px
      await page.setViewportSize({ width: 1280, height: 720 });
      await openScene(page, link(s, 'present=1', 'ask=1'));
      await page.evaluate(() => window.scrollTo(0, 0));
      // asking: the prompt, results hidden, the animation held at its start
      await expect(page.getByTestId('ask-prompt')).toBeVisible();
      expect(
        await page.getByTestId('ask-hidden').count(),
        `${s.id}: nothing is hidden under ask=1`,
      ).toBeGreaterThan(0);
      const roomTl = page.locator('.timeline').first();
      if ((await roomTl.count()) > 0) {
        await expect(roomTl, `${s.id}: the animation is held at its start`).toHaveAttribute('data-t', '0');
        await expect(roomTl).toHaveAttribute('data-playing', '0');
      }
      // the title, the share bar and the way back stand in one row; no embed code in the room
      const h1 = (await page.locator('main h1').boundingBox())!;
      const bar = (await page.locator('.share-bar').boundingBox())!;
      const back = (await page.locator('main .back-link').boundingBox())!;
      expect(bar.height, `${s.id}: the share bar wraps`).toBeLessThan(70);
      expect(bar.x, s.id).toBeGreaterThan(h1.x + h1.width);
      expect(back.x, s.id).toBeGreaterThan(bar.x + bar.width - 1);
      expect(Math.abs(bar.y + bar.height / 2 - (h1.y + h1.height / 2)), s.id).toBeLessThan(20);
      await expect(page.getByTestId('copy-embed')).toHaveCount(0);

      await page.getByTestId('reveal').click();
      await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
      await page.evaluate(() => window.scrollTo(0, 0));
      const stage = page.getByTestId('scene-stage');
      await expect(stage).toBeInViewport({ ratio: 1 });
      await expect(stage.getByTestId('timeline')).toBeInViewport({ ratio: 1 });
      const report = await page.evaluate(() => {
        const outside: string[] = [];
        const small: string[] = [];
        const stage = document.querySelector('[data-testid="scene-stage"]')!;
        for (const el of stage.querySelectorAll('.stage-body *')) {
          const r = el.getBoundingClientRect();
          if (r.width === 0 && r.height === 0) continue;
          if (el.closest('option, .sr-only')) continue;
          if (r.top < -1 || r.left < -1 || r.bottom > innerHeight + 1 || r.right > innerWidth + 1)
            outside.push(`${el.tagName.toLowerCase()} ${(el as HTMLElement).dataset.testid ?? el.className}`);
        }
        const walker = document.createTreeWalker(stage, NodeFilter.SHOW_TEXT);
        for (let n = walker.nextNode(); n; n = walker.nextNode()) {
          const text = (n.nodeValue ?? '').trim();
          const el = n.parentElement;
          if (!text || !el || el.closest('.sr-only, [hidden], [aria-hidden="true"] kbd, .katex-mathml'))
            continue;
          const r = el.getBoundingClientRect();
          if (r.width === 0 || r.height === 0 || getComputedStyle(el).visibility === 'hidden') continue;
          // KaTeX sets sub- and superscripts smaller by design: judge a formula by its base size
          const px = parseFloat(getComputedStyle(el.closest('.katex') ?? el).fontSize);
          if (px < 17.5) small.push(`${JSON.stringify(text.slice(0, 30))} at ${px.toFixed(1)} px`);
        }
        return { outside: outside.slice(0, 5), small: small.slice(0, 8) };
      });
      expect(report.outside, `${s.id}: parts of the stage outside the first screen`).toEqual([]);
      expect(report.small, `${s.id}: text under 18 px on the stage`).toEqual([]);
      const box = (await stage.boundingBox())!;
      expect(box.height, `${s.id}: the stage is ${Math.round(box.height)} px tall`).toBeGreaterThan(
        0.55 * 720,
      );
      await expect(page.getByTestId('controls-drawer')).toBeHidden();
    });
  });
}
