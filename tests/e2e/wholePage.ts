/**
 * One pass over a whole page for everything a reader meets on it, in both themes and at both
 * widths, from a single load: axe (WCAG 2.2 AA; every rule dark at 375 px, those a theme or a width
 * can change light at 1280 px too), the WCAG
 * criteria axe does not test (./wcag.ts), no caret in the visible text, and formulas that wrap
 * only at operators outside parentheses on a phone. The theme follows the system's preference
 * live (src/app/theme.ts), so switching the emulated colour scheme re-themes the loaded page, and
 * the layout follows the viewport, as on a rotated tablet.
 */
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { textFormulaGroups } from '../../src/ui/texBreaks';
import { expect, frameState, openScene, test } from './fixtures';
import { countTabStops } from './calmCount';
import { PLOT_TOOLS } from '../../src/ui/plotTools';
import {
  applyTextSpacing,
  clippedText,
  focusObscured,
  sidewaysOverflow,
  smallTargets,
  weakFocusRing,
} from './wcag';

/** Opens the page and waits until everything below the first screen has mounted (lazy sections). */
export async function openWhole(page: Page, hash: string): Promise<void> {
  await openScene(page, hash);
  // stepped on a timer, not per animation frame (a loaded machine may draw no frame for a
  // while), and bounded, in case a section that mounts on the way makes the page grow
  await page.evaluate(async () => {
    for (let y = 0, i = 0; y < document.body.scrollHeight && i < 200; y += innerHeight / 2, i++) {
      scrollTo(0, y);
      await new Promise((r) => setTimeout(r, 50));
    }
    scrollTo(0, 0);
  });
  await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
}

/**
 * Opens every folded part of the page (src/ui/Fold.tsx), folds inside folds too, and waits until
 * what they hold has loaded and mounted.
 */
export async function openAllFolds(page: Page): Promise<void> {
  for (let round = 0; round < 6; round++) {
    const opened = await page.evaluate(() => {
      const closed = [...document.querySelectorAll<HTMLDetailsElement>('details.fold:not([open])')];
      for (const d of closed) d.open = true;
      return closed.length;
    });
    if (opened === 0) break;
    await expect(page.locator('details.fold[open] > .fold-body > .fold-loading')).toHaveCount(0, {
      timeout: 60_000,
    });
  }
  await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
}

/**
 * axe's rules whose verdict a theme or a viewport's width can change: contrast (of text, of links
 * against the text around them) and target sizes. The rest (names, roles, structure) read the
 * same DOM in either theme and are run once, on the page with every fold open.
 */
export const LAYOUT_RULES = ['color-contrast', 'link-in-text-block', 'target-size'] as const;

/** The most tab stops a scene may show in its first screen, and on the page as it opens, at 1280×800. */
export const CALM = { firstScreen: 25, page: 60 };

/**
 * axe's WCAG 2.2 AA violations (or those of the given rules; in the whole page, or in the part the
 * `include` selector names), described. KaTeX's HTML layer is left out: it is aria-hidden,
 * drawn in the colour of the text around it (no formula sets a colour of its own), and holds
 * most of a scene's nodes; the formulas' MathML, what a screen reader is given, is scanned.
 * Only violations are collected in full (axe's `resultTypes`), which keeps a scan of a whole
 * scene to seconds.
 *
 * The scan runs in the page itself (AxeBuilder's legacy mode: `axe.run` in the top frame, frames
 * reached by axe's own messaging). The default mode runs axe per frame and then merges the
 * results in a fresh blank page, which doubled the time of a scan here (a scene with its folds
 * open: about 3 s against 6–7 s); no page scanned here embeds a frame of another origin, the one
 * case legacy mode cannot reach.
 */
export async function axeViolations(
  page: Page,
  label: string,
  { rules, include }: { rules?: readonly string[]; include?: string } = {},
): Promise<string[]> {
  // options first: AxeBuilder's options() replaces what withTags() and withRules() set
  const builder = new AxeBuilder({ page })
    .options({ resultTypes: ['violations'] })
    .exclude('.katex-html')
    .setLegacyMode(true);
  if (include) builder.include(include);
  if (rules) builder.withRules([...rules]);
  else builder.withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa']);
  const r = await builder.analyze();
  return r.violations.map(
    (v) =>
      `${label} ${v.id}: ${v.nodes
        .slice(0, 4)
        .map((n) => n.target.join(' '))
        .join(', ')}`,
  );
}

