/**
 * Browser tests of #/texture (exam Q3): the page's readouts are wired to the core's lookups, its
 * controls, drags and keys move them, bad input is named on the page. The lookup tables themselves
 * (addressing modes, texel centres, edges, grid sizes) are unit tests: tests/core/texture/.
 * Expected values are computed here from the parameters with the core, never copied from the key.
 */
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/texture/params';
import { bilinearStencil, examGrid, nearestStencil, parseGrid, sphericalUV } from '../../src/core/texture';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const close = (a: number, b: number, tol = 1e-9) =>
  expect(Math.abs(a - b), `${a} ≈ ${b}`).toBeLessThanOrEqual(tol);

/** What the readouts must say for a link's query (a grid given as text; the path at t = 0). */
function expected(query: string) {
  const p = parseParams(schema, query).values;
  const parsed = parseGrid(p.grid);
  const grid = parsed.ok ? parsed.grid : examGrid();
  const opts = { align: p.align, vflip: p.vflip, wrap: p.wrap };
  const s = sphericalUV(p.x, p.y, p.z);
  if (!s.ok) throw new Error(`no sphere point in ${query}`);
  const [su, sv] = p.normalize ? [s.u, s.v] : [s.phi, s.theta];
  return {
    nearest: nearestStencil(grid, p.u, p.v, opts).value,
    bilinear: bilinearStencil(grid, p.u, p.v, opts).value,
    sphereU: su,
    sphereV: sv,
    sphereBilinear: bilinearStencil(grid, su, sv, opts).value,
  };
}

test('wiring: the readouts are the core’s lookups for the exam, texel centres with repeat, and the unnormalized sphere', async ({
  page,
}) => {
  for (const q of [
    '',
    'grid=7,10;3,-1&align=center&wrap=repeat&u=1&v=0.25&x=-1&y=1&z=0.5',
    'normalize=0&u=1.4&v=-0.24&wrap=mirror',
  ]) {
    await openScene(page, `#/texture?${q}`);
    const want = expected(q);
    expect(Number(await readout(page, 'nearest')), `nearest (${q})`).toBe(want.nearest);
    expect(await readoutNumber(page, 'bilinear'), `bilinear (${q})`).toBe(want.bilinear);
    expect(await readoutNumber(page, 'sphere-u'), `sphere-u (${q})`).toBe(want.sphereU);
    expect(await readoutNumber(page, 'sphere-v'), `sphere-v (${q})`).toBe(want.sphereV);
    expect(await readoutNumber(page, 'sphere-bilinear'), `sphere-bilinear (${q})`).toBe(want.sphereBilinear);
    if (q === '') {
      // the exam's answers, and the worked panel with the key's three steps
      expect(want.nearest).toBe(18);
      close(want.bilinear, L(0.4, 0.24));
      close(want.sphereBilinear, L(1 / 8, 1 / 4));
      await expect(page.getByTestId('worked-query')).toContainText('c_u');
      await expect(page.locator('.readout-note').first()).toContainText('agrees with the key');
    }
    if (q.startsWith('normalize=0')) {
      // forgetting to normalize: the scene says the key's printed figure differs, both variants shown
      await expect(page.getByTestId('key-note')).toContainText('8.44');
      await expect(page.getByTestId('sphere-raw-value')).toBeVisible();
      await expect(page.getByTestId('sphere-normalized-value')).toBeVisible();
    }
  }
});

test('toggling the controls changes the figures at once and writes the link', async ({ page }) => {
  await openScene(page, '#/texture?open=settings');
  await page.getByTestId('align-select').selectOption('center');
  const centre = expected('align=center');
  await waitForReadout(page, 'bilinear', (v) => Number(v) === centre.bilinear);
  await page.getByTestId('align-select').selectOption('corner');
  await page.getByTestId('vflip-toggle').check();
  const flipped = expected('vflip=1');
  await waitForReadout(page, 'nearest', (v) => Number(v) === flipped.nearest);
  await expect(page).toHaveURL(/vflip=1/);
  await expect(page.getByTestId('addressing-note')).toContainText('v′ = 1 − v');
});

