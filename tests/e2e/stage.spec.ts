/**
 * The lecture room: the stage view (present=1), ask-then-reveal (ask=1), and the students' link.
 *
 * The per-scene checks run over every scene of the catalogue and assert for each: a scene whose
 * layout does not pass a `stage` yet (or does not hide its results under ask=1) fails with a
 * message that names it, so the list of failures is the list of scenes still to do. What the
 * shared stage does the same on every scene is checked on one (catalogue.spec.ts loops the
 * timeline's and the stage's shared behaviours over the catalogue).
 */
import type { Page } from '@playwright/test';
import { SCENES, predictPrompt, type SceneInfo } from '../../src/kit/catalogue';
import { textFormulaGroups } from '../../src/ui/texBreaks';
import { test, expect, openScene, settle } from './fixtures';

const SCREENS = [
  { width: 1280, height: 720 },
  { width: 1920, height: 1080 },
] as const;

/** How far `sel`'s boxes reach outside the first screen (0 when wholly inside), with what sticks out. */
async function outsideFirstScreen(page: Page, sel: string): Promise<{ worst: number; what: string }> {
  return page.evaluate((sel) => {
    const vw = document.documentElement.clientWidth;
    const vh = window.innerHeight;
    let worst = 0;
    let what = '';
    for (const el of document.querySelectorAll(sel)) {
      const r = el.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;
      const out = Math.max(0, -r.top, -r.left, r.bottom - vh, r.right - vw);
      if (out > worst) {
        worst = out;
        const id = (el as HTMLElement).dataset.testid ?? el.className;
        what = `${el.tagName.toLowerCase()} ${String(id).slice(0, 60)} [${Math.round(r.left)}, ${Math.round(r.top)}, ${Math.round(r.right)}, ${Math.round(r.bottom)}] in ${vw}×${vh}`;
      }
    }
    return { worst, what };
  }, sel);
}

/** Opens a scene in classroom mode at the top of the page (no part: the first screen as loaded). */
async function openStaged(page: Page, s: SceneInfo, extra = ''): Promise<boolean> {
  await openScene(page, `#${s.path}?present=1${extra}`);
  await page.evaluate(() => window.scrollTo(0, 0));
  return (await page.getByTestId('scene-stage').count()) > 0;
}

const NO_STAGE = (s: SceneInfo) =>
  `${s.id}: no scene-stage in classroom mode (the scene does not pass SceneLayout's stage yet)`;

/** The stage, and everything in it, on the first screen of `screen`, taking most of it. */
async function expectStageOnFirstScreen(page: Page, s: SceneInfo, screen: { height: number }): Promise<void> {
  const stage = page.getByTestId('scene-stage');
  await expect(stage).toBeVisible();
  // the stage itself, and everything in it (figure, readouts, transport), is on the first screen
  expect((await outsideFirstScreen(page, '[data-testid="scene-stage"]')).worst).toBeLessThanOrEqual(1);
  const inner = await outsideFirstScreen(
    page,
    '[data-testid="scene-stage"] .stage-body *:not(option):not(.sr-only)',
  );
  expect(
    inner.worst,
    `${s.id}: part of the stage is below or beside the first screen: ${inner.what}`,
  ).toBeLessThanOrEqual(1);
  // the stage takes most of the first screen (figure sized to the viewport), not a strip of it
  const box = (await stage.boundingBox())!;
  expect(box.height, `${s.id}: the stage is ${Math.round(box.height)} px tall`).toBeGreaterThan(
    0.55 * screen.height,
  );
  // the transport is part of the stage where the scene animates
  const transports = await page.locator('.timeline').count();
  if (transports > 0)
    await expect(stage.locator('.timeline').first(), `${s.id}: its transport is on the stage`).toBeVisible();
  // the controls are folded into the drawer: closed, they take none of the screen
  await expect(page.getByTestId('controls-drawer')).toBeHidden();
}

