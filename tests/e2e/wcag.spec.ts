/**
 * WCAG 2.2 AA, beyond the component tests of a11y.spec.ts: axe (wcag2a, wcag2aa, wcag21aa,
 * wcag22aa) in both themes at 375 and 1280 px on the pages that are not scenes (catalogue.spec.ts
 * runs it on every scene); on every route, scenes included, target sizes at 375 px, reflow at
 * 320 px, text spacing, focus never hidden under something fixed or sticky.
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

/** The routes that are not scenes: axe runs here; tests/e2e/catalogue.spec.ts runs it on every scene. */
const PAGES = ['#/', '#/guide', '#/practice', '#/practice/q1?seed=3', '#/accessibility', '#/results'];
/** Every route, for the checks that axe does not make. */
const ROUTES = [...PAGES, ...SCENES.map((s) => `#${s.path}`)];

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

for (const route of PAGES) {
  test(`${route}: axe wcag2a/2aa/21aa/22aa clean in both themes at 375 and 1280 px`, async ({ page }) => {
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
}

for (const route of ROUTES) {
  test(`${route} no caret in the visible text; at 375 px targets ≥ 24 × 24 or spaced, no sideways scrolling at 320 px, text spacing (1.4.12) clips nothing, focus never hidden (2.4.11) and its ring keeps 3:1 (1.4.11)`, async ({
    page,
  }) => {
    await open(page, route);
    // powers are written as superscripts; every formula still waiting for KaTeX shows its
    // plain-text reading, which has no caret either
    expect(await visibleCarets(page), 'carets in the visible text').toEqual([]);
    await page.setViewportSize({ width: 375, height: 812 });
    expect(await smallTargets(page), 'targets under 24 × 24 and not spaced').toEqual([]);
    await page.setViewportSize({ width: 320, height: 640 });
    await expect.poll(() => sidewaysOverflow(page), { timeout: 15_000 }).toEqual([]);
    await page.setViewportSize({ width: 375, height: 812 });
    await applyTextSpacing(page);
    expect(await clippedText(page), 'text clipped under text spacing').toEqual([]);
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
}

// the drawer is the shared stage's (src/ui/stage.tsx), the same on every scene
test(`classroom mode (present=1): with the controls drawer open, focus is never hidden`, async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await openScene(page, `#/texture?present=1`);
  const toggle = page.getByTestId('controls-drawer-toggle');
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
