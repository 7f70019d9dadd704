/**
 * #/hemisphere for a reader who does not see the figure: the main figure's description and the θ
 * histogram's, read from Chromium's accessibility tree (what a screen reader receives), their
 * live numbers recomputed here from the scene's own model, the histogram's table of bins; and a
 * keyboard-only run: orbit the 3D view, follow a stratum with the arrow keys (its sentence is the
 * model's, the URL keeps it, Escape stops), and read Q1's numbers from the accessibility tree.
 *
 * Elsewhere: the whole-page checks (axe, tab stops, the lecture room) in catalogue.spec.ts; the
 * description's wording for every lobe in tests/scenes/hemisphere/describe.test.ts.
 */
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';
import { computeDrawStats } from '../../src/scenes/hemisphere/drawStats';
import { examInversion } from '../../src/scenes/hemisphere/examChecks';
import { lobeFromParams } from '../../src/scenes/hemisphere/lobe';
import { cellImage, countInCell } from '../../src/scenes/hemisphere/stratum';
import { describeStratum } from '../../src/scenes/hemisphere/view/describe';
import { fillSequence2D } from '../../src/core/random';
import { examLobeK } from '../../src/core/sampling';
import { formatSignificant } from '../../src/ui/format';

const FIGURE = 'Warp of the unit square onto the hemisphere: samples of the chosen density';
const f3 = (x: number) => formatSignificant(x, 3, 'times');
const exam = lobeFromParams('exam', 8).lobe!;

interface AXNode {
  nodeId: string;
  ignored?: boolean;
  role?: { value: string };
  name?: { value: string };
  description?: { value: string };
  childIds?: string[];
  backendDOMNodeId?: number;
}

async function axTree(cdp: CDPSession): Promise<AXNode[]> {
  await cdp.send('Accessibility.enable');
  const { nodes } = (await cdp.send('Accessibility.getFullAXTree')) as { nodes: AXNode[] };
  return nodes;
}

/** The accessible description of the figure named `name` (a screen reader's reading of it). */
async function figureDescription(page: Page, name: string): Promise<string> {
  const cdp = await page.context().newCDPSession(page);
  const node = (await axTree(cdp)).find((n) => !n.ignored && n.name?.value === name);
  await cdp.detach();
  expect(node, `no accessible node named "${name}"`).toBeTruthy();
  return node!.description?.value ?? '';
}

/** The text of an element as the accessibility tree holds it (its StaticText descendants). */
async function axText(page: Page, selector: string): Promise<string> {
  const cdp = await page.context().newCDPSession(page);
  const { root } = (await cdp.send('DOM.getDocument', { depth: 0 })) as { root: { nodeId: number } };
  const { nodeId } = (await cdp.send('DOM.querySelector', { nodeId: root.nodeId, selector })) as {
    nodeId: number;
  };
  const { node } = (await cdp.send('DOM.describeNode', { nodeId })) as { node: { backendNodeId: number } };
  const nodes = await axTree(cdp);
  await cdp.detach();
  const byId = new Map(nodes.map((n) => [n.nodeId, n]));
  const out: string[] = [];
  const walk = (n: AXNode | undefined) => {
    if (!n) return;
    if (n.role?.value === 'StaticText' && n.name?.value) out.push(n.name.value);
    for (const c of n.childIds ?? []) walk(byId.get(c));
  };
  walk(nodes.find((n) => n.backendDOMNodeId === node.backendNodeId));
  return out.join('');
}

async function statsReady(page: Page) {
  await expect(page.getByTestId('stats-status')).toHaveAttribute('data-state', 'ready', { timeout: 60_000 });
}

/** Tab (keyboard only) until the focused element matches `selector`. */
async function tabTo(page: Page, selector: string, max = 200) {
  for (let i = 0; i < max; i++) {
    await page.keyboard.press('Tab');
    if (await page.evaluate((s) => !!document.activeElement?.matches(s), selector)) return;
  }
  throw new Error(`Tab never reached ${selector}`);
}

