/**
 * #/texture as a screen reader and a keyboard receive it: the main figure's name and description
 * read from Chromium's accessibility tree (CDP), following a setting and the paused position (and
 * said by the live region); the exam's (a), (b) and (c) by keyboard alone; a cell's value edited
 * without pointing. Expected figures come from the exam grid's definition
 * (L(u, v) = 21 + 4u − 20v) or the scene's own pure model at the position the page reports. The
 * descriptions' wording is a unit test (tests/scenes/texture/describe.test.ts); the whole page's
 * tab stops, axe and focus are in catalogue.spec.ts.
 */
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, openScene, waitForReadout } from './fixtures';
import { frameAt, pathOf } from '../../src/scenes/texture/path';
import { examGrid, type LookupOptions } from '../../src/core/texture';
import { coord, short } from '../../src/scenes/texture/view/describe';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const EXAM: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const DEFAULT_PATH = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
const MAIN = 'Texel grid with the query point, its path, and the value along the path';
const SPHERE = 'The sphere wearing the texture, with the chosen point';

interface AXValue {
  value?: unknown;
}
interface AXNode {
  role?: AXValue;
  name?: AXValue;
  description?: AXValue;
  ignored?: boolean;
}

/** The accessible role and description of the node named `name` (what a screen reader gets). */
async function axNamed(cdp: CDPSession, name: string): Promise<{ role: string; description: string } | null> {
  const { nodes } = (await cdp.send('Accessibility.getFullAXTree')) as { nodes: AXNode[] };
  const n = nodes.find((x) => !x.ignored && x.name?.value === name);
  return n ? { role: String(n.role?.value ?? ''), description: String(n.description?.value ?? '') } : null;
}

/** Polls the description of the node named `name` until it satisfies `pred`; returns it. */
async function waitForDescription(cdp: CDPSession, name: string, pred: (d: string) => boolean) {
  let last = '';
  await expect
    .poll(
      async () => {
        last = (await axNamed(cdp, name))?.description ?? '';
        return pred(last);
      },
      { timeout: 20_000 },
    )
    .toBe(true);
  return last;
}

async function timelineT(page: Page): Promise<number> {
  return Number(await page.getByTestId('timeline').getAttribute('data-t'));
}

/**
 * Presses Tab until the element with `testId` has the focus (Shift+Tab when it comes before the
 * focused element in the page), at most `max` presses.
 */
async function tabTo(page: Page, testId: string, max = 120): Promise<void> {
  const before = await page.evaluate((id) => {
    const target = document.querySelector(`[data-testid="${id}"]`);
    const from = document.activeElement;
    if (!target || !from || from === document.body) return false;
    return !!(target.compareDocumentPosition(from) & Node.DOCUMENT_POSITION_FOLLOWING);
  }, testId);
  for (let k = 0; k < max; k++) {
    await page.keyboard.press(before ? 'Shift+Tab' : 'Tab');
    if (await page.evaluate((id) => document.activeElement?.getAttribute('data-testid') === id, testId))
      return;
  }
  throw new Error(`Tab never reached ${testId}`);
}