for (const s of SCENES) {
  test(`${s.id} at 1280×720, present=1: the stage is wholly on the first screen; its text and plot ticks are at least 18 px`, async ({
    page,
  }) => {
    test.setTimeout(120_000);
    await page.setViewportSize(SCREENS[0]);
    expect(await openStaged(page, s), NO_STAGE(s)).toBe(true);
    await expectStageOnFirstScreen(page, s, SCREENS[0]);
    const small = await page.evaluate(() => {
      const stage = document.querySelector('[data-testid="scene-stage"]')!;
      const out: string[] = [];
      const walker = document.createTreeWalker(stage, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        const text = (n.nodeValue ?? '').trim();
        const el = n.parentElement;
        if (!text || !el || el.closest('.sr-only, [hidden], [aria-hidden="true"] kbd, .katex-mathml'))
          continue;
        const r = el.getBoundingClientRect();
        if (r.width === 0 || r.height === 0 || getComputedStyle(el).visibility === 'hidden') continue;
        // KaTeX sets sub- and superscripts smaller by design: judge a formula by its base size
        const judged = el.closest('.katex') ?? el;
        const px = parseFloat(getComputedStyle(judged).fontSize);
        if (px < 17.5) out.push(`${JSON.stringify(text.slice(0, 30))} at ${px.toFixed(1)} px`);
      }
      return out;
    });
    expect(small, `${s.id}: text under 18 px on the stage`).toEqual([]);
  });
}

// the stage's layout is the shared one (src/ui/stage.tsx): the larger screen on one scene
test('hemisphere at 1920×1080, present=1: the stage is wholly on the first screen', async ({ page }) => {
  test.setTimeout(120_000);
  const s = SCENES.find((x) => x.id === 'hemisphere')!;
  await page.setViewportSize(SCREENS[1]);
  expect(await openStaged(page, s), NO_STAGE(s)).toBe(true);
  await expectStageOnFirstScreen(page, s, SCREENS[1]);
});

test('the Controls drawer opens and closes by its button and by the key c; focus follows', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1280, height: 720 });
  const s = await firstStagedScene(page);
  const toggle = page.getByTestId('controls-drawer-toggle');
  const drawer = page.getByTestId('controls-drawer');
  await expect(toggle).toHaveAttribute('aria-expanded', 'false');
  await expect(drawer).toBeHidden();
  await toggle.click();
  await expect(drawer, s).toBeVisible();
  await expect(toggle).toHaveAttribute('aria-expanded', 'true');
  await expect(drawer).toBeFocused();
  // the drawer holds the scene's controls, usable
  await expect(drawer.locator('input, select, button').nth(1)).toBeVisible();
  await page.keyboard.press('c');
  await expect(drawer).toBeHidden();
  await expect(toggle).toBeFocused();
  await page.locator('h1').click();
  await page.keyboard.press('c');
  await expect(drawer).toBeVisible();
  await page.keyboard.press('Escape');
  await expect(drawer).toBeHidden();
  // c typed into a text field is text, not the shortcut
  await toggle.click();
  const field = drawer.locator('input[type="text"]').first();
  if ((await field.count()) > 0) {
    await field.focus();
    await page.keyboard.press('c');
    await expect(drawer).toBeVisible();
  }
});

test('the stage’s fullscreen button asks the browser to show the stage fullscreen', async ({ page }) => {
  await page.addInitScript(() => {
    const w = window as unknown as { __fs: string[] };
    w.__fs = [];
    Element.prototype.requestFullscreen = function (this: Element) {
      w.__fs.push((this as HTMLElement).dataset.testid ?? this.tagName);
      return Promise.resolve();
    };
  });
  await page.setViewportSize({ width: 1280, height: 720 });
  await firstStagedScene(page);
  await page.getByTestId('scene-stage').getByTestId('fullscreen').click();
  await expect
    .poll(() => page.evaluate(() => (window as unknown as { __fs: string[] }).__fs))
    .toEqual(['scene-stage']);
});

test('in real fullscreen the stage fills the screen, and Esc (exitFullscreen) leaves', async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await firstStagedScene(page);
  const stage = page.getByTestId('scene-stage');
  await stage.getByTestId('fullscreen').click();
  await expect(stage).toHaveClass(/is-fullscreen/);
  await expect(stage.getByTestId('fullscreen')).toHaveAttribute('aria-pressed', 'true');
  // Esc is the browser's own key for leaving; headless Chromium takes it as exitFullscreen
  await page.evaluate(() => document.exitFullscreen());
  await expect(stage).not.toHaveClass(/is-fullscreen/);
  await expect(stage.getByTestId('fullscreen')).toHaveAttribute('aria-pressed', 'false');
});

/** Opens the first scene of the catalogue that passes a stage (the test is skipped if none does yet). */
async function firstStagedScene(page: Page): Promise<string> {
  for (const s of SCENES) {
    if (await openStaged(page, s)) return s.id;
  }
  test.skip(true, 'no scene passes a stage yet');
  return '';
}

