/**
 * Layout on phones, tablets and in present mode ("make every layout legible"):
 * - one column (375 and 768 px): every scene shows its exam question (heading) before its inputs,
 *   and its inputs before its first computed answer;
 * - present=1: #/area-light's 3D view (the figure that teaches Q6) starts in the first screen;
 * - 375 px: derivation lines break instead of scrolling sideways; a display line wider than its
 *   box is allowed only inside a keyboard-focusable, labelled scroll container; the page itself
 *   never scrolls sideways.
 * axe at 375 px on every scene: catalogue.spec.ts.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';
import { SCENES as CATALOGUE, type SceneId } from '../../src/kit/catalogue';

/** Each scene: its first exam question's heading, the box that holds its inputs. */
const CONTROLS: Partial<Record<SceneId, string>> = {
  hemisphere: '.hemi-controls',
  'ray-sphere': '.rs-stage-ctl',
};
const SCENES = CATALOGUE.map((s) => ({
  path: s.id,
  heading: `#question-${Number.parseInt(s.parts[0]!, 10)}-title`,
  controls: CONTROLS[s.id] ?? '.scene-controls',
}));

/** Page y (not viewport y) of the top of the first element matching `sel` that has a box. */
async function pageTop(page: Page, sel: string): Promise<number> {
  const y = await page.evaluate((s) => {
    for (const el of document.querySelectorAll(s)) {
      const r = el.getBoundingClientRect();
      if (r.width > 0 && r.height > 0) return r.top + window.scrollY;
    }
    return null;
  }, sel);
  expect(y, `an element ${sel} with a box`).not.toBeNull();
  return y!;
}

/** The scene's exam question heading above its first input, that above its first computed answer. */
async function expectQuestionInputsAnswer(page: Page, s: (typeof SCENES)[number], w: number): Promise<void> {
  await expect(page.locator(s.heading)).toBeVisible({ timeout: 30000 });
  await expect(page.locator(s.controls).first()).toBeAttached();
  const control = `${s.controls} :is(input, select, textarea, button)`;
  const heading = await pageTop(page, s.heading);
  const firstControl = await pageTop(page, control);
  const firstAnswer = await pageTop(page, '.exam-answer');
  expect(heading, 'the question heading above the first input').toBeLessThan(firstControl);
  expect(firstControl, 'the first input above the first computed answer').toBeLessThan(firstAnswer);
  // and the page does not scroll sideways
  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(w);
}

// 375 px: in the derivations' test below, on the same page
test.describe('768 × 1024', () => {});

/** Scroll down the whole page (lazy parts mount near the screen) until every formula is typeset. */
async function typesetAll(page: Page): Promise<void> {
  await expect
    .poll(
      async () =>
        page.evaluate(() => {
          window.scrollBy(0, window.innerHeight);
          const atEnd = window.scrollY + window.innerHeight >= document.documentElement.scrollHeight - 2;
          return (
            atEnd &&
            document.querySelectorAll('.math-pending').length === 0 &&
            document.querySelectorAll('.katex-display').length > 0
          );
        }),
      { timeout: 60000, intervals: [200] },
    )
    .toBe(true);
}

interface DisplayLine {
  tex: string;
  /** the typeset line is wider than the box it sits in */
  overflows: boolean;
  /** it sits in a focusable (tabindex=0), labelled container that scrolls sideways */
  inScroller: boolean;
  /** its pieces sit on more than one line (it wrapped) */
  wrapped: boolean;
}

async function displayLines(page: Page): Promise<DisplayLine[]> {
  return page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('.katex-display')].map((el) => {
      const html = el.querySelector<HTMLElement>('.katex-html') ?? el;
      const tex = el.querySelector('annotation')?.textContent ?? '';
      const overflows = html.scrollWidth > html.clientWidth + 1;
      let box: HTMLElement | null = el;
      let inScroller = false;
      for (; box; box = box.parentElement) {
        if (
          box.getAttribute('tabindex') === '0' &&
          box.getAttribute('aria-label') &&
          ['auto', 'scroll'].includes(getComputedStyle(box).overflowX)
        ) {
          inScroller = true;
          break;
        }
      }
      const tops = new Set(
        [...html.querySelectorAll(':scope > .katex-base')].map((b) =>
          Math.round(b.getBoundingClientRect().top),
        ),
      );
      return { tex, overflows, inScroller, wrapped: tops.size > 1 };
    }),
  );
}

/** Long single-line derivation steps that must now wrap at 375 px (each was wider than a phone). */
const MUST_WRAP: Partial<Record<SceneId, string[]>> = {
  hemisphere: [
    String.raw`|D| = \int_\Omega d\omega`,
    String.raw`E\big[\langle I\rangle\big] = \frac{1}{N}\sum`,
  ],
  'ray-sphere': [String.raw`{a t^2 + b t + c = 0}`, String.raw`{t = \frac{-b \pm \sqrt{\Delta}}{2a}}`],
  'area-light': [String.raw`\langle L_o\rangle_{N=4}`, String.raw`\langle L_o\rangle = \frac{1}{N}\sum`],
};

test.describe('375 px: derivations', () => {
  for (const s of SCENES) {
    test(`#/${s.path}: the question, then its inputs, then its first answer; no display line wider than its box outside a focusable scroller; the long steps wrap`, async ({
      page,
    }) => {
      test.setTimeout(120_000);
      await page.setViewportSize({ width: 375, height: 800 });
      await openScene(page, `#/${s.path}`);
      await expectQuestionInputsAnswer(page, s, 375);
      await typesetAll(page);
      const lines = await displayLines(page);
      expect(lines.length).toBeGreaterThan(3);
      const bad = lines.filter((l) => l.overflows && !l.inScroller).map((l) => l.tex.slice(0, 80));
      expect(bad, 'display lines that scroll sideways outside a focusable container').toEqual([]);
      // every line the derivations break into rows fits: nothing needs the fallback scroller
      const scrolled = lines.filter((l) => l.overflows).map((l) => l.tex.slice(0, 80));
      expect(scrolled, 'display lines wider than a 375 px phone').toEqual([]);
      for (const start of MUST_WRAP[s.path] ?? []) {
        const l = lines.find((x) => x.tex.trim().startsWith(start));
        expect(l, `a display line starting ${start}`).toBeDefined();
        expect(l!.wrapped, `${start} … breaks into several lines`).toBe(true);
        expect(l!.overflows).toBe(false);
      }
      expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(375);
    });
  }
});
