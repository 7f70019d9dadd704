/**
 * Browser tests of #/texture (exam Q3): the page's readouts and worked steps are wired to the
 * core's lookups for a link, its controls, clicks, drags and typed values move them and write the
 * link, the cell editor is a fold the link reopens, a drag of the query redraws only the marker
 * layer, and the query's cross lands on both reconstructions at a laptop's and a phone's width.
 * Elsewhere: the lookup tables (addressing modes, texel centres, edges, grid sizes) are unit tests
 * (tests/core/texture/, tests/scenes/texture/); the page as a whole, its parts in order and play,
 * pause and the link's t are in catalogue.spec.ts; the accessibility tree and the keyboard in
 * texture-a11y.spec.ts. Expected values are computed here from the parameters with the core,
 * never copied from the key.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/texture/params';
import { bilinearStencil, examGrid, nearestStencil, parseGrid, sphericalUV } from '../../src/core/texture';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const close = (a: number, b: number, tol = 1e-9) =>
  expect(Math.abs(a - b), `${a} ≈ ${b}`).toBeLessThanOrEqual(tol);
/** As the page prints a number in text (6 significant digits). */
const p6 = (x: number) => String(Number(x.toPrecision(6)));

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

/**
 * The readouts equal the core's lookups for a link. A link opened on the page that is already open
 * renders as a transition, a moment later: the readouts are read once two of them show it.
 */
async function expectReadouts(page: Page, q: string) {
  const want = expected(q);
  await waitForReadout(page, 'bilinear', (v) => Number(v) === want.bilinear);
  await waitForReadout(page, 'sphere-bilinear', (v) => Number(v) === want.sphereBilinear);
  expect(Number(await readout(page, 'nearest')), `nearest (${q})`).toBe(want.nearest);
  expect(await readoutNumber(page, 'sphere-u'), `sphere-u (${q})`).toBe(want.sphereU);
  expect(await readoutNumber(page, 'sphere-v'), `sphere-v (${q})`).toBe(want.sphereV);
  return want;
}

