/**
 * Browser tests of #/texture (exam first, true statements, legible layouts)
 * (the query travels a path on the shared timeline). Expected figures are computed here: from the
 * exam grid's definition (value(i, j) = 21 − 5j + i at (i/4, j/4), i.e. L(u, v) = 21 + 4u − 20v)
 * or from the scene's own pure model at the position the page reports — never copied from the key.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, waitForReadout } from './fixtures';
import { frameAt, pathOf, type QueryPath } from '../../src/scenes/texture/path';
import { examGrid, type LookupOptions } from '../../src/core/texture';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const EXAM: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const DEFAULT_PATH: QueryPath = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
/** As the page prints a number in text (6 significant digits). */
const p6 = (x: number) => String(Number(x.toPrecision(6)));

async function timelineT(page: Page): Promise<number> {
  return Number(await page.getByTestId('timeline').getAttribute('data-t'));
}

test.describe('exam first', () => {
  test('the page opens with the question, then (a), (b), (c) in order, then explore further', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const ys: number[] = [];
    for (const id of ['question-3', 'texel-grid', 'part-3a', 'part-3b', 'part-3c', 'explore-further']) {
      const b = await page.getByTestId(id).boundingBox();
      expect(b, id).not.toBeNull();
      ys.push(b!.y);
    }
    for (let k = 1; k < ys.length; k++)
      expect(ys[k], `element ${k} below element ${k - 1}`).toBeGreaterThan(ys[k - 1]);
    // the exam's grid as printed: top row v = 1 is 1 … 5
    await expect(page.getByTestId('exam-grid').locator('tr').first()).toContainText('1');
    expect(await page.getByTestId('exam-grid').locator('tr').first().locator('td').allTextContents()).toEqual(
      ['1', '2', '3', '4', '5'].map(String),
    );
  });

  test('(b): the key’s c_u, c_l, c, each divided by the cell size, with live numbers', async ({ page }) => {
    await openScene(page, '#/texture');
    const d = page.getByTestId('derivation-3b');
    await expect(d.locator('.katex').first()).toBeVisible();
    // the upper row (v = 0.25) and the lower row (v = 0) at u = 0.4, then along v
    await expect(d).toContainText(p6(L(0.4, 0.25)));
    await expect(d).toContainText(p6(L(0.4, 0)));
    await expect(d).toContainText(p6(L(0.4, 0.24)));
    await expect(d).toContainText('Δu');
    await expect(d).toContainText('0.25');
    // the key note: what leaving out the division would give (c scaled by Δu Δv)
    await expect(page.getByTestId('keynote-3b')).toContainText(
      `c ${String(Number((L(0.4, 0.24) * 0.25 * 0.25).toPrecision(4)))}`,
    );
    // moving the query changes the numbers: at (0.6, 0.6) the cell is [0.5, 0.75]²
    await openScene(page, '#/texture?u=0.6&v=0.6');
    await expect(page.getByTestId('derivation-3b')).toContainText(p6(L(0.6, 0.75)));
    await expect(page.getByTestId('not-exam-query').first()).toBeVisible();
    await page.getByTestId('to-exam').first().click();
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - L(0.4, 0.24)) < 1e-9);
  });

  test('(c): atan2, arccos, the normalization by (2π, π); the un-normalized value computed and the key’s 8.44 named', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const d = page.getByTestId('derivation-3c');
    await expect(d).toContainText('atan2');
    await expect(d).toContainText('arccos');
    await expect(d).toContainText(p6(Math.PI / 4));
    await expect(d).toContainText(p6(2 * Math.PI));
    await expect(d).toContainText(p6(1 / 8));
    await expect(d).toContainText(p6(L(1 / 8, 1 / 4)));
    const note = page.getByTestId('key-note');
    await expect(note).toContainText('8.44');
    await expect(note).toContainText(p6(21 - 4 * Math.PI));
    await expect(note).toContainText(`rounds to ${(21 - 4 * Math.PI).toFixed(2)}`);
  });
});

test.describe('legible', () => {});

test.describe('the query travels its path', () => {
  test('play, pause: the readouts are the model at the paused t; the link restores them exactly', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    await page.getByTestId('timeline-play').click();
    await expect.poll(() => timelineT(page), { timeout: 20_000 }).toBeGreaterThan(0.1);
    await page.getByTestId('timeline-play').click();
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
    const t = await timelineT(page);
    expect(t).toBeGreaterThan(0);
    await expect(page).toHaveURL(new RegExp(`t=${String(t).replace('.', '\\.')}(&|$)`));
    const f = frameAt(examGrid(), EXAM, DEFAULT_PATH, t);
    const near = await readout(page, 'nearest');
    const bil = await readout(page, 'bilinear');
    expect(Number(near)).toBe(f.lookup.near.value);
    expect(Math.abs(Number(bil) - f.lookup.bil.value)).toBeLessThanOrEqual(1e-12);
    // the exam grid is the plane L: bilinear at the moving query is L there
    expect(Math.abs(Number(bil) - L(f.u, f.v))).toBeLessThan(1e-9);
    // the worked steps caught up with the paused position
    await expect(page.getByTestId('derivation-3b')).toContainText(p6(f.lookup.bil.value));
    // the weights follow: the chips carry the model's weights
    expect(Number(await page.getByTestId('tap-w11').getAttribute('data-weight'))).toBe(f.lookup.bil.w11);
    // the link
    const url = page.url();
    await page.goto('about:blank');
    await page.goto(url);
    await page.waitForSelector('main#main');
    expect(await readout(page, 'nearest')).toBe(near);
    expect(await readout(page, 'bilinear')).toBe(bil);
    expect(await timelineT(page)).toBe(t);
  });
});
