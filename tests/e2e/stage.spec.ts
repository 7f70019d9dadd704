/**
 * The lecture room's shared pieces, checked once (they are the same on every scene): the
 * controls drawer, fullscreen, the students' link and QR code, ask-then-reveal and its key, the
 * `?` list of keys, and Space on a focused 3D-view button in classroom mode. What every scene must
 * show in the room (the stage on the first screen, results held back until Reveal) is looped over
 * the catalogue in catalogue.spec.ts; a guide preset that asks, and the plots' tick labels in the
 * room, are in room.spec.ts.
 */
import type { Page } from '@playwright/test';
import { SCENES, predictPrompt, type SceneInfo } from '../../src/kit/catalogue';
import { test, expect, openScene } from './fixtures';
import { focusObscured } from './wcag';

/** Opens a scene in classroom mode at the top of the page (no part: the first screen as loaded). */
async function openStaged(page: Page, s: SceneInfo, extra = ''): Promise<boolean> {
  await openScene(page, `#${s.path}?present=1${extra}`);
  await page.evaluate(() => window.scrollTo(0, 0));
  return (await page.getByTestId('scene-stage').count()) > 0;
}

test('on the stage: the Controls drawer opens and closes by its button and by the key c, focus follows; the fullscreen button fills the screen', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.setViewportSize({ width: 1280, height: 720 });
  const s = await firstStagedScene(page);
  await test.step('the Controls drawer opens and closes by its button and by the key c; focus follows', async () => {
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
    // with the drawer open, focus is never hidden under it (WCAG 2.4.11); checked on the page as a
    // reader tabs through it once it has settled: every formula typeset (one typeset while a Tab
    // moves focus grows the page above the focused field after the browser has scrolled to it)
    if (!(await drawer.isVisible())) await toggle.click();
    await expect(drawer).toBeVisible();
    await expect(page.locator('[data-deferred="pending"], .math-pending')).toHaveCount(0, {
      timeout: 30_000,
    });
    await toggle.focus();
    const hidden: string[] = [];
    for (let i = 0; i < 40; i++) {
      await page.keyboard.press('Tab');
      const why = await focusObscured(page);
      if (why) hidden.push(why);
    }
    expect(hidden).toEqual([]);
  });

  await test.step('the fullscreen button shows the stage fullscreen; exitFullscreen (Esc) leaves', async () => {
    const stage = page.getByTestId('scene-stage');
    await stage.getByTestId('fullscreen').click();
    await expect
      .poll(() => page.evaluate(() => document.fullscreenElement?.getAttribute('data-testid')))
      .toBe('scene-stage');
    await expect(stage).toHaveClass(/is-fullscreen/);
    await expect(stage.getByTestId('fullscreen')).toHaveAttribute('aria-pressed', 'true');
    // Esc is the browser's own key for leaving; headless Chromium takes it as exitFullscreen
    await page.evaluate(() => document.exitFullscreen());
    await expect(stage).not.toHaveClass(/is-fullscreen/);
    await expect(stage.getByTestId('fullscreen')).toHaveAttribute('aria-pressed', 'false');
  });
});

/** Opens the first scene of the catalogue that passes a stage (the test is skipped if none does yet). */
async function firstStagedScene(page: Page): Promise<string> {
  for (const s of SCENES) {
    if (await openStaged(page, s)) return s.id;
  }
  test.skip(true, 'no scene passes a stage yet');
  return '';
}

test('an asking page: ask=1 shows the part’s prompt, v reveals and drops ask; outside classroom mode its link and QR code are the students’ unless the asker keeps it', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await test.step('ask=1 shows the part’s prompt; v reveals (not while typing) and drops ask from the URL; ask=garbage is named', async () => {
    const texture = SCENES.find((s) => s.id === 'texture')!;
    await openScene(page, '#/texture?u=0.4&v=0.3&ask=1&part=3b');
    const prompt = page.getByTestId('ask-prompt');
    await expect(prompt).toBeVisible();
    await expect(page.getByTestId('ask-prompt-text')).toHaveText(predictPrompt(texture, '3b')!);
    await expect(page.getByTestId('param-notice')).toHaveCount(0);
    // v typed into a field is text, not the shortcut
    await page.locator('input[type="text"]').first().focus();
    await page.keyboard.press('v');
    await expect(prompt).toBeVisible();
    await page.locator('h1').click();
    await page.keyboard.press('v');
    await expect(prompt).toHaveCount(0);
    await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
    await expect.poll(() => page.evaluate(() => window.location.hash)).not.toMatch(/[?&]ask=/);
    expect(await page.evaluate(() => window.location.hash)).toMatch(/u=0\.4.*v=0\.3|v=0\.3.*u=0\.4/);
    // a change to the scene afterwards writes a link without ask either
    await page.getByTestId('u-slider').focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => page.evaluate(() => window.location.hash)).not.toMatch(/u=0\.4(&|$)/);
    expect(await page.evaluate(() => window.location.hash)).not.toMatch(/[?&]ask=/);

    // without part= the first part's prompt is used; a value ask cannot take is named, and nothing is asked
    await openScene(page, '#/texture?ask=1');
    await expect(page.getByTestId('ask-prompt-text')).toHaveText(predictPrompt(texture, null)!);
    await openScene(page, '#/texture?ask=maybe');
    await expect(page.getByTestId('param-notice')).toContainText('ask');
    await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
  });

  await test.step('the link and QR code of an asking page are the students’ (no ask) unless the asker keeps it', async () => {
    // without ask, there is no choice to make
    await openScene(page, '#/texture?u=0.7');
    await expect(page.getByTestId('copy-link')).toBeVisible();
    await expect(page.getByTestId('keep-classroom')).toHaveCount(0);

    await openScene(page, '#/texture?u=0.7&ask=1&part=3b');
    const copied = async () => {
      await page.getByTestId('copy-link').click();
      return page.getByTestId('share-text').inputValue();
    };
    const students = await copied();
    expect(students).toContain('u=0.7');
    expect(students).toContain('part=3b');
    expect(students).not.toMatch(/[?&](present|ask)=/);
    await page.getByTestId('show-qr').click();
    const qr = page.getByTestId('qr-code');
    await expect(qr).toHaveAttribute('data-text', students);

    const keep = page.getByTestId('keep-classroom');
    await keep.check();
    const asking = await copied();
    expect(asking).toMatch(/[?&]ask=1/);
    expect(asking).not.toMatch(/[?&]present=/);
    await expect(qr).toHaveAttribute('data-text', asking);
    // revealed: nothing is left to ask
    await page.getByTestId('reveal').click();
    expect(await copied()).not.toMatch(/[?&](present|ask)=/);
  });
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

test('the ? list names every key that works on the page, and only those: c in classroom mode, v while asking; Space on a focused 3D-view button presses it', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // open=cdf-sound: the CDFs' audio traces (folded on the page) are open, for the list's last check
  await openScene(page, '#/hemisphere?present=1&ask=1&open=cdf-sound');
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

  // in classroom mode Space plays the animation, but on a focused button of the 3D view it presses
  // the button (the view orbits) and the animation stays as it was
  const vp = page.locator('.viewport').first();
  const timeline = page.locator('.timeline').first();
  const playing = await timeline.getAttribute('data-playing');
  const triadX = () => vp.locator('.viewport-triad').getAttribute('data-x-axis');
  const before = await triadX();
  await vp.getByRole('button', { name: 'Orbit right', exact: true }).focus();
  await page.keyboard.press('Space');
  await expect.poll(triadX).not.toBe(before);
  await expect(timeline).toHaveAttribute('data-playing', playing!);

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
