/**
 * Browser tests of #/texture (exam first, true statements, legible layouts)
 * (the query travels a path on the shared timeline). Expected figures are computed here: from the
 * exam grid's definition (value(i, j) = 21 − 5j + i at (i/4, j/4), i.e. L(u, v) = 21 + 4u − 20v)
 * or from the scene's own pure model at the position the page reports — never copied from the key.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, waitForReadout } from './fixtures';
import { frameAt, pathOf, type QueryPath } from '../../src/scenes/texture/path';
import { pathProfile } from '../../src/scenes/texture/pathProfile';
import { checkerGrid, examGrid, type LookupOptions } from '../../src/core/texture';

const L = (u: number, v: number) => 21 + 4 * u - 20 * v;
const EXAM: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const DEFAULT_PATH: QueryPath = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' });
/** As the page prints a number in text (6 significant digits). */
const p6 = (x: number) => String(Number(x.toPrecision(6)));

function urlParams(page: Page): URLSearchParams {
  return new URLSearchParams(page.url().replace(/^.*#\/texture\??/, ''));
}
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

  test('(a): the nearest steps with live numbers, and the key’s note on v′ = 1 − v with the flipped value computed', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const d = page.getByTestId('derivation-3a');
    await expect(d).toContainText('round');
    await expect(d).toContainText('0.24⋅4'); // v (N − 1) with the live v
    expect(Number(await readout(page, 'nearest'))).toBe(21 - 5 * Math.round(0.24 * 4) + Math.round(0.4 * 4));
    // flipped: v′ = 0.76 → j = round(3.04) = 3
    await expect(page.getByTestId('keynote-3a')).toContainText('v′ = 1 − v');
    await expect(page.getByTestId('keynote-3a')).toContainText(
      `nearest gives ${21 - 5 * Math.round(0.76 * 4) + 2}`,
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

  test('the crease caption is true: none on the linear exam grid, all 12 on the 8 × 8 checkerboard, drawn on the image', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const cap = page.getByTestId('crease-caption');
    await expect(cap).toContainText('none of the 6 interior node lines');
    await expect(page.locator('.tx-crease')).toHaveCount(0);
    await page.getByTestId('show-checker').click();
    await expect(page).toHaveURL(/preset=checker/);
    await expect(cap).toContainText('all 12 of the 12 interior node lines are creases');
    await expect(page.locator('.tx-crease')).toHaveCount(12);
  });
});

test.describe('legible', () => {
  test('the nearest-node highlight does not cover the answer’s label, and every label has an opaque contrasting halo', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const info = await page.evaluate(() => {
      const hl = document.querySelector('[data-testid=nearest-highlight]')!.getBoundingClientRect();
      const labels = [...document.querySelectorAll<SVGTextElement>('[data-testid=node-label]')];
      const answer = labels.find((t) => t.textContent === '18')!;
      const r = answer.getBoundingClientRect();
      const top = document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2);
      const lum = (c: string) => {
        const m = c
          .match(/[\d.]+/g)!
          .slice(0, 3)
          .map(Number)
          .map((x) => x / 255)
          .map((s) => (s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4));
        return 0.2126 * m[0] + 0.7152 * m[1] + 0.0722 * m[2];
      };
      const ratios = labels.map((t) => {
        const cs = getComputedStyle(t);
        const a = lum(cs.fill);
        const b = lum(cs.stroke);
        return {
          ratio: (Math.max(a, b) + 0.05) / (Math.min(a, b) + 0.05),
          strokeOpacity: Number(cs.strokeOpacity),
          alpha: cs.stroke.startsWith('rgba') ? Number(cs.stroke.match(/[\d.]+/g)![3]) : 1,
        };
      });
      const overlap = !(r.right < hl.left || r.left > hl.right || r.bottom < hl.top || r.top > hl.bottom);
      return { overlap, topIsLabel: top === answer, ratios, n: labels.length };
    });
    expect(info.n).toBe(25);
    // the label sits where the highlight is drawn, and is painted above it
    expect(info.overlap).toBe(true);
    expect(info.topIsLabel).toBe(true);
    for (const r of info.ratios) {
      expect(r.ratio).toBeGreaterThanOrEqual(7);
      expect(r.strokeOpacity).toBe(1);
      expect(r.alpha).toBe(1);
    }
  });

  test('1280: no dropdown text and no table number is cut off', async ({ page }) => {
    await page.setViewportSize({ width: 1280, height: 900 });
    for (const q of ['', 'normalize=0&x=-3.3333&y=1.23456&z=2.5', 'preset=random&size=64']) {
      await openScene(page, `#/texture?${q}`);
      const bad = await page.evaluate(() => {
        const out: string[] = [];
        const ctx = document.createElement('canvas').getContext('2d')!;
        for (const s of document.querySelectorAll<HTMLSelectElement>('.scene-texture select')) {
          const cs = getComputedStyle(s);
          ctx.font = `${cs.fontWeight} ${cs.fontSize} ${cs.fontFamily}`;
          for (const o of s.options) {
            const need =
              ctx.measureText(o.text).width + parseFloat(cs.paddingLeft) + parseFloat(cs.paddingRight) + 20; // + the arrow
            if (need > s.clientWidth + 2)
              out.push(`select "${o.text}": ${need.toFixed(0)} > ${s.clientWidth}`);
          }
        }
        for (const c of document.querySelectorAll<HTMLElement>('.scene-texture td, .scene-texture th')) {
          if (c.scrollWidth > c.clientWidth + 1) out.push(`cell "${c.textContent}"`);
        }
        for (const t of document.querySelectorAll<HTMLElement>('.scene-texture table')) {
          const box = t.parentElement!;
          if (box.scrollWidth > box.clientWidth + 1) out.push(`table in ${box.className} scrolls sideways`);
        }
        return out;
      });
      expect(bad, q).toEqual([]);
    }
  });

  test('keyboard: the cell editor (arrows choose a node, Enter goes to its value) and the sphere point (angle sliders)', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    await page.getByTestId('edit-toggle').check();
    const grid = page.getByTestId('texel-grid');
    await grid.focus();
    // the selection starts at the nearest node (2, 1); one step right is (3, 1) = 19
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    const cell = page.getByTestId('cell-field');
    await expect(cell).toBeFocused();
    await expect(cell).toHaveValue(String(21 - 5 + 3));
    await cell.fill('119');
    await cell.press('Enter');
    // bilinear weight of node (3, 1) at (0.4, 0.24) is 0: the cell is [0.25, 0.5]; nearest is unchanged too
    await expect(page).toHaveURL(/grid=/);
    await page.keyboard.press('Escape');
    await grid.focus();
    await page.keyboard.press('ArrowLeft'); // (2, 1)
    await page.keyboard.press('Enter');
    await expect(cell).toBeFocused();
    await cell.fill('118');
    await cell.press('Enter');
    await waitForReadout(page, 'nearest', (x) => x === '118');

    // the sphere point from the keyboard: the azimuth slider moves it by 0.1°
    await openScene(page, '#/texture');
    const phi = page.getByTestId('phi-slider');
    await phi.focus();
    await page.keyboard.press('ArrowRight');
    await expect(page).toHaveURL(/x=/);
    const p = urlParams(page);
    const [x, y] = [Number(p.get('x')), Number(p.get('y'))];
    expect(Math.abs((Math.atan2(y, x) * 180) / Math.PI - 45.1)).toBeLessThan(0.01);
    await waitForReadout(
      page,
      'sphere-u',
      (s) => Math.abs(Number(s) - Math.atan2(y, x) / (2 * Math.PI)) < 1e-12,
    );
  });

  test('draggable handles show a visible focus indicator; the end handle moves with the arrow keys', async ({
    page,
  }) => {
    await openScene(page, '#/texture');
    const grid = page.getByTestId('texel-grid');
    await grid.focus();
    await page.keyboard.press('ArrowRight'); // keyboard modality: :focus-visible applies
    const ring = (sel: string) =>
      page.locator(sel).evaluate((el) => ({
        stroke: getComputedStyle(el).stroke,
        width: parseFloat(getComputedStyle(el).strokeWidth),
      }));
    const a = await ring('.tx-handle.a .tx-handle-focus');
    expect(a.stroke).not.toBe('none');
    expect(a.width).toBeGreaterThanOrEqual(4);
    await page.keyboard.press('Tab');
    const end = page.getByTestId('path-end-handle');
    await expect(end).toBeFocused();
    const b = await ring('[data-testid=path-end-handle] .tx-handle-focus');
    expect(b.stroke).not.toBe('none');
    expect(b.width).toBeGreaterThanOrEqual(4);
    await page.keyboard.press('ArrowLeft');
    await expect(page).toHaveURL(/u2=0\.84(&|$)/);
    // unfocused: no ring
    await page.getByTestId('u-slider').focus();
    expect((await ring('[data-testid=path-end-handle] .tx-handle-focus')).stroke).toBe('none');
  });

  test('375 px: SVG text ≥ 12 px, handles ≥ 24 px, the question’s inputs before its results', async ({
    page,
  }) => {
    await page.setViewportSize({ width: 375, height: 740 });
    for (const q of ['', 'preset=checker', 'present=1']) {
      await openScene(page, `#/texture?${q}`);
      const sizes = await page.evaluate(() => {
        const out: { text: string; px: number }[] = [];
        for (const svg of document.querySelectorAll<SVGSVGElement>('.scene-texture svg')) {
          const vb = svg.viewBox.baseVal;
          const scale = vb && vb.width ? svg.getBoundingClientRect().width / vb.width : 1;
          if (!svg.getBoundingClientRect().width) continue;
          for (const t of svg.querySelectorAll('text'))
            out.push({ text: t.textContent ?? '', px: parseFloat(getComputedStyle(t).fontSize) * scale });
        }
        return out;
      });
      expect(sizes.length).toBeGreaterThan(10);
      const small = sizes.filter((s) => s.px < 12);
      expect(small, q).toEqual([]);
      const hit = await page.locator('[data-testid=path-end-handle] .tx-handle-hit').boundingBox();
      expect(hit!.width).toBeGreaterThanOrEqual(24);
      const y = async (id: string) => (await page.getByTestId(id).boundingBox())!.y;
      if (q === 'present=1') {
        // classroom mode folds the inputs into the stage's Controls drawer: its button comes first
        expect(await y('controls-drawer-toggle')).toBeLessThan(await y('nearest'));
        expect(await y('controls-drawer-toggle')).toBeLessThan(await y('bilinear'));
        continue;
      }
      expect(await y('u-slider')).toBeLessThan(await y('nearest'));
      expect(await y('align-select')).toBeLessThan(await y('nearest'));
      expect(await y('wrap-select')).toBeLessThan(await y('bilinear'));
    }
    // a press 11 px from the end handle's centre grabs it (not the query)
    await openScene(page, '#/texture');
    await page.getByTestId('path-end-handle').scrollIntoViewIfNeeded();
    const h2 = (await page.getByTestId('path-end-handle').locator('.tx-handle-mark').boundingBox())!;
    await page.mouse.move(h2.x + h2.width / 2 + 11, h2.y + h2.height / 2);
    await page.mouse.down();
    await page.mouse.move(h2.x + h2.width / 2 - 30, h2.y + h2.height / 2 + 30, { steps: 4 });
    await page.mouse.up();
    await expect(page).toHaveURL(/u2=/);
    const p = urlParams(page);
    expect(p.get('u')).toBeNull(); // the query's start did not move
    expect(Number(p.get('u2'))).toBeLessThan(0.85);
  });
});

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

  test('step advances by one step (1/20 of the path); the plot marker follows', async ({ page }) => {
    await openScene(page, '#/texture?t=0.3');
    expect(await timelineT(page)).toBe(0.3);
    const x0 = Number(await page.getByTestId('path-plot-marker').locator('line').getAttribute('x1'));
    await page.getByTestId('timeline-step').click();
    await expect.poll(() => timelineT(page)).toBeCloseTo(0.35, 12);
    await expect(page).toHaveURL(/t=0\.35/);
    const f = frameAt(examGrid(), EXAM, DEFAULT_PATH, await timelineT(page));
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
    const x1 = Number(await page.getByTestId('path-plot-marker').locator('line').getAttribute('x1'));
    expect(x1).toBeGreaterThan(x0);
  });

  test('conventions and addressing toggle while it plays; the paused readouts use the new ones', async ({
    page,
  }) => {
    await openScene(page, '#/texture?u2=1.6&v2=0.3');
    await page.getByTestId('timeline-speed').selectOption('0.25');
    await page.getByTestId('timeline-play').click();
    await page.getByTestId('wrap-select').selectOption('repeat');
    await page.getByTestId('align-select').selectOption('center');
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
    await expect.poll(() => timelineT(page)).toBeGreaterThan(0.02);
    await page.getByTestId('timeline-play').click();
    const t = await timelineT(page);
    const opts: LookupOptions = { align: 'center', vflip: false, wrap: 'repeat' };
    const path = pathOf({ u: 0.4, v: 0.24, u2: 1.6, v2: 0.3, path: 'line' });
    const f = frameAt(examGrid(), opts, path, t);
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
    expect(Number(await readout(page, 'nearest'))).toBe(f.lookup.near.value);
    // the plot: repeat with texel centres is continuous (no jump) but kinks where the values wrap
    const prof = pathProfile(examGrid(), opts, path);
    await expect(page.getByTestId('path-plot')).toHaveAttribute('data-borders', String(prof.borders.length));
    await expect(page.getByTestId('path-plot')).toHaveAttribute(
      'data-jumps',
      String(prof.borders.filter((b) => b.jump).length),
    );
  });

  test('the circle preset and the path ends are in the link; the plot counts kinks (none on the exam grid, all on the checker)', async ({
    page,
  }) => {
    await openScene(page, '#/texture?path=circle&u2=0.6&v2=0.7&t=0.3');
    const path = pathOf({ u: 0.4, v: 0.24, u2: 0.6, v2: 0.7, path: 'circle' });
    const f = frameAt(examGrid(), EXAM, path, 0.3);
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
    expect(Number(await readout(page, 'nearest'))).toBe(f.lookup.near.value);
    await expect(page.getByTestId('path-select')).toHaveValue('circle');
    const plot = page.getByTestId('path-plot');
    await expect(plot).toHaveAttribute('data-kinks', '0');
    const pe = pathProfile(examGrid(), EXAM, path);
    await expect(plot).toHaveAttribute('data-borders', String(pe.borders.length));
    await expect(plot).toHaveAttribute('data-steps', String(pe.nearSwitches.length));
    await page.getByTestId('preset-select').selectOption('checker');
    const pc = pathProfile(checkerGrid(8, 8), EXAM, path);
    expect(pc.borders.filter((b) => b.kink).length).toBeGreaterThan(0);
    await expect(plot).toHaveAttribute('data-kinks', String(pc.borders.filter((b) => b.kink).length));
    // switching to the line keeps the ends
    await page.getByTestId('path-select').selectOption('line');
    await expect(page).not.toHaveURL(/path=/);
    await expect(page).toHaveURL(/u2=0\.6/);
  });

  test('dragging the end handle moves the path’s end and keeps the position; clicking elsewhere rewinds to the clicked query', async ({
    page,
  }) => {
    await openScene(page, '#/texture?t=0.5');
    const h = (await page.getByTestId('path-end-handle').locator('.tx-handle-mark').boundingBox())!;
    await page.mouse.move(h.x + h.width / 2, h.y + h.height / 2);
    await page.mouse.down();
    await page.mouse.move(h.x + h.width / 2 + 40, h.y + h.height / 2 + 40, { steps: 4 });
    await page.mouse.up();
    await expect(page).toHaveURL(/u2=/);
    const p = urlParams(page);
    expect(Number(p.get('t'))).toBe(0.5);
    const path = pathOf({ u: 0.4, v: 0.24, u2: Number(p.get('u2')), v2: Number(p.get('v2')), path: 'line' });
    const f = frameAt(examGrid(), EXAM, path, 0.5);
    await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
    // a click away from both handles: the query goes there, at t = 0
    const g = (await page.getByTestId('texel-grid').boundingBox())!;
    await page.mouse.click(g.x + g.width * 0.2, g.y + g.height * 0.2);
    await expect.poll(() => timelineT(page)).toBe(0);
    const q = urlParams(page);
    expect(q.get('t')).toBeNull();
    await waitForReadout(
      page,
      'bilinear',
      (x) => Math.abs(Number(x) - L(Number(q.get('u')), Number(q.get('v')))) < 1e-9,
    );
  });
});