test.describe('interaction', () => {
  test('click and drag the query point: only the marker layer changes, no canvas is redrawn', async ({
    page,
  }) => {
    // count canvas redraws (the grid's base layer and the two reconstructions use putImageData)
    await page.addInitScript(() => {
      const w = window as unknown as { __puts: number };
      w.__puts = 0;
      const orig = CanvasRenderingContext2D.prototype.putImageData;
      CanvasRenderingContext2D.prototype.putImageData = function (
        this: CanvasRenderingContext2D,
        ...args: Parameters<typeof orig>
      ) {
        w.__puts++;
        return orig.apply(this, args);
      } as typeof orig;
    });
    await openScene(page, '#/texture?preset=random&size=32&open=whole');
    const svg = page.getByTestId('texel-grid');
    await expect(svg).toBeVisible();
    // the reconstructions are drawn when they come near the screen
    await page.getByTestId('recon-bilinear').scrollIntoViewIfNeeded();
    await expect
      .poll(() => page.evaluate(() => (window as unknown as { __puts: number }).__puts))
      .toBeGreaterThanOrEqual(3);
    await svg.scrollIntoViewIfNeeded();
    // the canvases are drawn once they have settled: the count reads the same twice in a row
    const puts = () => page.evaluate(() => (window as unknown as { __puts: number }).__puts);
    let last = -1;
    await expect
      .poll(
        async () => {
          const n = await puts();
          const settled = n === last;
          last = n;
          return settled;
        },
        { intervals: [250] },
      )
      .toBe(true);
    const putsBefore = await puts();
    expect(putsBefore).toBeGreaterThanOrEqual(3);
    // count DOM mutations inside the static layer (the svg's first <g>: 32 × 32 nodes and lines)
    await page.evaluate(() => {
      const g = document.querySelector('[data-testid=texel-grid] > g')!;
      const w = window as unknown as { __mut: number };
      w.__mut = 0;
      new MutationObserver((m) => (w.__mut += m.length)).observe(g, {
        subtree: true,
        childList: true,
        attributes: true,
        characterData: true,
      });
    });
    const box = (await svg.boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.3);
    await page.mouse.down();
    const steps = 40;
    for (let k = 1; k <= steps; k++)
      await page.mouse.move(
        box.x + box.width * (0.3 + (0.4 * k) / steps),
        box.y + box.height * (0.3 + (0.3 * k) / steps),
      );
    await page.mouse.up();
    expect(await page.evaluate(() => (window as unknown as { __mut: number }).__mut)).toBe(0);
    expect(await page.evaluate(() => (window as unknown as { __puts: number }).__puts)).toBe(putsBefore);
    await expect(page).toHaveURL(/u=/);
    // the dragged point is in the link: on the exam grid it gives L(u, v) there
    const url = new URL(page.url().replace(/^.*#\/texture\?/, 'http://x/?'));
    const u = Number(url.searchParams.get('u'));
    const v = Number(url.searchParams.get('v'));
    expect(u).toBeGreaterThan(0.5);
    await openScene(page, `#/texture?u=${u}&v=${v}`);
    close(await readoutNumber(page, 'bilinear'), L(u, v), 1e-9);
  });

  test('the cell editor is folded (opened by a click, kept by the link); editing a cell changes the lookups', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    // closed on load with nothing mounted; a click opens it and writes open=edit, which a reload keeps
    const fold = page.getByTestId('fold-edit');
    await expect(fold).not.toHaveAttribute('open');
    await expect(page.getByTestId('edit-toggle')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=edit(&|$)/);
    await page.reload();
    await page.waitForSelector('main#main');
    await expect(page.getByTestId('fold-edit')).toHaveAttribute('open', '');
    await page.getByTestId('edit-toggle').check();
    await page.getByTestId('texel-grid').scrollIntoViewIfNeeded();
    const box = (await page.getByTestId('texel-grid').boundingBox())!;
    // the node (0.5, 0.25) = value 18; the plotted window is [−0.08, 1.08]
    const fx = (0.5 + 0.08) / 1.16;
    const fy = (1.08 - 0.25) / 1.16;
    await page.mouse.click(box.x + box.width * fx, box.y + box.height * fy);
    const cell = page.getByTestId('cell-field');
    await expect(cell).toHaveValue('18');
    await cell.fill('118');
    await cell.press('Enter');
    await waitForReadout(page, 'nearest', (x) => x === '118');
    // bilinear weight of node (2, 1) at (0.4, 0.24) is fu·fv = 0.6 · 0.96
    close(await readoutNumber(page, 'bilinear'), L(0.4, 0.24) + 100 * 0.6 * 0.96, 1e-9);
  });

  test('typing (x, y, z) updates the sphere readouts; clicking the sphere picks a point', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const x = page.getByTestId('x-field');
    await x.fill('-1');
    await x.press('Enter');
    // (−1, 1, √2): φ = 3π/4 → u = 3/8
    await waitForReadout(page, 'sphere-u', (s) => Math.abs(Number(s) - 3 / 8) < 1e-15);
    const vp = page.getByTestId('sphere-view');
    await vp.scrollIntoViewIfNeeded();
    await expect(vp).toHaveAttribute('data-status', 'ready');
    await expect(vp.locator('canvas')).toBeVisible();
    await expect(vp).toBeInViewport();
    const b = (await vp.boundingBox())!;
    await page.mouse.click(b.x + b.width / 2, b.y + b.height / 2);
    // the camera looks at the origin from φ ≈ 16°: the picked point faces it
    const u = Number(await waitForReadout(page, 'sphere-u', (s) => Math.abs(Number(s) - 3 / 8) > 1e-3));
    expect(u).toBeGreaterThan(0);
    expect(u).toBeLessThan(0.1);
  });
});
