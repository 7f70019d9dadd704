/**
 * #/texture as a screen reader receives it: the figures' names and descriptions read from
 * Chromium's accessibility tree (CDP), the audio traces of the value along the path, the cell
 * editor without pointing, and the exam's interaction by keyboard alone. Expected figures come
 * from the exam grid's definition (L(u, v) = 21 + 4u − 20v) or the scene's own pure model at the
 * position the page reports.
 */
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, openScene, waitForReadout } from './fixtures';
import { frameAt, pathOf } from '../../src/scenes/texture/path';
import { checkerGrid, examGrid, type LookupOptions } from '../../src/core/texture';
import { coord, short } from '../../src/scenes/texture/view/describe';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const EXAM: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const DEFAULT_PATH = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
const MAIN = 'Texel grid with the query point, its path, and the value along the path';
const PLOT = 'The looked-up value along the path: nearest and bilinear against the position t';
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

/** Presses Tab until the element with `testId` has the focus (at most `max` presses). */
async function tabTo(page: Page, testId: string, max = 120): Promise<void> {
  for (let k = 0; k < max; k++) {
    await page.keyboard.press('Tab');
    if (await page.evaluate((id) => document.activeElement?.getAttribute('data-testid') === id, testId))
      return;
  }
  throw new Error(`Tab never reached ${testId}`);
}