test('keyboard and accessibility tree: the main figure’s description, the exam by keyboard, a cell edited without pointing', async ({
  page,
}) => {
  test.setTimeout(180_000);
  const cdp = await page.context().newCDPSession(page);
  await test.step('the main figure is named and its description holds the live numbers; it follows a setting and the pause', async () => {
    await openScene(page, '#/texture?open=settings');
    const fig = await axNamed(cdp, MAIN);
    expect(fig?.role).toBe('group');
    const d0 = fig!.description;
    expect(d0).toContain('The query point at u 0.40, v 0.24 lies in cell (1, 0)');
    expect(d0).toContain(`bilinear ${short(L(0.4, 0.24))} from 17, 18 above and 22, 23 below`);
    expect(d0).toContain('nearest 18, the node (2, 1)');
    expect(d0).toContain(`(u, v) = (φ/2π, θ/π) = (0.125, 0.25), bilinear ${short(L(1 / 8, 1 / 4))}`);

    // a parameter: the addressing and the query
    await page.getByTestId('vflip-toggle').check();
    const d1 = await waitForDescription(cdp, MAIN, (d) => d !== d0);
    expect(d1).toContain('v flipped');
    expect(d1).toContain(`nearest ${21 - 5 * Math.round(0.76 * 4) + 2}`);
    await page.getByTestId('vflip-toggle').uncheck();
    await waitForDescription(cdp, MAIN, (d) => d === d0);

    // on pause: the position on the path and the numbers there
    await page.getByTestId('timeline-play').click();
    await expect.poll(() => timelineT(page), { timeout: 20_000 }).toBeGreaterThan(0.05);
    await page.getByTestId('timeline-play').click();
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
    const t = await timelineT(page);
    const f = frameAt(examGrid(), EXAM, DEFAULT_PATH, t);
    const d2 = await waitForDescription(cdp, MAIN, (d) => d.includes(`t = ${coord(t)}`));
    expect(d2).toContain(`u ${coord(f.u)}, v ${coord(f.v)}`);
    expect(d2).toContain(`bilinear ${short(f.lookup.bil.value)} from`);
    expect(d2).toContain(`nearest ${short(f.lookup.near.value)}`);
    // … and the live region said it on pause
    await expect(page.getByTestId('live-region')).toContainText(`t = ${coord(t)}`, { timeout: 10_000 });
  });

  await test.step('the exam’s (a), (b) and (c) by keyboard: move the query, type the sphere point, read the tree', async () => {
    await openScene(page, '#/texture?u=0.6&v=0.6&x=2&y=0&z=0');
    await waitForDescription(cdp, MAIN, (x) => x.includes('u 0.60, v 0.60'));
    await tabTo(page, 'texel-grid');
    // (0.6, 0.6) → (0.4, 0.24): Shift+← twice (0.1 each), Shift+↓ three times, ↓ six times (0.01 each)
    for (let k = 0; k < 2; k++) await page.keyboard.press('Shift+ArrowLeft');
    for (let k = 0; k < 3; k++) await page.keyboard.press('Shift+ArrowDown');
    for (let k = 0; k < 6; k++) await page.keyboard.press('ArrowDown');
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - L(0.4, 0.24)) < 1e-9);
    const d = await waitForDescription(cdp, MAIN, (x) => x.includes('u 0.40, v 0.24'));
    expect(d).toContain(`bilinear ${short(L(0.4, 0.24))}`); // (b)
    expect(d).toContain('nearest 18, the node (2, 1) at (0.50, 0.25)'); // (a)
    // (c): the point with y/x = 1 and z/r = √2/2, typed into the fields
    for (const [k, value] of [
      ['x', '1'],
      ['y', '1'],
      ['z', String(Math.SQRT2)],
    ] as const) {
      await tabTo(page, `${k}-field`);
      await page.keyboard.press('Control+A');
      await page.keyboard.type(value);
      await page.keyboard.press('Enter');
    }
    const s = await waitForDescription(cdp, SPHERE, (x) => x.includes('(0.125, 0.25)'));
    expect(s).toContain(`bilinear ${short(L(1 / 8, 1 / 4))}`);
  });

  await test.step('a cell’s value edited without pointing: choose its column and row, type the value', async () => {
    await openScene(page, '#/texture?open=edit');
    await expect(page.getByTestId('fold-edit')).toHaveAttribute('open', '');
    await tabTo(page, 'edit-toggle');
    await page.keyboard.press('Space');
    await tabTo(page, 'cell-column');
    await page.keyboard.press('ArrowDown'); // column 3
    await tabTo(page, 'cell-field', 4);
    await expect(page.getByTestId('cell-field')).toHaveValue(String(21 - 5 + 3));
    await page.getByTestId('cell-column').selectOption('2');
    await page.getByTestId('cell-row').selectOption('1');
    await expect(page.getByTestId('cell-field')).toHaveValue('18');
    await page.getByTestId('cell-field').focus();
    await page.keyboard.press('Control+A');
    await page.keyboard.type('118');
    await page.keyboard.press('Enter');
    await waitForReadout(page, 'nearest', (x) => x === '118');
    await waitForDescription(cdp, MAIN, (x) => x.includes('Editing cells: node (2, 1) chosen, value 118.'));
  });
});