/** Text nodes on screen with a caret in them (code, TeX source and hidden text aside). */
export function visibleCarets(page: Page): Promise<string[]> {
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

/**
 * Formulas broken across lines inside their parentheses: KaTeX's top-level boxes (a line break
 * may fall only between them) and formulas written as plain text (their groups found by the
 * app's own rule, src/ui/texBreaks.ts, and measured here). Code (an expression as typed) is not
 * a formula and wraps as code does.
 */
export async function formulasBrokenInsideParentheses(page: Page): Promise<string[]> {
  await expect(page.locator('.math-pending')).toHaveCount(0, { timeout: 60_000 });
  const inside = await page.evaluate(() => {
    const out: string[] = [];
    for (const html of document.querySelectorAll('.katex-html')) {
      let depth = 0;
      let prev: DOMRect | null = null;
      for (const base of html.querySelectorAll(':scope > .base')) {
        const r = base.getBoundingClientRect();
        if (prev && depth > 0 && r.top >= prev.bottom - 1)
          out.push((html.closest('.katex')?.querySelector('annotation')?.textContent ?? '').slice(0, 80));
        depth +=
          base.querySelectorAll('.mopen:not(.minner .mopen)').length -
          base.querySelectorAll('.mclose:not(.minner .mclose)').length;
        prev = r;
      }
    }
    return out;
  });
  const texts = await page.evaluate(() => {
    const w = window as unknown as { __texts: Text[] };
    w.__texts = [];
    const walker = document.createTreeWalker(document.querySelector('main')!, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode())
      if (!n.parentElement?.closest('.katex, .sr-only, .math-preview, code, kbd, samp, pre'))
        w.__texts.push(n as Text);
    return w.__texts.map((n) => n.nodeValue ?? '');
  });
  const groups = texts.flatMap((t, i) => textFormulaGroups(t).map(([a, b]) => [i, a, b] as const));
  const broken = await page.evaluate((groups) => {
    const nodes = (window as unknown as { __texts: Text[] }).__texts;
    return groups
      .filter(([i, a, b]) => {
        const range = document.createRange();
        range.setStart(nodes[i], a);
        range.setEnd(nodes[i], b + 1);
        const rects = [...range.getClientRects()].filter((r) => r.width > 0);
        return new Set(rects.map((r) => Math.round(r.top))).size > 1;
      })
      .map(([i, a, b]) => (nodes[i].nodeValue ?? '').slice(Math.max(0, a - 12), b + 1));
  }, groups);
  return [...inside, ...broken];
}

/**
 * The exam first: each of the scene's parts (`part-1a`, …) on the page as it opens, in the exam's
 * order, each with what the exam asks and its derivation, and "Explore further" after the last
 * of them.
 */
export function examFirst(page: Page, parts: readonly string[]): Promise<string[]> {
  return page.evaluate((parts) => {
    const out: string[] = [];
    let last = -Infinity;
    for (const id of parts) {
      const el = document.querySelector(`[data-testid="part-${id}"]`);
      if (!el || el.getClientRects().length === 0) {
        out.push(`part ${id} is not on the page as it opens`);
        continue;
      }
      for (const [sel, what] of [
        ['.exam-asks', 'what the exam asks'],
        ['.exam-derivation', 'a derivation'],
      ])
        if (!el.querySelector(sel)) out.push(`part ${id} has no ${what}`);
      const top = el.getBoundingClientRect().top;
      if (top < last) out.push(`part ${id} is above the part before it`);
      last = top;
    }
    const explore = document.querySelector('[data-testid="explore-further"]');
    if (explore && explore.getBoundingClientRect().top < last)
      out.push('"Explore further" comes before a part');
    return out;
  }, parts);
}

/** The box holding each scene's inputs, where it is not `.scene-controls`. */
const CONTROLS: Record<string, string> = { hemisphere: '.hemi-controls', 'ray-sphere': '.rs-stage-ctl' };

/**
 * Long single-line derivation steps that must wrap on a phone (each is wider than 375 px on one
 * line), by scene.
 */
const MUST_WRAP: Record<string, string[]> = {
  hemisphere: [
    String.raw`|D| = \int_\Omega d\omega`,
    String.raw`E\big[\langle I\rangle\big] = \frac{1}{N}\sum`,
  ],
  'ray-sphere': [String.raw`{a t^2 + b t + c = 0}`, String.raw`{t = \frac{-b \pm \sqrt{\Delta}}{2a}}`],
  'area-light': [String.raw`\langle L_o\rangle_{N=4}`, String.raw`\langle L_o\rangle = \frac{1}{N}\sum`],
};

/**
 * A scene on a phone (one column): its first question's heading above its first input, that above
 * its first computed answer; every display formula fits its box (the derivations break into rows;
 * nothing needs a sideways scroller), and the long steps of MUST_WRAP wrap.
 */
export async function phoneLayout(page: Page, sceneId: string, firstQuestion: number): Promise<string[]> {
  return page.evaluate(
    ({ heading, controls, mustWrap }) => {
      const out: string[] = [];
      const top = (sel: string) => {
        for (const el of document.querySelectorAll(sel)) {
          const r = el.getBoundingClientRect();
          if (r.width > 0 && r.height > 0) return r.top + scrollY;
        }
        return null;
      };
      const h = top(heading);
      const c = top(`${controls} :is(input, select, textarea, button)`);
      const a = top('.exam-answer');
      if (h === null || c === null || a === null)
        out.push(`no ${h === null ? heading : c === null ? controls : 'answer'}`);
      else if (!(h < c && c < a)) out.push('on a phone: not the question, then its inputs, then its answer');
      const lines = [...document.querySelectorAll<HTMLElement>('.katex-display')].map((el) => {
        const html = el.querySelector<HTMLElement>('.katex-html') ?? el;
        const tops = new Set(
          [...html.querySelectorAll(':scope > .katex-base')].map((b) =>
            Math.round(b.getBoundingClientRect().top),
          ),
        );
        return {
          tex: (el.querySelector('annotation')?.textContent ?? '').trim(),
          overflows: html.scrollWidth > html.clientWidth + 1,
          wrapped: tops.size > 1,
        };
      });
      for (const l of lines)
        if (l.overflows) out.push(`display line wider than a phone: ${l.tex.slice(0, 60)}`);
      for (const start of mustWrap) {
        const l = lines.find((x) => x.tex.startsWith(start));
        if (!l?.wrapped) out.push(`${start} … does not break into rows on a phone`);
      }
      return out;
    },
    {
      heading: `#question-${firstQuestion}-title`,
      controls: CONTROLS[sceneId] ?? '.scene-controls',
      mustWrap: MUST_WRAP[sceneId] ?? [],
    },
  );
}

/** A scene's part of the whole-page pass: its id and exam parts (src/kit/catalogue.ts). */
export interface ScenePage {
  id: string;
  parts: readonly string[];
}

/**
 * The whole-page pass: the page as it opens, light at 1280 × 800 (for a scene: few tab stops, the
 * exam first), then with every fold opened, light at 1280 px (axe's LAYOUT_RULES) and dark at
 * 375 px (every axe rule; for a scene: the phone's
 * one column) and 320 px for reflow, every lazy part loaded from the app's own origin. Every
 * finding is collected and the test fails once with the full list. `prepare` brings the page to
 * the state to check (e.g. a practice question checked, its feedback shown) once it has opened.
 */
export async function checkWholePage(
  page: Page,
  hash: string,
  { scene, prepare }: { scene?: ScenePage; prepare?: (page: Page) => Promise<void> } = {},
): Promise<void> {
  const found: string[] = [];
  const requested: string[] = [];
  page.on('request', (r) => requested.push(r.url()));
  await page.emulateMedia({ colorScheme: 'light' });
  await page.setViewportSize({ width: 1280, height: 800 });
  await test.step('open', () => openWhole(page, hash));
  await prepare?.(page);
  if (scene) {
    found.push(...(await examFirst(page, scene.parts)));
    const c = await page.evaluate(countTabStops, PLOT_TOOLS.length);
    if (c.firstScreen > CALM.firstScreen)
      found.push(
        `${c.firstScreen} tab stops in the first screen (at most ${CALM.firstScreen}): ${c.first.join(' | ')}`,
      );
    if (c.page > CALM.page) found.push(`${c.page} tab stops on the page as it opens (at most ${CALM.page})`);
    // every exam question ends with its "Practise this" links to its own practice page
    const practise = await page.evaluate(() =>
      [...document.querySelectorAll('section.exam-question')].map((q) => {
        const n = q.id.replace('question-', '');
        const a = q.querySelector(`[data-testid="practise-link-${n}"]`);
        return a?.getAttribute('href') === `#/practice/q${n}?seed=1`
          ? null
          : `question ${n} has no practice link`;
      }),
    );
    found.push(...practise.filter((x): x is string => x !== null));
  }
  await test.step('folds', () => openAllFolds(page));
  // light at 1280 px, every fold open: the rules a theme or a width can change (colours,
  // target sizes); every rule runs below, dark at 375 px, on the same content
  found.push(
    ...(await test.step('axe light', () => axeViolations(page, 'light 1280', { rules: LAYOUT_RULES }))),
  );
  // powers are written as superscripts; a formula still waiting for KaTeX shows its plain-text
  // reading, which has no caret either
  found.push(...(await visibleCarets(page)).map((c) => `caret in the visible text: ${c}`));

  // the page activated in its browser before the switch (as settleLazyViews does): Chromium tells a
  // page of a changed preference only in its next animation frame
  await page.bringToFront();
  await page.emulateMedia({ colorScheme: 'dark' });
  await page.setViewportSize({ width: 375, height: 812 });
  // (generous: with every fold open, a page may be busy with what they compute for a while)
  await expect
    .poll(() => page.evaluate(() => document.documentElement.dataset.theme), { timeout: 60_000 })
    .toBe('dark')
    .catch(async (e: unknown) => {
      // Seen rarely on a loaded machine: the theme stays light. Chromium tells a page that a media
      // query changed with its next animation frame, so say whether the preference is dark and
      // whether the page still gets frames (a frame asked for, 3 s given to come).
      const state = {
        prefersDark: await page.evaluate(() => matchMedia('(prefers-color-scheme: dark)').matches),
        ...(await frameState(page, 3000)),
        // and whether a frame comes once the page is brought to the front again
        afterBringToFront: await page.bringToFront().then(() => frameState(page, 3000)),
        // and whether a screenshot (which asks the compositor for a frame of its own) or a resize
        // brings frames, and the theme, back
        shot: await page.screenshot({ timeout: 8000 }).then(
          () => 'ok',
          (e: unknown) => String(e).slice(0, 120),
        ),
        afterShot: await frameState(page, 3000),
        themeAfterShot: await page.evaluate(() => document.documentElement.dataset.theme),
        resize: await page.setViewportSize({ width: 376, height: 812 }).then(() => frameState(page, 3000)),
        themeAfterResize: await page.evaluate(() => document.documentElement.dataset.theme),
      };
      throw new Error(
        `${e instanceof Error ? e.message : String(e)}\nthe page then: ${JSON.stringify(state)}`,
      );
    });
  await expect
    .poll(() => page.evaluate(() => document.documentElement.clientWidth), { timeout: 60_000 })
    .toBeLessThanOrEqual(375);
  found.push(...(await test.step('axe dark', () => axeViolations(page, 'dark 375'))));
  found.push(
    ...(await test.step('targets', () => smallTargets(page))).map(
      (t) => `target under 24 × 24 and not spaced: ${t}`,
    ),
  );
  found.push(
    ...(await test.step('formulas', () => formulasBrokenInsideParentheses(page))).map(
      (f) => `broken inside parentheses: ${f}`,
    ),
  );
  if (scene) found.push(...(await phoneLayout(page, scene.id, Number.parseInt(scene.parts[0]!, 10))));

  await page.setViewportSize({ width: 320, height: 640 });
  await expect
    .poll(() => sidewaysOverflow(page), { timeout: 15_000, message: 'sideways scrolling at 320 px' })
    .toEqual([]);
  await page.setViewportSize({ width: 375, height: 812 });
  await applyTextSpacing(page);
  found.push(
    ...(await test.step('clipped', () => clippedText(page))).map((t) => `clipped under text spacing: ${t}`),
  );
  for (let i = 0; i < 40; i++) {
    await page.keyboard.press('Tab');
    // (both asked at once: one round trip to the page per Tab)
    const [obscured, weak] = await Promise.all([focusObscured(page), weakFocusRing(page)]);
    const why = obscured ?? weak;
    if (why) found.push(why);
  }
  // everything came from the app's own folder (the static build works offline)
  const origin = new URL(page.url()).origin;
  for (const u of requested)
    if (!/^(data|blob):/.test(u) && new URL(u).origin !== origin)
      found.push(`request off the app's origin: ${u}`);
  expect(found, `${hash}: what a reader meets`).toEqual([]);
}