test.describe('the figures in the accessibility tree', () => {
  test('the main figure is named and its description holds the live numbers; it changes with a parameter and on pause', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const cdp = await page.context().newCDPSession(page);
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
    await expect.poll(() => timelineT(page), { timeout: 20_000 }).toBeGreaterThan(0.15);
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

  test('the plot of the value along the path: named, summarized, as a table', async ({ page }) => {
    await openScene(page, '#/texture');
    const cdp = await page.context().newCDPSession(page);
    const d = await waitForDescription(cdp, PLOT, (x) => x.includes('Bilinear'));
    expect(d).toContain(
      `Bilinear falls from ${short(L(0.4, 0.24))} at t = 0 to ${short(L(0.85, 0.8))} at t = 1`,
    );
    expect(d).toMatch(/crossing \d+ cell borders at t = [\d., ]+, 0 with a kink/);
    expect(d).toContain('Now at t = 0.00: nearest 18');
    const table = page.getByTestId('path-table');
    await table.locator('summary').click();
    const rows = table.locator('tbody tr');
    await expect(rows.first()).toBeVisible();
    // the first row is t = 0: nearest 18, bilinear L(0.4, 0.24)
    await expect(rows.first().locator('td')).toHaveText(['0', '18', short(L(0.4, 0.24)), '']);
    await expect(table.locator('tbody td', { hasText: 'crosses a cell border' }).first()).toBeVisible();
    // the other figures have names and descriptions too
    await page.getByTestId('sphere-figure').scrollIntoViewIfNeeded();
    expect((await axNamed(cdp, SPHERE))?.description).toContain('azimuth φ 45°, polar angle θ 45°');
    await page.getByTestId('grid-table').locator('summary').click();
    await expect(page.getByTestId('grid-table').locator('tbody tr').first().locator('td')).toHaveText([
      '1',
      '1',
      '2',
      '3',
      '4',
      '5',
    ]);
  });

  test('the audio trace starts Web Audio nodes on Enter and steps point by point by key', async ({
    page,
  }) => {
    await page.addInitScript(() => {
      const w = window as unknown as { __osc: number };
      w.__osc = 0;
      const proto = BaseAudioContext.prototype;
      const orig = proto.createOscillator;
      proto.createOscillator = function (this: BaseAudioContext) {
        w.__osc++;
        return orig.call(this);
      };
    });
    await openScene(page, '#/texture?preset=checker&size=8');
    await page.getByTestId('path-listen').locator('summary').click();
    const trace = page.getByTestId('path-audio-bilinear');
    await trace.focus();
    // nothing plays until asked
    expect(await page.evaluate(() => (window as unknown as { __osc: number }).__osc)).toBe(0);
    await page.keyboard.press('Enter');
    await expect
      .poll(() => page.evaluate(() => (window as unknown as { __osc: number }).__osc), { timeout: 15_000 })
      .toBeGreaterThan(0);
    await page.keyboard.press('Escape');
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    const f = frameAt(checkerGrid(8, 8), EXAM, DEFAULT_PATH, 1 / 40);
    await expect(page.getByTestId('path-audio-bilinear-point')).toContainText('(point 2 of 41)');
    await expect(page.getByTestId('path-audio-bilinear-point')).toContainText(
      `bilinear = ${short(f.lookup.bil.value)}`,
    );
    await expect(page.getByTestId('live-region')).toContainText('point 2 of 41', { timeout: 10_000 });
    // the checkerboard's kinks are events: some point names one
    await page.keyboard.press('End');
    await expect(page.getByTestId('path-audio-bilinear-point')).toContainText('(point 41 of 41)');
  });
});

test.describe('by keyboard alone', () => {
  test('the exam’s (a), (b) and (c): move the query and type the sphere point, read the answers from the tree', async ({
    page,
  }) => {
    await openScene(page, '#/texture?u=0.6&v=0.6&x=2&y=0&z=0');
    const cdp = await page.context().newCDPSession(page);
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

  test('a cell’s value edited without pointing: choose its column and row, type the value', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
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
    const cdp = await page.context().newCDPSession(page);
    await waitForDescription(cdp, MAIN, (x) => x.includes('Editing cells: node (2, 1) chosen, value 118.'));
  });
});

test.describe('ask first, and the stage for the room', () => {
  test('ask=1: the steps, answers, stencil, plot and animation are hidden until Reveal', async ({ page }) => {
    await openScene(page, '#/texture?ask=1&t=0.5');
    await expect(page.getByTestId('ask-prompt')).toBeVisible();
    for (const id of ['nearest', 'bilinear', 'sphere-u', 'derivation-3a', 'derivation-3b', 'derivation-3c'])
      await expect(page.getByTestId(id), id).toHaveCount(0);
    for (const id of ['stencil', 'path-plot', 'timeline', 'query-now', 'phi-slider'])
      await expect(page.getByTestId(id), id).toHaveCount(0);
    await expect(page.getByTestId('part-3b').getByTestId('ask-hidden')).toContainText(
      'Hidden until you reveal: the steps and the answer',
    );
    const cdp = await page.context().newCDPSession(page);
    const d = (await axNamed(cdp, MAIN))!.description;
    expect(d).toContain('The query point at u 0.40, v 0.24; the values looked up there are hidden');
    expect(d).not.toMatch(/bilinear|nearest|45°/);
    // the query is at the start of its path (t = 0), not at the link's t
    expect(d).toContain('at the start of its path');

    await page.getByTestId('reveal').click();
    await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
    await waitForReadout(page, 'bilinear', (x) => Number.isFinite(Number(x)));
    await expect(page.getByTestId('derivation-3b')).toBeVisible();
    await expect(page.getByTestId('stencil')).toHaveCount(1);
    await expect(page.getByTestId('timeline')).toBeVisible();
    const t = await timelineT(page);
    const f = frameAt(examGrid(), EXAM, DEFAULT_PATH, t);
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
    await waitForDescription(cdp, MAIN, (x) => x.includes(`bilinear ${short(f.lookup.bil.value)} from`));
  });

  // the classroom's own first screen at the common projector size (the other screen sizes and the
  // stage's general checks run for every scene in catalogue.spec.ts and stage.spec.ts)
  for (const [w, h] of [[1280, 720]] as const) {
    for (const ask of [false, true]) {
      test(`present=1${ask ? '&ask=1' : ''} at ${w}×${h}: the stage (grid, readouts, transport) is wholly on the first screen`, async ({
        page,
      }) => {
        await page.setViewportSize({ width: w, height: h });
        await openScene(page, `#/texture?present=1${ask ? '&ask=1' : ''}`);
        const stage = page.getByTestId('scene-stage');
        const box = (await stage.boundingBox())!;
        expect(box.y).toBeGreaterThanOrEqual(0);
        expect(box.y + box.height).toBeLessThanOrEqual(h);
        // nothing of the stage spills out of it
        const [sh, ch] = await stage.evaluate((el) => [el.scrollHeight, el.clientHeight]);
        expect(sh).toBeLessThanOrEqual(ch + 1);
        const inside = async (testId: string) => {
          const b = (await page.getByTestId(testId).boundingBox())!;
          expect(b.y, testId).toBeGreaterThanOrEqual(box.y - 1);
          expect(b.y + b.height, testId).toBeLessThanOrEqual(Math.min(h, box.y + box.height) + 1);
          return b;
        };
        const grid = await inside('texel-grid');
        expect(grid.height).toBeGreaterThan(ask ? 250 : 380);
        if (ask) {
          const held = page.getByTestId('scene-stage').getByTestId('ask-hidden').first();
          await expect(held).toContainText('the query’s path');
          const b = (await held.boundingBox())!;
          expect(b.y + b.height).toBeLessThanOrEqual(Math.min(h, box.y + box.height) + 1);
        } else {
          await inside('timeline');
          await inside('query-now');
          // the key readouts in classroom type
          const px = await page
            .getByTestId('query-now')
            .evaluate((el) => parseFloat(getComputedStyle(el).fontSize));
          expect(px).toBeGreaterThanOrEqual(18);
        }
        // the stage is the described main figure
        const cdp = await page.context().newCDPSession(page);
        expect((await axNamed(cdp, MAIN))?.description).toContain('u 0.40, v 0.24');
      });
    }
  }
});