test('for a reader who does not see the figures, and by keyboard only: descriptions, the stratum, Q1’s numbers', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await openScene(page, '#/hemisphere?n=2000&open=settings,bins');
  await statsReady(page);
  const core = computeDrawStats(exam, Math.cos, 'independent', 1, 2000);
  let d = '';
  await test.step('the main figure: k, the count, p, where the lobe peaks', async () => {
    await expect
      .poll(() => figureDescription(page, FIGURE), { timeout: 30_000 })
      .toContain(`p = ${f3(core.chi2!.pValue)}`);
    d = await figureDescription(page, FIGURE);
    expect(d).toContain(`k = ${formatSignificant(examLobeK(), 4, 'times')}`);
    expect(d).toContain('2,000 independent samples');
    expect(d).toContain('every point sits on its direction on the hemisphere');
    expect(d).toContain(`around θ = ${f3(Math.PI / 4)} rad`);
    expect(d).toContain('towards φ = 2π');
  });

  await test.step('the 3D view: arrows orbit, Home returns', async () => {
    await tabTo(page, '[data-testid="hemisphere-3d"]');
    const triad = page.getByTestId('hemisphere-3d-axes');
    await expect(triad).toHaveAttribute('data-x-axis', /./, { timeout: 30_000 });
    const home = await triad.getAttribute('data-x-axis');
    await page.keyboard.press('ArrowLeft');
    await expect.poll(() => triad.getAttribute('data-x-axis')).not.toBe(home);
    await page.keyboard.press('Home');
    await expect.poll(() => triad.getAttribute('data-x-axis')).toBe(home);
  });

  await test.step('the stratum grid: arrows pick a cell, its sentence is the model’s, the URL keeps it, Escape stops', async () => {
    await tabTo(page, '[data-testid="stratum-cells"] [role="radio"]');
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
    for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowUp');
    const cell = page.locator('[data-cell="3,5"]');
    await expect(cell).toHaveAttribute('aria-checked', 'true');
    await expect(cell).toBeFocused();
    await expect.poll(() => page.evaluate(() => location.hash)).toMatch(/[?&]cell=3,5(&|$)/);
    const c = { i: 3, j: 5 };
    const count = countInCell('independent', 1, 2000, c, 0, 2000, new Float64Array(2 * 512));
    const text = describeStratum(c, cellImage(exam, c), count, 2000);
    await expect(page.getByTestId('stratum-text')).toHaveText(text);
    await expect.poll(() => figureDescription(page, FIGURE)).toContain(text);
    // the 3D view names the stratum it marks
    await expect(page.getByTestId('hemisphere-3d')).toHaveAttribute('aria-label', /stratum \(3, 5\) marked/);
    await page.keyboard.press('Escape');
    await expect.poll(() => page.evaluate(() => location.hash)).not.toMatch(/cell=/);
    await expect(cell).toHaveAttribute('aria-checked', 'false');
  });

  // the first sample's stratum, by the button
  const u = fillSequence2D('independent', 1, 2000, new Float64Array(2), 0, 1, 0);
  const cell = { i: Math.floor(u[0] * 8), j: Math.floor(u[1] * 8) };
  await test.step('the first sample’s stratum, by the button', async () => {
    await tabTo(page, '[data-testid="stratum-start"]');
    await page.keyboard.press('Enter');
    await expect(page.locator(`[data-cell="${cell.i},${cell.j}"]`)).toHaveAttribute('aria-checked', 'true');
    await statsReady(page);
  });

  await test.step('(a) k, (c) the CDFs at the first sample, (d) the χ² test: as a screen reader gets them', async () => {
    const k = await axText(page, '[data-testid="answer-1a"]');
    expect(k).toContain(formatSignificant(examLobeK(), 8, 'times'));
    const ex = examInversion(u[0], u[1]);
    const c = await axText(page, '[data-testid="cdf-example"]');
    expect(c).toContain(`θ = ${formatSignificant(ex.thetaAsin, 8, 'times')}`);
    expect(c).toContain(`φ = ${formatSignificant(ex.phiLog1p, 8, 'times')}`);
    expect(c).toContain(`P(θ) = ${formatSignificant(ex.cdfTheta, 10, 'times')}`);
    const verdict = await axText(page, '[data-testid="chi2-verdict"]');
    expect(verdict).toContain(`p = ${formatSignificant(core.chi2!.pValue, 4, 'times')}`);
    expect(verdict).toContain('Accepted');
    // the stratum's sentence is part of the figure's description
    expect(await figureDescription(page, FIGURE)).toContain(`Stratum (${cell.i}, ${cell.j})`);
  });

  await test.step('the θ histogram: named, summarized, a table of its bins', async () => {
    const name = 'Histogram of the sampled polar angles θ against the marginal density p(θ)';
    const h = await figureDescription(page, name);
    expect(h).toContain('Histogram of 2,000 sampled θ (rad) in 36 bins');
    expect(h).toContain(`p(θ) ends about where it starts from 0 at θ = 0 to 0 at θ = ${f3(Math.PI / 2)}`);
    expect(h).toContain(`maximum 1 at θ = ${f3(Math.PI / 4)}`);
    const table = page.getByTestId('plot-theta-table');
    await table.locator('summary').click();
    await expect(table.locator('tbody tr')).toHaveCount(36);
    const bins = core.hist!.theta;
    const first = (await table.locator('tbody tr').first().locator('td').allTextContents()).map(Number);
    expect(first[0]).toBeCloseTo(bins.centers[0], 3);
    expect(first[1]).toBeCloseTo(bins.density[0], 3);
  });

  await test.step('another lobe, another description', async () => {
    await page.getByTestId('lobe').selectOption('cosine');
    await expect.poll(() => figureDescription(page, FIGURE), { timeout: 30_000 }).toContain('cos θ / π');
    const cos = await figureDescription(page, FIGURE);
    expect(cos).not.toBe(d);
    expect(cos).toContain('evenly in φ');
  });

  await test.step('play, then pause: the description says the paused position, announced', async () => {
    await page.getByTestId('timeline-play').click();
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
    await page.waitForFunction(() => {
      const t = Number(document.querySelector('[data-testid="timeline"]')?.getAttribute('data-t'));
      return t > 0.15 && t < 0.85;
    });
    await page.getByTestId('timeline-play').click();
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
    const t = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    const s = Number(await page.getByTestId('morph-s').getAttribute('data-value'));
    await expect
      .poll(() => figureDescription(page, FIGURE))
      .toContain(`Warp morph at t = ${t.toFixed(2)} (s = ${s.toFixed(2)})`);
    await expect(page.getByTestId('live-region')).toContainText(`t = ${t.toFixed(2)}`, { timeout: 10_000 });
  });
});