test('the copied link and the QR code are the students’ link, unless classroom mode is kept', async ({
  page,
}) => {
  await openScene(page, '#/texture?u=0.7&present=1&ask=1&part=3b');
  const copied = async () => {
    await page.getByTestId('copy-link').click();
    return page.getByTestId('share-text').inputValue();
  };
  const students = await copied();
  expect(students).toContain('u=0.7');
  expect(students).toContain('part=3b');
  expect(students).not.toMatch(/[?&]present=/);
  expect(students).not.toMatch(/[?&]ask=/);
  await page.getByTestId('show-qr').click();
  const qr = page.getByTestId('qr-code');
  await expect(qr).toHaveAttribute('data-text', students);
  await expect(page.getByTestId('qr-panel')).toContainText('students’ view');

  const keep = page.getByTestId('keep-classroom');
  await keep.check();
  const lecturer = await copied();
  expect(lecturer).toMatch(/[?&]present=1/);
  expect(lecturer).toMatch(/[?&]ask=1/);
  await expect(qr).toHaveAttribute('data-text', lecturer);

  // revealed: the kept link keeps classroom mode, and no longer asks
  await page.getByTestId('reveal').click();
  const after = await copied();
  expect(after).toMatch(/[?&]present=1/);
  expect(after).not.toMatch(/[?&]ask=/);
  await keep.uncheck();
  expect(await copied()).not.toMatch(/[?&](present|ask)=/);
});

test('present=1 at 1280×720: each scene’s title, share bar and way back stand in one row', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await page.setViewportSize({ width: 1280, height: 720 });
  for (const s of SCENES) {
    await openScene(page, `#${s.path}?present=1&ask=1`);
    const h1 = (await page.locator('main h1').boundingBox())!;
    const bar = (await page.locator('.share-bar').boundingBox())!;
    const back = (await page.locator('main .back-link').boundingBox())!;
    // one row: the share bar is no taller than a row of buttons, beside the title, not under it
    expect(bar.height, `${s.id}: the share bar wraps`).toBeLessThan(70);
    expect(bar.x, s.id).toBeGreaterThan(h1.x + h1.width);
    expect(back.x, s.id).toBeGreaterThan(bar.x + bar.width - 1);
    expect(Math.abs(bar.y + bar.height / 2 - (h1.y + h1.height / 2)), s.id).toBeLessThan(20);
    // embedding is not a lecture's business: no embed code in classroom mode
    await expect(page.getByTestId('copy-embed')).toHaveCount(0);
  }
});

test('without classroom mode there is no "keep classroom mode" choice', async ({ page }) => {
  await openScene(page, '#/texture?u=0.7');
  await expect(page.getByTestId('copy-link')).toBeVisible();
  await expect(page.getByTestId('keep-classroom')).toHaveCount(0);
});

test('ask=1 shows the part’s prediction prompt; Reveal removes it and drops ask from the URL', async ({
  page,
}) => {
  const texture = SCENES.find((s) => s.id === 'texture')!;
  await openScene(page, '#/texture?u=0.4&v=0.3&ask=1&part=3b');
  const prompt = page.getByTestId('ask-prompt');
  await expect(prompt).toBeVisible();
  await expect(page.getByTestId('ask-prompt-text')).toHaveText(predictPrompt(texture, '3b')!);
  await expect(page.getByTestId('param-notice')).toHaveCount(0);
  await page.getByTestId('reveal').click();
  await expect(prompt).toHaveCount(0);
  await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
  await expect.poll(() => page.evaluate(() => window.location.hash)).not.toMatch(/[?&]ask=/);
  expect(await page.evaluate(() => window.location.hash)).toMatch(/u=0\.4.*v=0\.3|v=0\.3.*u=0\.4/);
  // a change to the scene afterwards writes a link without ask either
  await page.getByTestId('u-slider').focus();
  await page.keyboard.press('ArrowRight');
  await expect.poll(() => page.evaluate(() => window.location.hash)).not.toMatch(/u=0\.4(&|$)/);
  expect(await page.evaluate(() => window.location.hash)).not.toMatch(/[?&]ask=/);
});