test('wiring: readouts and worked steps for links, the key’s notes, back to the exam, and the settings', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await test.step('the exam: the answers, the printed grid, (b) in the key’s form and (c) with the key’s 8.44', async () => {
    await openScene(page, '#/texture');
    const want = await expectReadouts(page, '');
    expect(want.nearest).toBe(18);
    close(want.bilinear, L(0.4, 0.24));
    close(want.sphereBilinear, L(1 / 8, 1 / 4));
    await expect(page.getByTestId('worked-query')).toContainText('c_u');
    await expect(page.locator('.readout-note').first()).toContainText('agrees with the key');
    // the exam's grid as printed: top row v = 1 is 1 … 5
    expect(await page.getByTestId('exam-grid').locator('tr').first().locator('td').allTextContents()).toEqual(
      ['1', '2', '3', '4', '5'],
    );
    // (b): the upper row (v = 0.25) and the lower row (v = 0) at u = 0.4, then along v, each step
    // divided by the cell size Δu = 0.25
    const d = page.getByTestId('derivation-3b');
    await expect(d.locator('.katex').first()).toBeVisible();
    for (const text of [p6(L(0.4, 0.25)), p6(L(0.4, 0)), p6(L(0.4, 0.24)), 'Δu', '0.25'])
      await expect(d).toContainText(text);
    // the key note: what leaving out the division would give (c scaled by Δu Δv)
    await expect(page.getByTestId('keynote-3b')).toContainText(
      `c ${String(Number((L(0.4, 0.24) * 0.25 * 0.25).toPrecision(4)))}`,
    );
    // (c): atan2, arccos, the normalization by (2π, π); the un-normalized value and the key's 8.44
    const c = page.getByTestId('derivation-3c');
    for (const text of ['atan2', 'arccos', p6(Math.PI / 4), p6(2 * Math.PI), p6(1 / 8), p6(L(1 / 8, 1 / 4))])
      await expect(c).toContainText(text);
    const note = page.getByTestId('key-note');
    await expect(note).toContainText('8.44');
    await expect(note).toContainText(p6(21 - 4 * Math.PI));
    await expect(note).toContainText(`rounds to ${(21 - 4 * Math.PI).toFixed(2)}`);
  });

  await test.step('links: texel centres with repeat on another grid, and the un-normalized sphere', async () => {
    const centres = 'grid=7,10;3,-1&align=center&wrap=repeat&u=1&v=0.25&x=-1&y=1&z=0.5';
    await openScene(page, `#/texture?${centres}`);
    await expectReadouts(page, centres);
    // forgetting to normalize: the key's printed figure differs, both variants shown
    const raw = 'normalize=0&u=1.4&v=-0.24&wrap=mirror';
    await openScene(page, `#/texture?${raw}`);
    await expectReadouts(page, raw);
    await expect(page.getByTestId('key-note')).toContainText('8.44');
    await expect(page.getByTestId('sphere-raw-value')).toBeVisible();
    await expect(page.getByTestId('sphere-normalized-value')).toBeVisible();
  });

  await test.step('another query: the steps follow it, say it is not the exam’s, and a button goes back', async () => {
    // at (0.6, 0.6) the cell is [0.5, 0.75]²
    await openScene(page, '#/texture?u=0.6&v=0.6');
    await expectReadouts(page, 'u=0.6&v=0.6');
    await expect(page.getByTestId('derivation-3b')).toContainText(p6(L(0.6, 0.75)));
    await expect(page.getByTestId('not-exam-query').first()).toBeVisible();
    await page.getByTestId('to-exam').first().click();
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - L(0.4, 0.24)) < 1e-9);
  });

  await test.step('the settings change the figures at once and write the link', async () => {
    await openScene(page, '#/texture?open=settings');
    await expectReadouts(page, '');
    await page.getByTestId('align-select').selectOption('center');
    const centre = expected('align=center');
    await waitForReadout(page, 'bilinear', (v) => Number(v) === centre.bilinear);
    await expect(page).toHaveURL(/align=center/);
    await page.getByTestId('align-select').selectOption('corner');
    await page.getByTestId('vflip-toggle').check();
    const flipped = expected('vflip=1');
    await waitForReadout(page, 'nearest', (v) => Number(v) === flipped.nearest);
    await expect(page).toHaveURL(/vflip=1/);
    await expect(page.getByTestId('addressing-note')).toContainText('v′ = 1 − v');
  });
});

