/**
 * Accessibility beyond what axe sees: what Chromium's accessibility tree gives a screen reader of a
 * described figure, the audio trace's sound and keys, the A11y view (on the accessibility page and
 * on a scene), status messages, and formulas (KaTeX's MathML, and the plain-text reading before it).
 */
import type { Page, Route } from '@playwright/test';
import { test, expect, openScene } from './fixtures';
import { axNodeOf, axTree } from './axTree';

test.describe.configure({ timeout: 180_000 });

/** Shows the accessibility page afresh (its demo back at its start) by way of another route. */
async function reopenDemo(page: Page, hash = '#/accessibility'): Promise<void> {
  await page.goto('./#/');
  await expect(page.getByTestId('demo-figure')).toHaveCount(0);
  await page.goto(`./${hash}`);
}

test('the accessibility page and a scene: a described figure and the A11y view follow a change; the audio trace; the table; status messages', async ({
  page,
}) => {
  await page.addInitScript(() => {
    const w = window as unknown as { __osc: number; __ctx: number };
    w.__osc = 0;
    w.__ctx = 0;
    const C = window.AudioContext;
    const orig = C.prototype.createOscillator;
    C.prototype.createOscillator = function (this: AudioContext) {
      w.__osc++;
      return orig.call(this);
    };
    window.AudioContext = class extends C {
      constructor(o?: AudioContextOptions) {
        super(o);
        w.__ctx++;
      }
    };
  });
  // the A11y view (a11y=1) is on from the start: it shows what the figure's steps change
  await page.goto('./#/accessibility?a11y=1');
  await expect(
    page.getByTestId('a11y-figures').locator('li', { hasText: 'g(t) along the ray, and where' }),
  ).toContainText('hits the sphere', { timeout: 30_000 });

  await test.step('a described figure: its name and live description in the accessibility tree, announced once settled', async () => {
    const fig = page.getByTestId('demo-figure');
    await expect(fig).toBeVisible({ timeout: 30_000 });
    const before = await axNodeOf(page, '[data-testid="demo-figure"]');
    expect(before).not.toBeNull();
    expect(before!.role).toBe('group');
    expect(before!.name).toBe('g(t) along the ray, and where it crosses 0');
    expect(before!.description).toMatch(/hits the sphere at t = \d\.\d\d and leaves it at t = \d\.\d\d/);

    // a parameter change: the description follows, with the new numbers, and is announced
    const slider = page.getByTestId('demo-r');
    await slider.focus();
    for (let i = 0; i < 12; i++) await page.keyboard.press('ArrowLeft');
    await expect
      .poll(async () => (await axNodeOf(page, '[data-testid="demo-figure"]'))!.description, {
        timeout: 15_000,
      })
      .toMatch(/The ray misses: g stays above 0, lowest \d\.\d\d at t = 2, −?\d\.\d\d beyond the radius/);
    const missed = (await axNodeOf(page, '[data-testid="demo-figure"]'))!.description;
    const r = Number(missed.match(/r = (\d\.\d\d)/)![1]);
    expect(r).toBeLessThan(0.5);
    await expect(page.getByTestId('live-region')).toHaveText(missed, { timeout: 15_000 });

    // the key d inside the figure says it again at once
    await page.evaluate(() => {
      const el = document.querySelector<HTMLElement>('[data-testid="demo-figure"]')!;
      el.tabIndex = -1;
      el.focus();
    });
    await page.evaluate(() => (document.querySelector('[data-testid="live-region"]')!.textContent = ''));
    await page.keyboard.press('d');
    await expect(page.getByTestId('live-region')).toHaveText(missed);
  });

  await test.step('the A11y view shows the figures a screen reader is given and what was announced, live', async () => {
    const view = page.getByTestId('a11y-view');
    await expect(view).toBeVisible({ timeout: 30_000 });
    const item = view.getByTestId('a11y-figures').locator('li', { hasText: 'g(t) along the ray, and where' });
    await expect(item).toContainText('The ray misses', { timeout: 15_000 });
    await expect(view.getByTestId('a11y-announcements').locator('li').first()).toContainText(
      'The ray misses',
      {
        timeout: 15_000,
      },
    );
  });

  await reopenDemo(page);
  await test.step('an audio trace starts Web Audio nodes only when asked, steps by key and speaks each point', async () => {
    const trace = page.getByTestId('demo-trace');
    await expect(trace).toBeVisible({ timeout: 30_000 });
    const count = () => page.evaluate(() => (window as unknown as { __osc: number }).__osc);
    const contexts = () => page.evaluate(() => (window as unknown as { __ctx: number }).__ctx);
    // nothing plays on load, on a parameter change, or on stepping before sound was asked for
    await trace.focus();
    await page.keyboard.press('ArrowRight');
    const live = page.getByTestId('live-region');
    await expect(live).toHaveText(/^t = 0, g = .* \(point 1 of 41\)/);
    await page.keyboard.press('ArrowRight');
    await expect(live).toHaveText(/^t = 0\.1, g = .* \(point 2 of 41\)/);
    await page.keyboard.press('End');
    await expect(live).toHaveText(/^t = 4, g = .* \(point 41 of 41\)/);
    await page.keyboard.press('Home');
    await expect(live).toHaveText(/\(point 1 of 41\)/);
    expect(await contexts()).toBe(0);
    expect(await count()).toBe(0);

    // Enter plays: one tone and a tick at each root
    await page.keyboard.press('Enter');
    await expect(live).toHaveText(/^Playing g\(t\) along the ray, t from 0 to 4/);
    await expect.poll(count, { timeout: 15_000 }).toBe(3);
    expect(await contexts()).toBe(1);
    await expect(trace).toHaveAttribute('data-playing', '1');
    await page.keyboard.press('Escape');
    await expect(trace).not.toHaveAttribute('data-playing', '1');
    await expect(live).toHaveText('Stopped.');

    // stepping onto a root names it (a blip once sound is on)
    let named = false;
    for (let i = 0; i < 41 && !named; i++) {
      await page.keyboard.press('ArrowRight');
      named = /; root \(point/.test((await live.textContent()) ?? '');
    }
    expect(named).toBe(true);
    await expect.poll(count).toBeGreaterThan(3);

    // a parameter change plays nothing by itself: no new nodes once it has settled and been announced
    const n = await count();
    await page.getByTestId('demo-r').focus();
    await page.keyboard.press('ArrowRight');
    await expect(live).toHaveText(/^Radius r = 1\.05/, { timeout: 15_000 });
    expect(await count()).toBe(n);
    await expect(trace).not.toHaveAttribute('data-playing', '1');
  });

  await reopenDemo(page);
  await test.step('status messages (4.1.3): one live region for the page', async () => {
    await page.getByTestId('demo-r').focus();
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowLeft');
    await expect(page.getByTestId('live-region')).toHaveText(/Radius r = 0\.85/, { timeout: 15_000 });
    await page.getByTestId('demo-trace').focus();
    await page.keyboard.press('ArrowRight');
    await expect(page.getByTestId('live-region')).toHaveText(/point 1 of 41/);
    await expect(page.getByTestId('live-region')).toHaveCount(1);
    const live = await axNodeOf(page, '[data-testid="live-region"]');
    expect(live!.role).toBe('status');
  });

  await test.step('show as table: a real table, rendered when opened', async () => {
    const t = page.getByTestId('demo-table');
    await expect(t).toBeVisible({ timeout: 30_000 });
    await expect(t.locator('table')).toHaveCount(0);
    await t.locator('summary').click();
    await expect(t.locator('table caption')).toHaveText('g(t) along the ray');
    await expect(t.locator('th[scope="col"]')).toHaveText(['t', 'g(t)']);
    await expect(t.locator('tbody tr')).toHaveCount(41);
    const tree = await axTree(page);
    expect(tree.some((n) => n.role === 'table')).toBe(true);
  });

  await test.step('on a scene: Copy link’s result is a status message', async () => {
    await openScene(page, '#/texture');
    await page.getByTestId('copy-link').click();
    await expect(
      page.getByRole('status').filter({ hasText: /Link copied\.|Copy it from the box/ }),
    ).toHaveCount(1);
  });

  await test.step('on a scene, the A11y view lists what the page names, and links keep the flag', async () => {
    await openScene(page, '#/texture?a11y=1');
    const view = page.getByTestId('a11y-view');
    await expect(view).toBeVisible({ timeout: 30_000 });
    await expect(view.getByTestId('a11y-figures').locator('li').first()).toBeVisible({ timeout: 30_000 });
    const names = await view.locator('.a11y-figures li strong').allTextContents();
    const tree = await axTree(page);
    for (const nm of names)
      expect(
        tree.some((n) => n.name === nm),
        nm,
      ).toBe(true);
    expect(page.url()).toContain('a11y=1');
  });

  await test.step('a practice result is a status message', async () => {
    await page.goto('./#/practice/q3?seed=7');
    const check = page.getByRole('button', { name: /^Check/ });
    await expect(check).toBeVisible({ timeout: 30_000 });
    await check.click();
    await expect(page.getByTestId('practice-summary')).toHaveAttribute('role', 'status');
    await expect(page.getByTestId('practice-summary')).not.toBeEmpty();
  });
});

test('formulas: the plain-text reading shown before KaTeX arrives is a named math element; KaTeX’s MathML is in the accessibility tree, never under aria-hidden', async ({
  page,
}) => {
  // hold KaTeX back (its worker and its library do not arrive until let go): the previews stay
  const held: Route[] = [];
  await page.route(/katex/i, (r) => {
    held.push(r);
  });
  await test.step('before KaTeX: the plain-text reading is a named math element', async () => {
    await page.goto('./#/hemisphere');
    const preview = page.locator('.math-preview').first();
    await expect(preview).toBeAttached({ timeout: 60_000 });
    const node = await axNodeOf(page, '.math-preview');
    expect(node!.role.toLowerCase()).toContain('math');
    expect(node!.name.length).toBeGreaterThan(0);
    expect(node!.name).not.toMatch(/[\\^_]/);
  });

  await test.step('KaTeX’s MathML is in the accessibility tree, never under aria-hidden', async () => {
    // KaTeX let go: the formulas are typeset
    for (const r of held) await r.continue();
    await page.unroute(/katex/i);
    await expect(page.locator('.katex-mathml math').first()).toBeAttached({ timeout: 60_000 });
    const hiddenMath = await page.evaluate(
      () =>
        [...document.querySelectorAll('.katex-mathml')].filter((m) => m.closest('[aria-hidden="true"]'))
          .length,
    );
    expect(hiddenMath).toBe(0);
    const node = await axNodeOf(page, '.katex-mathml math');
    expect(node!.ignored).toBe(false);
    expect(node!.role.toLowerCase()).toContain('math');
    // the HTML rendering is hidden: a screen reader does not read the formula twice
    const html = await axNodeOf(page, '.katex-html');
    expect(html!.ignored).toBe(true);
    // the hidden MathML is laid out in the page's font, at its formula's size, letters as written
    // (not MathML's math font, script sizes and mathematical italics: a font search per letter
    // where no math font is installed, for text nobody sees)
    const hidden = await page.evaluate(() => {
      const page = getComputedStyle(document.body).fontFamily;
      const odd: string[] = [];
      for (const copy of document.querySelectorAll('.katex-mathml')) {
        const size = getComputedStyle(copy).fontSize;
        for (const el of copy.querySelectorAll('*')) {
          const s = getComputedStyle(el);
          if (s.fontFamily !== page || s.fontSize !== size || s.textTransform !== 'none')
            odd.push(`${el.tagName} ${s.fontFamily} ${s.fontSize} (formula ${size}) ${s.textTransform}`);
        }
      }
      return { copies: document.querySelectorAll('.katex-mathml').length, odd: odd.slice(0, 5) };
    });
    expect(hidden.copies).toBeGreaterThan(0);
    expect(hidden.odd).toEqual([]);
  });
});

// WCAG 2.4.11 (focus not obscured) while the page settles: a part above the field a reader has
// just tabbed to grows (a derivation drawn as it nears the screen, a formula typeset, a view
// loaded), after the browser has scrolled to the field. The field is brought back into view
// (src/ui/focusInView.ts); a click that then moves the page is left alone.
test('a field reached with Tab stays on screen when a part above it grows a moment later', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await openScene(page, '#/texture');
  const buttons = page.locator('main button:visible');
  expect(await buttons.count()).toBeGreaterThan(6);
  // Tab on from a button down the page (the browser scrolls the next field into view)
  await buttons.nth(4).focus();
  await page.keyboard.press('Tab');
  await page.evaluate(() => document.activeElement?.setAttribute('data-tabbed-to', ''));
  const field = page.locator('[data-tabbed-to]');
  await expect(field).toBeFocused();
  const inView = () =>
    field.evaluate((el) => {
      const r = el.getBoundingClientRect();
      return r.bottom > 0 && r.top < document.documentElement.clientHeight;
    });
  expect(await inView()).toBe(true);
  // a part right above it grows by more than the screen's height
  await field.evaluate((el) => {
    // (before the outermost box around it that lays out in a flex or grid row: a block of its own)
    let box: Element = el;
    while (box.parentElement && /flex|grid/.test(getComputedStyle(box.parentElement).display))
      box = box.parentElement;
    const grow = document.createElement('div');
    grow.style.height = '900px';
    box.parentElement!.insertBefore(grow, box);
  });
  await expect.poll(inView, { message: 'the focused field went off screen and stayed there' }).toBe(true);
  await expect(field).toBeFocused();
});
