// #/ray-sphere in the browser: every case, the precision presets (robust roots against references
// computed here with mathjs BigNumber), bad input, typing and dragging.
import { create, all, type BigNumber } from 'mathjs';
import AxeBuilder from '@axe-core/playwright';
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';

type V = [number, number, number];
const M = create(all, { number: 'BigNumber', precision: 300 });

/** The exact value of a double as a BigNumber. */
function big(x: number): BigNumber {
  if (x === 0) return M.bignumber(0);
  const v = new DataView(new ArrayBuffer(8));
  v.setFloat64(0, x);
  const bits = v.getBigUint64(0);
  const eb = Number((bits >> 52n) & 0x7ffn);
  let m = bits & 0xfffffffffffffn;
  let e = -1074;
  if (eb !== 0) {
    m |= 1n << 52n;
    e = eb - 1075;
  }
  const a = M.bignumber(m.toString()).times(M.bignumber(2).pow(e)) as BigNumber;
  return bits >> 63n ? (a.neg() as BigNumber) : a;
}

/** Exact roots of |o + t d − c|² = r² (inputs as exact doubles), rounded to doubles at the end. */
function exact(o: V, d: V, c: V, r: number) {
  const f = o.map((x, i) => big(x).minus(big(c[i])) as BigNumber);
  const D = d.map(big);
  const dot = (x: BigNumber[], y: BigNumber[]) =>
    x[0].times(y[0]).plus(x[1].times(y[1])).plus(x[2].times(y[2])) as BigNumber;
  const a = dot(D, D);
  const beta = dot(f, D);
  const cc = dot(f, f).minus(big(r).times(big(r))) as BigNumber;
  const q = beta.times(beta).minus(a.times(cc)) as BigNumber;
  if (q.isNegative()) return { sign: -1, t0: null, t1: null, hit: null };
  const s = q.sqrt();
  const t0 = Number(beta.neg().minus(s).div(a));
  const t1 = Number(beta.neg().plus(s).div(a));
  return { sign: q.isZero() ? 0 : 1, t0, t1, hit: t0 >= 0 ? t0 : t1 >= 0 ? t1 : null };
}

const q = (o: V, d: V, c: V, r: number, method = 'stable') =>
  `#/ray-sphere?o=${o.join(',')}&d=${d.join(',')}&c=${c.join(',')}&r=${r}&method=${method}`;

function close(actual: number, expected: number, rel = 1e-13) {
  expect(Math.abs(actual - expected), `${actual} vs ${expected}`).toBeLessThanOrEqual(
    rel * Math.abs(expected) + 1e-300,
  );
}