test('the key v reveals (not while typing), without part= the first part’s prompt is used', async ({
  page,
}) => {
  const texture = SCENES.find((s) => s.id === 'texture')!;
  await openScene(page, '#/texture?ask=1');
  await expect(page.getByTestId('ask-prompt-text')).toHaveText(predictPrompt(texture, null)!);
  const field = page.locator('input[type="text"]').first();
  await field.focus();
  await page.keyboard.press('v');
  await expect(page.getByTestId('ask-prompt')).toBeVisible();
  await page.locator('h1').click();
  await page.keyboard.press('v');
  await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
  await expect.poll(() => page.evaluate(() => window.location.hash)).toBe('#/texture');
});

/** The keys the open `?` list names (each <dt>), by the heading they stand under ('' for page-wide). */
async function listedKeys(page: Page): Promise<Record<string, string[]>> {
  const dialog = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
  await expect(dialog).toBeVisible();
  return dialog.evaluate((d) => {
    const out: Record<string, string[]> = {};
    for (const dl of d.querySelectorAll('dl')) {
      const h = dl.previousElementSibling?.tagName === 'H3' ? dl.previousElementSibling.textContent! : '';
      out[h] = [...dl.querySelectorAll('dt')].map((dt) => dt.textContent!.trim());
    }
    return out;
  });
}

test('the ? list names every key that works on the page, and only those: c in classroom mode, v while asking', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/hemisphere?present=1&ask=1');
  await expect(page.locator('.viewport').first()).toHaveAttribute('data-status', 'ready', {
    timeout: 60_000,
  });
  await page.locator('h1').click();
  await page.keyboard.press('?');
  let keys = await listedKeys(page);
  expect(keys['']).toEqual(expect.arrayContaining(['r', 'c', 'v', '?', 'Esc']));
  // the animation is held at its start until Reveal: its keys are not offered yet
  for (const k of ['Space', 's']) expect(keys['']).not.toContain(k);
  // the keys that work with focus on a part of the page: a 3D view, a described figure
  expect(Object.keys(keys)).toEqual(
    expect.arrayContaining(['On a focused 3D view', 'Inside a described figure']),
  );
  expect(keys['On a focused 3D view']).toEqual(expect.arrayContaining(['← → ↑ ↓', '+ / −', 'Home']));
  await page.keyboard.press('Escape');
  await expect(page.getByRole('dialog', { name: 'Keyboard shortcuts' })).toHaveCount(0);
  // each listed page-wide key does what the list says: c opens the drawer, v reveals
  await page.keyboard.press('c');
  await expect(page.getByTestId('controls-drawer')).toBeVisible();
  await page.keyboard.press('c');
  await expect(page.getByTestId('controls-drawer')).toBeHidden();
  await page.keyboard.press('v');
  await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
  // revealed: v no longer does anything, so it is not listed
  await page.keyboard.press('?');
  keys = await listedKeys(page);
  expect(keys['']).toEqual(expect.arrayContaining(['Space', 'r', 's', 'c', '?', 'Esc']));
  expect(keys['']).not.toContain('v');
  await page.keyboard.press('Escape');
  // the revealed histograms can be heard: their audio traces' keys join the list
  await expect(page.locator('.audio-trace').first()).toBeAttached({ timeout: 30_000 });
  await page.keyboard.press('?');
  expect((await listedKeys(page))['On a focused audio trace']).toEqual(
    expect.arrayContaining(['Enter or p', '← →', 'Home / End', 'Esc']),
  );
  await page.keyboard.press('Escape');

  // outside classroom mode: ? still lists what works (v while asking), never the classroom keys
  await openScene(page, '#/monte-carlo?ask=1');
  await page.locator('h1').click();
  await page.keyboard.press('?');
  keys = await listedKeys(page);
  expect(keys['']).toContain('v');
  for (const k of ['Space', 'r', 's', 'c']) expect(keys['']).not.toContain(k);
  expect(keys['On a focused 3D view']).toBeUndefined();
  // the list lies over the page's corner: tabbing out of it closes it (focus never lands under it)
  await expect(page.getByRole('dialog', { name: 'Keyboard shortcuts' }).getByRole('button')).toBeFocused();
  await page.keyboard.press('Shift+Tab');
  await expect(page.getByRole('dialog', { name: 'Keyboard shortcuts' })).toHaveCount(0);
});