test('the cell editor is a fold written into the link; a clicked cell edited changes the lookups; typed and clicked sphere points', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // (a link with open=edit opening the editor is checked in texture-a11y.spec.ts)
  await test.step('the cell editor: closed with nothing mounted, opened by a click that writes it into the link', async () => {
    await openScene(page, '#/texture');
    const fold = page.getByTestId('fold-edit');
    await expect(fold).not.toHaveAttribute('open');
    await expect(page.getByTestId('edit-toggle')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=edit(&|$)/);
  });

  await test.step('a click on a node picks it; its new value changes nearest and bilinear', async () => {
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

  await test.step('typing (x, y, z) updates the sphere readouts; clicking the sphere picks a point', async () => {
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

interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** The boxes of both reconstructions (canvas and query cross) and of the card that holds them. */
async function reconBoxes(page: Page): Promise<{ card: Box; figs: { canvas: Box; cross: Box }[] }> {
  const recon = page.locator('.tx-recon');
  await recon.scrollIntoViewIfNeeded();
  return recon.evaluate((el) => {
    const box = (e: Element | null): Box => {
      if (!e) throw new Error('missing element');
      const r = e.getBoundingClientRect();
      return { x: r.left, y: r.top, width: r.width, height: r.height };
    };
    return {
      card: box(el.closest('.panel')),
      figs: [...el.querySelectorAll('.tx-recon-box')].map((b) => ({
        canvas: box(b.querySelector('canvas')),
        cross: box(b.querySelector('.tx-query')),
      })),
    };
  });
}

const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

test('a drag of the query redraws only the marker layer; its cross then sits on both reconstructions at 1280 and 375 px', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // count canvas redraws: the two reconstructions write their pixels (putImageData); the grid's
  // base layer fills one rectangle per texel region, a redraw starting with the one at (0, 0)
  await page.addInitScript(() => {
    const w = window as unknown as { __puts: number };
    w.__puts = 0;
    const proto = CanvasRenderingContext2D.prototype;
    const put = proto.putImageData;
    proto.putImageData = function (this: CanvasRenderingContext2D, ...args: Parameters<typeof put>) {
      w.__puts++;
      return put.apply(this, args);
    } as typeof put;
    const fill = proto.fillRect;
    proto.fillRect = function (this: CanvasRenderingContext2D, x: number, y: number, cw: number, ch: number) {
      if (x === 0 && y === 0) w.__puts++;
      return fill.call(this, x, y, cw, ch);
    };
  });
  const puts = () => page.evaluate(() => (window as unknown as { __puts: number }).__puts);
  let u = 0;
  let v = 0;
  await test.step('click and drag the query point: no canvas is redrawn, the static layer does not change', async () => {
    await openScene(page, '#/texture?preset=random&size=32&open=whole');
    const svg = page.getByTestId('texel-grid');
    await expect(svg).toBeVisible();
    // the reconstructions are drawn when they come near the screen
    await page.getByTestId('recon-bilinear').scrollIntoViewIfNeeded();
    await expect.poll(puts).toBeGreaterThanOrEqual(3);
    await svg.scrollIntoViewIfNeeded();
    // the canvases are drawn once they have settled: the count reads the same twice in a row
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
    const steps = 12;
    for (let k = 1; k <= steps; k++)
      await page.mouse.move(
        box.x + box.width * (0.3 + (0.4 * k) / steps),
        box.y + box.height * (0.3 + (0.3 * k) / steps),
      );
    await page.mouse.up();
    expect(await page.evaluate(() => (window as unknown as { __mut: number }).__mut)).toBe(0);
    expect(await puts()).toBe(putsBefore);
    await expect(page).toHaveURL(/u=/);
    const url = new URL(page.url().replace(/^.*#\/texture\?/, 'http://x/?'));
    u = Number(url.searchParams.get('u'));
    v = Number(url.searchParams.get('v'));
    expect(u).toBeGreaterThan(0.5);
  });

  for (const [w, h] of [
    [1280, 900],
    [375, 800],
  ] as const) {
    await test.step(`${w} px: the query's cross sits on each picture at (u, v), the pictures apart inside their card`, async () => {
      await page.setViewportSize({ width: w, height: h });
      // the cross is symmetric about the query, so its box's centre is the query's point
      const centreOff = (f: { canvas: Box; cross: Box }) => [
        f.cross.x + f.cross.width / 2 - (f.canvas.x + u * f.canvas.width),
        f.cross.y + f.cross.height / 2 - (f.canvas.y + (1 - v) * f.canvas.height),
      ];
      // the page lays itself out again for the new width: poll until the cross has followed
      await expect
        .poll(async () =>
          Math.max(...(await reconBoxes(page)).figs.flatMap((f) => centreOff(f).map(Math.abs))),
        )
        .toBeLessThanOrEqual(2);
      const { card, figs } = await reconBoxes(page);
      expect(figs).toHaveLength(2);
      for (const [k, { canvas }] of figs.entries()) {
        const name = k === 0 ? 'nearest' : 'bilinear';
        expect(canvas.width, `${name} canvas has a size`).toBeGreaterThan(50);
        expect(canvas.x, `${name} canvas left of the card's edge`).toBeGreaterThanOrEqual(card.x);
        expect(canvas.x + canvas.width, `${name} canvas past the card's right edge`).toBeLessThanOrEqual(
          card.x + card.width,
        );
        expect(canvas.y, `${name} canvas above the card`).toBeGreaterThanOrEqual(card.y);
        expect(canvas.y + canvas.height, `${name} canvas below the card`).toBeLessThanOrEqual(
          card.y + card.height,
        );
      }
      expect(overlap(figs[0].canvas, figs[1].canvas), 'the two canvases overlap').toBe(false);
    });
  }

  await test.step('the dragged point is in the link: on the exam grid it gives L(u, v) there', async () => {
    await openScene(page, `#/texture?u=${u}&v=${v}`);
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - L(u, v)) <= 1e-9);
  });
});