const CASES: { name: string; o: V; d: V; c: V; r: number }[] = [
  { name: 'two-hits', o: [-3, 0.3, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  { name: 'miss', o: [-3, 1.5, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  { name: 'tangent', o: [-5, 1, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  { name: 'inside', o: [0.2, -0.3, 0.1], d: [1, 0.5, 0], c: [0, 0, 0], r: 1 },
  { name: 'behind', o: [3, 0.3, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  { name: 'two-hits', o: [1, 2, 3], d: [0.3, -0.7, -2], c: [1.5, 1, -2], r: 1.7 },
];

test.describe('every case, by URL', () => {
  for (const k of CASES) {
    for (const method of ['stable', 'naive']) {
      test(`${k.name} o=${k.o} (${method})`, async ({ page }) => {
        await openScene(page, q(k.o, k.d, k.c, k.r, method));
        const ex = exact(k.o, k.d, k.c, k.r);
        expect(await readout(page, 'case')).toBe(k.name);
        // textbook coefficients
        const f = k.o.map((x, i) => x - k.c[i]);
        expect(await readoutNumber(page, 'a')).toBe(k.d[0] ** 2 + k.d[1] ** 2 + k.d[2] ** 2);
        close(await readoutNumber(page, 'b'), 2 * (f[0] * k.d[0] + f[1] * k.d[1] + f[2] * k.d[2]));
        close(await readoutNumber(page, 'c'), f[0] ** 2 + f[1] ** 2 + f[2] ** 2 - k.r * k.r);
        const disc = await readoutNumber(page, 'discriminant');
        expect(Math.sign(disc)).toBe(ex.sign);
        if (ex.t0 === null) {
          expect(await readout(page, 't0')).toBe('none');
          expect(await readout(page, 't1')).toBe('none');
          expect(await readout(page, 't-hit')).toBe('none');
        } else {
          close(await readoutNumber(page, 't0'), ex.t0, 1e-14);
          close(await readoutNumber(page, 't1'), ex.t1!, 1e-14);
          if (ex.hit === null) expect(await readout(page, 't-hit')).toBe('none');
          else close(await readoutNumber(page, 't-hit'), ex.hit, 1e-14);
        }
        await expect(page.getByTestId('case-banner')).toContainText(/Δ/);
      });
    }
  }

  test('case preset buttons set the URL and the readouts', async ({ page }) => {
    await openScene(page, '#/ray-sphere');
    for (const name of ['miss', 'tangent', 'inside', 'behind', 'two-hits']) {
      await page.getByTestId(`preset-${name}`).click();
      await waitForReadout(page, 'case', (v) => v === name);
      await expect(page).toHaveURL(/o=/);
    }
  });
});

test.describe('precision presets: robust roots match high-precision references', () => {
  const P: { id: string; o: V; d: V; c: V; r: number; textbookCase?: string }[] = [
    { id: 'far', o: [0, 0, 0], d: [1, 5e-9, 0], c: [1e8, 0, 0], r: 1, textbookCase: 'tangent' },
    { id: 'grazing', o: [-1e5, 0.99999, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
    {
      id: 'ulp-past',
      o: [-5, 1.0000000000000002, 0],
      d: [1, 0, 0],
      c: [0, 0, 0],
      r: 1,
      textbookCase: 'tangent',
    },
    {
      id: 'ulp-inside',
      o: [-5, 0.9999999999999999, 0],
      d: [1, 0, 0],
      c: [0, 0, 0],
      r: 1,
      textbookCase: 'tangent',
    },
  ];
  for (const p of P) {
    test(`${p.id}: robust readouts equal the exact roots to ~1 ulp; the textbook column is wrong`, async ({
      page,
    }) => {
      await openScene(page, '#/ray-sphere');
      await page.getByTestId(`preset-${p.id}`).click();
      const ex = exact(p.o, p.d, p.c, p.r);
      const wantCase = ex.sign < 0 ? 'miss' : ex.sign === 0 ? 'tangent' : ex.t0! >= 0 ? 'two-hits' : 'inside';
      await waitForReadout(page, 'case', (v) => v === wantCase);
      if (ex.t0 === null) {
        expect(await readout(page, 't-hit')).toBe('none');
      } else {
        close(await readoutNumber(page, 't0'), ex.t0, 4e-16);
        close(await readoutNumber(page, 't1'), ex.t1!, 4e-16);
        close(await readoutNumber(page, 't-hit'), ex.hit!, 4e-16);
        // the page's double-double reference column agrees too
        close(Number(await page.getByTestId('ref-t0').getAttribute('data-value')), ex.t0, 4e-16);
      }
      await expect(page.getByTestId('stable-case')).toHaveAttribute('data-value', wantCase);
      await expect(page.getByTestId('ref-case')).toHaveAttribute('data-value', wantCase);
      if (p.textbookCase)
        await expect(page.getByTestId('naive-case')).toHaveAttribute('data-value', p.textbookCase);
      else {
        // grazing: textbook case right but its t₀ is off by far more than the robust one's
        const tb = Number(await page.getByTestId('naive-t0').getAttribute('data-value'));
        expect(Math.abs(tb - ex.t0!) / ex.t0!).toBeGreaterThan(1e-10);
      }
      // switching the readouts to the textbook method shows its (wrong) answer
      await page.getByTestId('method').selectOption('naive');
      if (p.textbookCase) {
        await waitForReadout(page, 'case', (v) => v === p.textbookCase);
        await expect(page.getByTestId('method-wrong')).toContainText(wantCase);
      }
      await expect(page).toHaveURL(/method=naive/);
    });
  }

  test('the distant-sphere images: holes at 10^7.5, none up close', async ({ page }) => {
    await openScene(page, '#/ray-sphere');
    const summary = page.getByTestId('distant-summary');
    await summary.scrollIntoViewIfNeeded();
    // (computed once the panel is in view)
    await expect(summary).toHaveAttribute('data-disagree', /^\d+$/, { timeout: 30_000 });
    expect(Number(await summary.getAttribute('data-disagree'))).toBeGreaterThan(50);
    const box = page.getByTestId('distant-exp').locator('xpath=..').getByRole('textbox');
    await box.fill('2');
    await box.press('Enter');
    await expect(summary).toHaveAttribute('data-disagree', '0');
    expect(await page.getByTestId('img-naive').getAttribute('data-hits')).toBe(
      await page.getByTestId('img-stable').getAttribute('data-hits'),
    );
  });
});

test.describe('bad input: clear message, safe fallback', () => {
  test('zero direction', async ({ page }) => {
    await openScene(page, '#/ray-sphere?d=0,0,0');
    await expect(page.getByTestId('input-problems')).toContainText('points nowhere');
    expect(['two-hits', 'miss', 'inside', 'behind', 'tangent']).toContain(await readout(page, 'case'));
    await readoutNumber(page, 'a'); // finite: the fallback direction is used
  });
  test('negative and zero radius', async ({ page }) => {
    await openScene(page, `${q([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], -2)}`);
    await expect(page.getByTestId('input-problems')).toContainText('negative radius');
    const ex = exact([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 2);
    close(await readoutNumber(page, 't0'), ex.t0!, 1e-14);
    await openScene(page, `${q([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 0)}`);
    await expect(page.getByTestId('input-problems')).toContainText('radius of 0');
    await expect(page.getByRole('alert').first()).toBeVisible();
  });
  test('non-finite and malformed numbers in the URL', async ({ page }) => {
    await openScene(page, '#/ray-sphere?o=NaN,0,0&r=Infinity&c=1,2&method=weird');
    const notice = page.getByTestId('param-notice');
    await expect(notice).toContainText('o');
    await expect(notice).toContainText('r');
    await expect(notice).toContainText('method');
    expect(await readout(page, 'case')).not.toBe('none');
  });
  test('a direction too short to square', async ({ page }) => {
    await openScene(page, '#/ray-sphere?d=1e-200,0,0');
    await expect(page.getByTestId('input-problems')).toContainText('too short');
  });
  test('out-of-range coordinates are clamped with a notice naming the parameter', async ({ page }) => {
    await openScene(page, '#/ray-sphere?o=-1e13,0.5,0&d=1,0,0');
    await expect(page.getByTestId('param-notice')).toContainText('o');
    expect(await readout(page, 'case')).toBe('two-hits');
    close(await readoutNumber(page, 't-hit'), exact([-1e12, 0.5, 0], [1, 0, 0], [0, 0, 0], 1).hit!, 1e-15);
  });
  test('typing a bad value in a field is flagged and does not reach the model', async ({ page }) => {
    await openScene(page, '#/ray-sphere');
    const before = await readout(page, 't0');
    const r = page.getByTestId('input-r');
    await r.fill('abc');
    await r.press('Enter');
    await expect(page.getByText('Enter a finite number')).toBeVisible();
    expect(await readout(page, 't0')).toBe(before);
    await r.fill('0.5');
    await r.press('Enter');
    await waitForReadout(page, 't0', (v) => v !== before);
  });
});

test.describe('interaction', () => {
  test('dragging the origin handle moves the ray smoothly and updates the URL', async ({ page }) => {
    await openScene(page, '#/ray-sphere?o=-3,0.3,0&d=1,0,0');
    const h = page.getByTestId('handle-o');
    const b = (await h.boundingBox())!;
    const x = b.x + b.width / 2;
    const y = b.y + b.height / 2;
    // record frame intervals in the page while dragging
    await page.evaluate(() => {
      const w = window as unknown as { __frames: number[]; __stop: boolean };
      w.__frames = [];
      w.__stop = false;
      const loop = (t: number) => {
        w.__frames.push(t);
        if (!w.__stop) requestAnimationFrame(loop);
      };
      requestAnimationFrame(loop);
    });
    await page.mouse.move(x, y);
    await page.mouse.down();
    const t = Date.now();
    const steps = 40;
    for (let i = 1; i <= steps; i++) await page.mouse.move(x, y - i * 2);
    const ms = (Date.now() - t) / steps;
    await page.mouse.up();
    const frames = await page.evaluate(() => {
      const w = window as unknown as { __frames: number[]; __stop: boolean };
      w.__stop = true;
      return w.__frames;
    });
    const gaps = frames
      .slice(1)
      .map((f, i) => f - frames[i])
      .sort((a, b) => a - b);
    const median = gaps[gaps.length >> 1];
    const p90 = gaps[Math.floor(gaps.length * 0.9)];
    console.log(
      `drag: ${ms.toFixed(1)} ms per pointer move incl. Playwright round trip; frames: median ${median.toFixed(1)} ms, p90 ${p90.toFixed(1)} ms over ${gaps.length}`,
    );
    await expect(page).toHaveURL(/o=-3,0\.[4-9]|o=-3,1/);
    expect(['miss', 'two-hits']).toContain(await readout(page, 'case'));
    // generous bound: the CI box is shared; on an idle laptop this is ~16 ms
    expect(median).toBeLessThan(60);
  });
  test('the direction handle rotates the ray; keyboard arrows move a handle', async ({ page }) => {
    await openScene(page, '#/ray-sphere?o=-3,0,0&d=1,0,0');
    expect(await readout(page, 'case')).toBe('two-hits');
    const h = page.getByTestId('handle-tip');
    const b = (await h.boundingBox())!;
    await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2);
    await page.mouse.down();
    await page.mouse.move(b.x + b.width / 2, b.y - 140, { steps: 8 });
    await page.mouse.up();
    await waitForReadout(page, 'case', (v) => v === 'miss');
    const c = page.getByTestId('handle-c');
    await c.focus();
    const before = await readout(page, 'b');
    await page.keyboard.press('ArrowRight');
    await waitForReadout(page, 'b', (v) => v !== before);
  });
  test('typing a vector component updates the readouts', async ({ page }) => {
    await openScene(page, '#/ray-sphere?o=-3,0,0&d=1,0,0');
    const f = page.getByTestId('input-o-y');
    await f.fill('2');
    await f.press('Enter');
    await waitForReadout(page, 'case', (v) => v === 'miss');
    await expect(page).toHaveURL(/o=-3,2,0/);
  });
});

test('axe finds no serious or critical violations (light, dark, present, far preset)', async ({ page }) => {
  test.setTimeout(240_000); // four full-page scans on a busy shared machine
  for (const qs of [
    'theme=light',
    'theme=dark',
    'present=1&o=0,0,0&d=1,5e-9,0&c=100000000,0,0&r=1',
    'd=0,0,0&r=-1',
  ]) {
    await openScene(page, `#/ray-sphere?${qs}`);
    await page.getByTestId('view-3d').scrollIntoViewIfNeeded();
    await expect(page.getByTestId('view-3d')).toHaveAttribute('data-status', /ready|no-webgl/);
    await page.getByTestId('error-plot').scrollIntoViewIfNeeded();
    // The shared Plot component (src/ui/Plot.tsx, not this scene's) wraps Plotly's focusable
    // modebar in an aria-hidden div; reported to its owner, and excluded here so this test checks
    // what this scene renders.
    const results = await new AxeBuilder({ page }).exclude('.plot-canvas').analyze();
    const bad = results.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical');
    expect(
      bad.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`),
      qs,
    ).toEqual([]);
  }
});