test('a guide preset opened with ask=1 puts the preset’s own question', async ({ page }) => {
  await openScene(page, '#/guide');
  const preset = page
    .getByTestId('guide-preset')
    .filter({ has: page.locator('a[href*="ask=1"]') })
    .first();
  const ask = (await preset.locator('.guide-ask').innerText()).replace(/^Ask:\s*/, '');
  await preset.locator('h3 a').click();
  await expect(page.getByTestId('ask-prompt-text')).toHaveText(ask);
});

test('ask=garbage is reported and the scene does not ask', async ({ page }) => {
  await openScene(page, '#/texture?ask=maybe');
  await expect(page.getByTestId('param-notice')).toContainText('ask');
  await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
});

for (const s of SCENES) {
  test(`${s.id}, ask=1: results are hidden and the animation held at its start until Reveal`, async ({
    page,
  }) => {
    test.setTimeout(120_000);
    await openScene(page, `#${s.path}?ask=1`);
    await expect(page.getByTestId('ask-prompt')).toBeVisible();
    expect(
      await page.getByTestId('ask-hidden').count(),
      `${s.id}: nothing is hidden under ask=1 (the scene does not wrap its results in <Revealed> yet)`,
    ).toBeGreaterThan(0);
    const timeline = page.locator('.timeline').first();
    if ((await timeline.count()) > 0) {
      await expect(timeline, `${s.id}: the animation is held at its start`).toHaveAttribute('data-t', '0');
      await expect(timeline).toHaveAttribute('data-playing', '0');
    }
    await page.getByTestId('reveal').click();
    await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
  });
}

test('Play and Pause have the same width: the transport row does not shift', async ({ page }) => {
  await openScene(page, '#/texture');
  const play = page.getByTestId('timeline-play').first();
  await play.scrollIntoViewIfNeeded();
  const before = (await play.boundingBox())!.width;
  // the invisible wider label is neither seen by screen readers nor part of the button's name
  await expect(play).toHaveAccessibleName('▶ Play');
  await play.click();
  await expect(play).toHaveAttribute('aria-pressed', 'true');
  const during = (await play.boundingBox())!.width;
  await expect(play).toHaveAccessibleName('❚❚ Pause');
  await play.click();
  expect(Math.abs(during - before)).toBeLessThanOrEqual(0.5);
});

for (const s of SCENES) {
  test(`${s.id} on a phone: formulas wrap only at operators outside parentheses`, async ({ page }) => {
    test.setTimeout(180_000);
    await page.setViewportSize({ width: 375, height: 800 });
    await openScene(page, `#${s.path}`);
    // bring every section on screen once, so its formulas are typeset
    const height = await page.evaluate(() => document.documentElement.scrollHeight);
    for (let y = 0; y < height; y += 700) {
      await page.evaluate((y) => window.scrollTo(0, y), y);
      await settle(page);
    }
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
    // formulas written as plain text: the page's text, its formula groups found here, and each
    // group measured there (on two lines: broken inside its parentheses)
    const texts = await page.evaluate(() => {
      const w = window as unknown as { __texts: Text[] };
      w.__texts = [];
      const walker = document.createTreeWalker(document.querySelector('main')!, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode())
        if (!n.parentElement?.closest('.katex, .sr-only, .math-preview')) w.__texts.push(n as Text);
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
    inside.push(...broken);
    expect(inside, `${s.id}: formulas broken inside parentheses`).toEqual([]);
  });
}

test('present=1: every Plotly plot’s tick labels are at least 18 px', async ({ page }) => {
  test.setTimeout(180_000);
  await page.setViewportSize({ width: 1280, height: 720 });
  await openScene(page, '#/monte-carlo?present=1');
  const height = await page.evaluate(() => document.documentElement.scrollHeight);
  for (let y = 0; y < height; y += 600) {
    await page.evaluate((y) => window.scrollTo(0, y), y);
    await settle(page);
  }
  await expect(page.locator('.js-plotly-plot .xtick text').first()).toBeAttached({ timeout: 60_000 });
  const sizes = await page.locator('.js-plotly-plot :is(.xtick, .ytick) text').evaluateAll((ts) =>
    ts.map((t) => ({
      px: parseFloat(getComputedStyle(t).fontSize),
      what: `${t.closest('figure')?.getAttribute('aria-label')?.slice(0, 40)}: ${t.textContent}`,
    })),
  );
  expect(sizes.length).toBeGreaterThan(0);
  expect(sizes.filter((s) => s.px < 17.5).map((s) => `${s.what} at ${s.px} px`)).toEqual([]);
});