test.describe('the derivation and the answer under it agree while it plays', () => {
  /** The result each part's derivation prints (from its TeX) and the answer under it, read at one moment. */
  async function resultsNow(page: Page) {
    return page.evaluate(() => {
      const tex = (id: string) =>
        document.querySelector(`[data-testid=derivation-${id}] annotation[encoding="application/x-tex"]`)
          ?.textContent ?? null;
      const out = (id: string) => document.querySelector(`[data-testid=${id}]`)?.textContent ?? null;
      const t = document.querySelector('[data-testid=timeline]')?.getAttribute('data-t') ?? null;
      return { a: tex('3a'), b: tex('3b'), nearest: out('nearest'), bilinear: out('bilinear'), t };
    });
  }
  /** The last value of the bilinear steps (c = …) and the value of the nearest node (T_{i,j} = …). */
  const bilinearResult = (tex: string) => /&= ([-0-9.]+)\s*\\end\{aligned\}\s*$/.exec(tex)?.[1];
  const nearestResult = (tex: string) => /T_\{\d+,\d+\} &= ([-0-9.]+)/.exec(tex)?.[1];

  async function expectAgree(page: Page) {
    const r = await resultsNow(page);
    expect(r.a && r.b, 'both derivations are typeset').toBeTruthy();
    expect(nearestResult(r.a!), `(a) at t = ${r.t}`).toBe(r.nearest);
    expect(bilinearResult(r.b!), `(b) at t = ${r.t}`).toBe(r.bilinear);
    return r;
  }
  const typeset = async (page: Page) => {
    for (const id of ['3a', '3b'])
      await expect(page.getByTestId(`derivation-${id}`).locator('.math-pending')).toHaveCount(0);
  };

  test('sampled while playing, and paused at several t: the steps end in the answer shown under them', async ({
    page,
  }) => {
    test.setTimeout(180_000);
    await openScene(page, '#/texture');
    // the grid stays in view (the timeline runs only while its figure is on screen); the steps
    // below are typeset all the same
    await page.getByTestId('texel-grid').scrollIntoViewIfNeeded();
    await typeset(page);
    const first = await expectAgree(page);
    expect(Number(first.bilinear)).toBeCloseTo(L(0.4, 0.24), 9);
    await page.getByTestId('timeline-speed').selectOption('0.5');
    // while it plays: every sample agrees, and the steps do move with the point
    await page.getByTestId('timeline-play').click();
    const seen = new Set<string>();
    const disagree: string[] = [];
    let samples = 0;
    await expect
      .poll(
        async () => {
          const r = await resultsNow(page);
          if (r.a && r.b) {
            // (not typeset yet: the first formula of the page)
            samples++;
            if (nearestResult(r.a) !== r.nearest) disagree.push(`(a) at t ≈ ${r.t}: ${r.a} vs ${r.nearest}`);
            if (bilinearResult(r.b) !== r.bilinear)
              disagree.push(`(b) at t ≈ ${r.t}: ${r.b} vs ${r.bilinear}`);
            seen.add(r.bilinear!);
          }
          return seen.size;
        },
        { timeout: 30_000, intervals: [150] },
      )
      .toBeGreaterThan(4);
    expect(disagree).toEqual([]);
    expect(samples).toBeGreaterThan(4);
    await page.getByTestId('timeline-play').click();
    await page.getByTestId('timeline-speed').selectOption('1');
    // paused at several positions: the steps, the answer and the model at the paused t agree
    for (const after of [0.3, 0.7]) {
      await page.getByTestId('timeline-play').click();
      await expect.poll(() => timelineT(page), { timeout: 30_000 }).toBeGreaterThan(after);
      await page.getByTestId('timeline-play').click();
      await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
      const t = await timelineT(page);
      const f = frameAt(examGrid(), EXAM, DEFAULT_PATH, t);
      await waitForReadout(page, 'bilinear', (x) => Math.abs(Number(x) - f.lookup.bil.value) < 1e-12);
      await typeset(page);
      const r = await expectAgree(page);
      expect(Number(r.bilinear)).toBeCloseTo(f.lookup.bil.value, 4);
      expect(Number(r.nearest)).toBe(f.lookup.near.value);
      // the key's note names the point it computes at, not the exam's
      await expect(page.getByTestId('keynote-3a')).toContainText(`at t = ${p4(t)}`);
      await expect(page.getByTestId('keynote-3a')).toContainText('at the exam’s point (0.4, 0.24) the key');
      await expect(page.getByTestId('not-exam-query').first()).toContainText(`at t = ${p4(t)}`);
    }
  });
});

/** As the page prints a short number (4 significant digits). */
const p4 = (x: number) => String(Number(x.toPrecision(4)));
