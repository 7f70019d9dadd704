/**
 * WCAG 2.2 AA on every route, beyond the component tests of a11y.spec.ts: axe (wcag2a, wcag2aa,
 * wcag21aa, wcag22aa) in both themes at 375 and 1280 px, target sizes at 375 px, reflow at 320 px,
 * text spacing, focus never hidden under something fixed or sticky.
 */
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { QUESTIONS, SCENES } from '../../src/kit/catalogue';
import { test, expect, openScene } from './fixtures';
import {
  applyTextSpacing,
  clippedText,
  focusObscured,
  sidewaysOverflow,
  smallTargets,
  weakFocusRing,
} from './wcag';

test.describe.configure({ timeout: 300_000 });

const ROUTES = ['#/', '#/guide', '#/practice', '#/accessibility', ...SCENES.map((s) => `#${s.path}`)];

async function open(page: Page, hash: string) {
  await openScene(page, hash);
  // everything that mounts on the way down (deferred sections, lazy plots) is on the page
  // (stepped on a timer, not per animation frame: a loaded machine may draw no frame for a while,
  // and bounded, in case a section that mounts on the way makes the page grow as it is scrolled)
  await page.evaluate(async () => {
    for (let y = 0, i = 0; y < document.body.scrollHeight && i < 200; y += innerHeight / 2, i++) {
      scrollTo(0, y);
      await new Promise((r) => setTimeout(r, 50));
    }
    scrollTo(0, 0);
  });
  await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
}

/** Text nodes on screen with a caret in them (code, TeX source and hidden text aside). */
function visibleCarets(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const out: string[] = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const text = n.nodeValue ?? '';
      const el = n.parentElement;
      if (!text.includes('^') || !el) continue;
      // code a reader types or reads as code (expression syntax, TeX source), and what is not shown
      if (
        el.closest(
          'code, pre, kbd, samp, textarea, script, style, .katex-mathml, [hidden], [aria-hidden="true"]',
        )
      )
        continue;
      if (el.getClientRects().length === 0 || getComputedStyle(el).visibility === 'hidden') continue;
      const at = text.indexOf('^');
      out.push(JSON.stringify(text.slice(Math.max(0, at - 30), at + 20)));
    }
    return out;
  });
}

function withTheme(hash: string, theme: 'light' | 'dark') {
  return `${hash}${hash.includes('?') ? '&' : '?'}theme=${theme}`;
}

for (const route of ROUTES) {
  test.describe(route, () => {
    test(`axe wcag2a/2aa/21aa/22aa: clean in both themes at 375 and 1280 px`, async ({ page }) => {
      const found: string[] = [];
      for (const width of [375, 1280]) {
        await page.setViewportSize({ width, height: width === 375 ? 812 : 900 });
        for (const theme of ['light', 'dark'] as const) {
          await open(page, withTheme(route, theme));
          const r = await new AxeBuilder({ page })
            .withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'])
            .analyze();
          for (const v of r.violations)
            found.push(
              `${width} ${theme} ${v.id}: ${v.nodes
                .slice(0, 4)
                .map((n) => n.target.join(' '))
                .join(', ')}`,
            );
        }
      }
      expect(found).toEqual([]);
    });

    test('375 px: every target is ≥ 24 × 24 or spaced; 320 px: no sideways scrolling', async ({ page }) => {
      await page.setViewportSize({ width: 375, height: 812 });
      await open(page, route);
      expect(await smallTargets(page)).toEqual([]);
      await page.setViewportSize({ width: 320, height: 640 });
      await expect.poll(() => sidewaysOverflow(page), { timeout: 15_000 }).toEqual([]);
    });

    test('no caret in the visible text: powers are written as superscripts', async ({ page }) => {
      await open(page, route);
      // every formula still waiting for KaTeX shows its plain-text reading: that has none either
      const carets = await visibleCarets(page);
      expect(carets).toEqual([]);
    });

    test('text spacing (1.4.12): nothing clipped; tabbing, focus is never hidden (2.4.11) and its ring keeps 3:1 (1.4.11)', async ({
      page,
    }) => {
      await page.setViewportSize({ width: 375, height: 812 });
      await open(page, route);
      await applyTextSpacing(page);
      expect(await clippedText(page)).toEqual([]);
      const hidden: string[] = [];
      for (let i = 0; i < 40; i++) {
        await page.keyboard.press('Tab');
        const why = await focusObscured(page);
        if (why) hidden.push(why);
        const ring = await weakFocusRing(page);
        if (ring) hidden.push(ring);
      }
      expect(hidden).toEqual([]);
    });
  });
}

for (const s of SCENES) {
  test(`${s.path} in classroom mode (present=1): with the controls drawer open, focus is never hidden`, async ({
    page,
  }) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openScene(page, `#${s.path}?present=1`);
    const toggle = page.getByTestId('controls-drawer-toggle');
    test.skip((await toggle.count()) === 0, 'this scene has no stage drawer');
    await toggle.click();
    await expect(page.getByTestId('controls-drawer')).toBeVisible();
    const hidden: string[] = [];
    for (let i = 0; i < 40; i++) {
      await page.keyboard.press('Tab');
      const why = await focusObscured(page);
      if (why) hidden.push(why);
    }
    expect(hidden).toEqual([]);
  });
}

// the practice questions: their statements, givens, feedback and worked solutions
for (const q of QUESTIONS) {
  test(`#/practice/${q.practice.id}: no caret in the statement, feedback or worked solution`, async ({
    page,
  }) => {
    await openScene(page, `#/practice/${q.practice.id}?seed=3`);
    // the statement, every part's prompt, the givens and the whole worked solution with its answers
    await page.getByTestId('show-solution').click();
    await expect(page.getByTestId('solution')).toBeVisible();
    expect(await visibleCarets(page)).toEqual([]);
  });
}
