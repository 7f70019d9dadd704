/**
 * Browser tests of #/monte-carlo (exam Q2, Q4): the wiring (the worked table of the exam's four
 * samples, each part's derivation with live numbers, typed integrands and pdfs, bad ones, the
 * zero-variance note), long runs in the worker (finish, cancel), the race's histograms while it
 * plays and steps, and for a reader who cannot see it: the race's description read from
 * Chromium's accessibility tree, and a keyboard-only run reading Q4's answers from the tree.
 * Every expected value is computed here from the formula (f(x) = (x + 2)², p = 1/(b − a),
 * p = 3(x + 2)²/((b + 2)³ − (a + 2)³), ∫ eˣ dx = eᵇ − eᵃ) or from the scene's model (drawnEstimate,
 * raceTrack / raceAt), never pasted from the answer key or from the app.
 *
 * Elsewhere: the parts in exam order, the shared timeline (play, pause, the link restores t), the
 * lecture room and the whole-page checks in catalogue.spec.ts; the storm of changes at 10⁶ samples
 * in storm.spec.ts; each pdf message in tests/scenes/monte-carlo/model.test.ts; the description's
 * wording in tests/scenes/monte-carlo/describe.test.ts.
 */
import type { Page } from '@playwright/test';
import { test, expect, followLinkAnew, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { axNodeOf, axTree } from './axTree';
import { drawnEstimate } from '../../src/scenes/monte-carlo/drawnEstimate';
import { raceAt, raceTrack } from '../../src/scenes/monte-carlo/race';
import { squarePdf1D, uniformPdf1D } from '../../src/core/sampling/pdf1d';
import { compileXFast } from '../../src/scenes/monte-carlo/expr';

const EXAM_X = [1.16, 1.98, 0.54, 1.26];
const f = (x: number) => (x + 2) ** 2;
const cube = (x: number) => x * x * x;
const exactSquare = (a: number, b: number) => (cube(b + 2) - cube(a + 2)) / 3;
const I = exactSquare(0, 2);
const close = (got: number, want: number, tol: number) =>
  expect(Math.abs(got - want), `${got} ≈ ${want} (±${tol})`).toBeLessThanOrEqual(tol);

/** The race as the model computes it, for the exam's f on [0, 2], p ∝ f, seed s. */
const examTrack = (seed: number) => raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, seed);

async function raceReadouts(page: Page) {
  const out: Record<string, string> = {};
  for (const lane of ['uniform', 'importance'])
    for (const k of ['x', 'term', 'estimate', 'stderr'])
      out[`${lane}-${k}`] = await readout(page, `race-${lane}-${k}`);
  return out;
}
function expectFrame(r: Record<string, string>, fr: ReturnType<typeof raceAt>) {
  close(Number(r['uniform-x']), fr.uniform.x, 1e-12);
  close(Number(r['uniform-term']), fr.uniform.term, 1e-10);
  close(Number(r['uniform-estimate']), fr.uniform.estimate, 1e-10);
  close(Number(r['uniform-stderr']), fr.uniform.stderr, 1e-10);
  close(Number(r['importance-x']), fr.importance.x, 1e-12);
  close(Number(r['importance-estimate']), fr.importance.estimate, 1e-10);
}

test('wiring: the exam’s Q4 part by part, typed integrands and pdfs, bad ones, the zero-variance note, cancelling a long run', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/monte-carlo');
  await test.step('(a), (b): the worked table of the exam’s four samples, 56/3, the key’s differing figures', async () => {
    close(await readoutNumber(page, 'exact'), I, 1e-13);
    for (const [i, x] of EXAM_X.entries()) {
      close(await readoutNumber(page, `f-${i}`), f(x), 1e-12);
      close(await readoutNumber(page, `p-${i}`), 1 / 2, 0);
    }
    const uniform = (2 / 4) * EXAM_X.reduce((s, x) => s + f(x), 0);
    close(await readoutNumber(page, 'q4-uniform'), uniform, 1e-12);
    close(await readoutNumber(page, 'q4-importance'), I, 1e-12);
    // the key prints 18.84 for f(1.98); the page says the computed value differs
    const notes = page.getByTestId('key-notes');
    await expect(notes).toContainText(String(f(1.98)));
    await expect(notes).toContainText('18.84');
    await expect(notes).toContainText('slip');
    // (a): expansion, antiderivative, the evaluation F(2) = 8/3 + 8 + 8
    const a = page.getByTestId('derivation-4a');
    await expect(a).toContainText('4x');
    await expect(a).toContainText(String((8 / 3).toPrecision(6)));
    await expect(a).toContainText('56');
    // (b): every f(xᵢ) and the average; the headline is the exam's answer, computed; the key's Σ from i = 0
    const b = page.getByTestId('derivation-4b');
    for (const x of EXAM_X) await expect(b).toContainText(String(Number(f(x).toPrecision(6))));
    await expect(page.getByTestId('answer-4b')).toContainText(uniform.toFixed(2));
    await expect(page.getByTestId('key-sum-4b')).toContainText('i = 1 to 4');
    await expect(page.getByTestId('key-sum-4c')).toBeVisible();
  });

  await test.step('(c), (d): p ∝ f gives every term = I; the errors after the whole race are the model’s', async () => {
    // p(x) = 3(x + 2)²/56 stated in the default (uniform) configuration
    await expect(page.getByTestId('pdf-4c')).toContainText(String(cube(4) - cube(2)));
    await expect(page.getByTestId('derivation-4c')).toContainText(I.toFixed(10).slice(0, 12));
    const end = raceAt(examTrack(1), 8192);
    close(await readoutNumber(page, 'q4d-uniform-error'), end.uniform.absError, 1e-10);
    expect(await readoutNumber(page, 'q4d-importance-error')).toBeLessThan(1e-12);
    await expect(page.getByTestId('answer-4d')).toContainText('(c) converges faster');
  });

  await test.step('the race at its opening position: the model’s frame; a zero spread says “zero variance”', async () => {
    const t = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    expect(t).toBeGreaterThan(0);
    expectFrame(await raceReadouts(page), raceAt(examTrack(1), t));
    await expect(page.getByTestId('race-importance-stderr')).toHaveText(/zero variance/);
    expect(await readoutNumber(page, 'race-importance-stderr')).toBeLessThan(1e-12);
    await expect(page.getByTestId('race-uniform-stderr')).not.toHaveText(/zero variance/);
  });

  await test.step('no samples given: the estimate from N drawn samples is the model’s, within 5 standard errors', async () => {
    const est = Number(await waitForReadout(page, 'estimate', (v) => v !== 'none'));
    const se = await readoutNumber(page, 'stderr');
    expect(se).toBeGreaterThan(0);
    close(est, I, 5 * se);
    // exactly the model's estimate with these settings (N = 10000 i.i.d. uniform points, seed 1)
    const want = drawnEstimate(compileXFast('(x+2)^2')!.fn, uniformPdf1D(0, 2), 'independent', 1, 10000);
    expect(est).toBe(want.estimate);
    expect(se).toBe(want.stderr);
  });

  await test.step('beyond the exam, folded: opening writes open= into the link, and the link opens it again', async () => {
    const fold = page.getByTestId('fold-race-data');
    await expect(fold).not.toHaveAttribute('open');
    await expect(fold.getByTestId('race-table')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(fold.getByTestId('race-table')).toBeVisible();
    await expect(fold.getByTestId('trace-uniform-estimate')).toBeVisible();
    await expect(page).toHaveURL(/[?&]open=race-data(&|$)/);
    await followLinkAnew(page);
    await expect(page.getByTestId('fold-race-data')).toHaveAttribute('open');
    await expect(page.getByTestId('race-table')).toBeVisible({ timeout: 30_000 });
  });

  await test.step('exp(x) on [−1, 1.5]: exact by quadrature, given samples, a custom pdf ∝ eˣ', async () => {
    const [a, b] = [-1, 1.5];
    const J = Math.exp(b) - Math.exp(a);
    // drawn from the tabulated custom pdf: nearly zero variance, unbiased
    await page.goto(`./#/monte-carlo?f=exp(x)&a=${a}&b=${b}&pdf=custom&pdfexpr=exp(x)&n=20000`);
    const est = Number(await waitForReadout(page, 'estimate', (v) => Math.abs(Number(v) - J) < 1e-2));
    const se = await readoutNumber(page, 'stderr');
    expect(se).toBeLessThan(1e-3);
    close(est, J, 5 * se + 1e-12);
    close(await readoutNumber(page, 'exact'), J, 1e-13);

    // two given samples, uniform pdf
    const uniform = ((Math.exp(0.3) + Math.exp(-0.5)) / 2) * (b - a);
    await page.goto(`./#/monte-carlo?f=exp(x)&a=${a}&b=${b}&samples=0.3,-0.5`);
    await waitForReadout(page, 'estimate', (v) => Math.abs(Number(v) - uniform) < 1e-12);
    close(await readoutNumber(page, 'f-0'), Math.exp(0.3), 1e-14);
    close(await readoutNumber(page, 'p-1'), 1 / (b - a), 1e-15);
    await expect(page.getByText(/Gauss–Kronrod/).first()).toBeVisible();

    // the same samples with the custom pdf ∝ eˣ: every term is the integral
    await page.goto(`./#/monte-carlo?f=exp(x)&a=${a}&b=${b}&pdf=custom&pdfexpr=exp(x)&samples=0.3,-0.5`);
    await waitForReadout(page, 'p-0', (v) => Math.abs(Number(v) - Math.exp(0.3) / J) < 1e-12);
    close(await readoutNumber(page, 'estimate'), J, 1e-11);
  });

  // one pdf that is wrong as a density and one that does not parse (each kind of message is a
  // unit test of the model: tests/scenes/monte-carlo/model.test.ts)
  await test.step('bad pdfs: a clear message and no estimate; a bad f falls back; a > b is refused', async () => {
    const cases: [string, RegExp][] = [
      ['x-1', /negative/],
      ['x+', /syntax|character|not valid/i],
    ];
    for (const [expr, msg] of cases) {
      await page.goto(`./#/monte-carlo?pdf=custom&pdfexpr=${encodeURIComponent(expr)}`);
      await expect(page.getByTestId('pdf-error')).toContainText(msg);
      await waitForReadout(page, 'estimate', (v) => v === 'none');
      expect(await readout(page, 'p-0')).toBe('none');
      // the exact integral and f stay available
      close(await readoutNumber(page, 'exact'), I, 1e-13);
    }
    await page.goto('./#/monte-carlo?f=y%2B1');
    await expect(page.getByText(/using \(x\+2\)\^2/)).toBeVisible();
    close(await readoutNumber(page, 'exact'), I, 1e-13);
    await page.goto('./#/monte-carlo?a=3&b=1');
    await expect(page.getByText(/must satisfy a < b/)).toBeVisible();
  });

  await test.step('the page’s own estimate with p ∝ f: exact, “zero variance”; the convergence plot notes the exact strategy', async () => {
    await page.goto('./#/monte-carlo?pdf=proportional&n=2000&open=convergence');
    const est = Number(await waitForReadout(page, 'estimate', (v) => Math.abs(Number(v) - I) < 1e-10));
    close(est, I, 1e-10);
    await expect(page.getByTestId('stderr').locator('..')).toContainText('zero variance');
    await page.getByRole('heading', { name: /Convergence as N grows/ }).scrollIntoViewIfNeeded();
    await expect(page.getByTestId('exact-strategies')).toContainText('p ∝ f', { timeout: 45000 });
    await expect(page.locator('.mc-plots svg.chart').first()).toBeVisible();
    // a ramp that only approximates f: a real spread
    await page.goto('./#/monte-carlo?pdf=linear&n=2000');
    await waitForReadout(page, 'estimate', (v) => v !== 'none' && Math.abs(Number(v) - I) > 1e-10);
    await expect(page.getByTestId('stderr').locator('..')).not.toContainText('zero variance');
    await expect(page.getByTestId('race-importance-stderr')).not.toHaveText(/zero variance/);
  });

  // a run of 10⁷ samples in the worker (a long run finishing there is storm.spec.ts's, at 10⁶)
  await test.step('cancel: a 10⁷-sample run stops, no estimate, and the page stays responsive', async () => {
    // a slow-ish integrand and sequence, so that the run is still going when we cancel it
    const g = encodeURIComponent('sin(x)^2 + cos(3*x)*exp(-x) + sqrt(x+1) + log(x+2) + atan(x)^3');
    await page.goto(`./#/monte-carlo?n=10000000&strategy=halton&pdf=linear&f=${g}`);
    await expect(page.getByText(/Estimating with 10,000,000 samples/)).toBeVisible();
    // dispatchEvent: the progress text re-renders every frame, so do not wait for a "stable" box
    await page.locator('.mc-progress button', { hasText: 'Cancel' }).dispatchEvent('click');
    await expect(page.getByText(/Estimating with 10,000,000 samples/)).toHaveCount(0);
    expect(await readout(page, 'estimate')).toBe('none');
    // still responsive: a control change goes through at once
    await page.getByTestId('pdf-select').selectOption('proportional');
    await expect(page).toHaveURL(/pdf=proportional/);
  });
});

// ---------------------------------------------------------------------------------------------
// The race accumulates what it claims: histograms of every sample drawn so far
// ---------------------------------------------------------------------------------------------

/** Counts of the first t samples in `bins` equal bins over [0, 2], binned here from the model's samples. */
function binned(xs: Float64Array, t: number, bins: number): number[] {
  const c = new Array<number>(bins).fill(0);
  for (let i = 0; i < t; i++) c[Math.min(bins - 1, Math.floor((xs[i] / 2) * bins))]++;
  return c;
}

/** Both histograms' counts and the samples they count, read in one go (one frame's state). */
async function histograms(page: Page) {
  return page.evaluate(() =>
    (['uniform', 'importance'] as const).map((id) => {
      const el = document.querySelector(`[data-testid="race-hist-${id}"]`)!;
      return {
        t: Number(el.getAttribute('data-t')),
        counts: (el.getAttribute('data-counts') ?? '').split(',').map(Number),
      };
    }),
  );
}

const RACE = '[data-testid="race-figure"]';

const description = async (page: Page, sel = RACE) => (await axNodeOf(page, sel))?.description ?? '';

/** The uniform lane's "estimate ± error" as the description writes it, checked against the model. */
function expectUniform(desc: string, t: number, seed: number) {
  const fr = raceAt(examTrack(seed), t, []);
  const m = /uniform estimate (\d+\.?\d*) ± (\d+\.?\d*)/.exec(desc);
  expect(m, desc).not.toBeNull();
  const [est, se] = [Number(m![1]), Number(m![2])];
  // written to the error's first digit (two from a leading 1): within half a unit of that digit
  const e = Math.floor(Math.log10(fr.uniform.stderr));
  const unit = 10 ** (fr.uniform.stderr / 10 ** e < 2 ? e - 1 : e);
  expect(Math.abs(est - fr.uniform.estimate)).toBeLessThanOrEqual(unit / 2 + 1e-12);
  expect(Math.abs(se - fr.uniform.stderr)).toBeLessThanOrEqual(unit / 2 + 1e-12);
}

test('the race: its description with live numbers, a new seed; the histograms count every sample drawn so far, paused, playing, stepped and reset; a step adds one sample', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // the histograms and the seed field are folded: the link opens them
  await openScene(page, '#/monte-carlo?open=race-histograms,settings');
  await test.step('the description (accessibility tree): live numbers at the opening position, then another seed', async () => {
    const node = await axNodeOf(page, RACE);
    expect(node!.role).toBe('group');
    expect(node!.name).toMatch(/uniform against importance sampling/);
    const t = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    const desc = node!.description;
    expect(desc.startsWith(`${t.toLocaleString('en')} samples: uniform estimate`)).toBe(true);
    expectUniform(desc, t, 1);
    expect(desc).toContain(`importance (p ∝ f) ${I.toPrecision(4)} ± 0 (zero variance)`);
    expect(desc).toContain(`exact I = ${Number(I.toPrecision(6))}`);
    // where the samples fell, as the model's samples say
    const tr = examTrack(1);
    const share = (xs: Float64Array) =>
      Math.round((100 * Array.from(xs.subarray(0, t)).filter((x) => x >= 1 && x <= 2).length) / t);
    expect(desc).toContain(`${share(tr.importance.x)} % of the importance samples lie in [1, 2]`);
    expect(desc).toContain(`against ${share(tr.uniform.x)} % of the uniform ones`);
    // the inner plots are named and described too
    expect((await axNodeOf(page, '[data-testid="race-errors"]'))!.description).toMatch(/falls as N⁻/);
    expect((await axNodeOf(page, '[data-testid="race-histogram-importance"]'))!.description).toContain(
      `Histogram of all ${t.toLocaleString('en')} importance samples`,
    );

    // a parameter: another seed gives another description, with that seed's numbers
    const seed = page.getByTestId('seed-input');
    await seed.fill('7');
    await seed.press('Enter');
    await expect.poll(() => description(page), { timeout: 15_000 }).not.toBe(desc);
    expectUniform(await description(page), t, 7);
    // and it is announced once settled
    await expect(page.getByTestId('live-region')).toHaveText(await description(page), { timeout: 15_000 });
  });

  // the race with seed 7 from here on
  await test.step('the histograms hold every sample drawn so far, paused, playing, stepped and reset', async () => {
    const track = examTrack(7);
    const tl = page.getByTestId('timeline');
    const lanes = [track.uniform.x, track.importance.x];
    const check = (h: { t: number; counts: number[] }[]) => {
      h.forEach((lane, k) => {
        expect(lane.counts.reduce((s, c) => s + c, 0)).toBe(lane.t);
        expect(lane.counts).toEqual(binned(lanes[k], lane.t, lane.counts.length));
      });
      expect(h[0].t).toBe(h[1].t);
      return h[0].t;
    };
    // the race opens with samples drawn (not at t = 0), and the histograms hold all of them
    const t0 = Number(await tl.getAttribute('data-t'));
    expect(t0).toBeGreaterThan(100);
    expect(check(await histograms(page))).toBe(t0);
    // importance samples crowd where f is large: more of them in the last bin than in the first
    const [, imp] = await histograms(page);
    expect(imp.counts.at(-1)!).toBeGreaterThan(imp.counts[0]);
    // playing: at several moments, what is drawn is all the samples drawn so far
    await page.getByTestId('timeline-play').click();
    const seen = new Set<number>();
    await expect
      .poll(
        async () => {
          seen.add(check(await histograms(page)));
          return seen.size;
        },
        { timeout: 30_000 },
      )
      .toBeGreaterThanOrEqual(4);
    expect(Math.max(...seen)).toBeGreaterThan(t0);
    await page.getByTestId('timeline-play').click();
    await expect(tl).toHaveAttribute('data-playing', '0');
    const t = Number(await tl.getAttribute('data-t'));
    expect(check(await histograms(page))).toBe(t);
    // paused: the readouts are the model's frame at t
    expectFrame(await raceReadouts(page), raceAt(track, t));
    // a step adds one sample: the model's next frame, whose uniform term is (b − a) f(xᵢ)
    await page.getByTestId('timeline-step').click();
    await expect(tl).toHaveAttribute('data-t', String(t + 1));
    expect(check(await histograms(page))).toBe(t + 1);
    expectFrame(await raceReadouts(page), raceAt(track, t + 1));
    close(
      await readoutNumber(page, 'race-uniform-term'),
      2 * f(await readoutNumber(page, 'race-uniform-x')),
      1e-10,
    );
    await page.getByTestId('timeline-reset').click();
    await expect(tl).toHaveAttribute('data-t', '0');
    expect(check(await histograms(page))).toBe(0);
  });
});

test('accessibility: keyboard only, back to the exam’s configuration, Q4’s answers read from the accessibility tree', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/monte-carlo?f=x%5E2');
  // Tab to the "Exam configuration" button and press it
  let found = false;
  for (let i = 0; i < 80 && !found; i++) {
    await page.keyboard.press('Tab');
    found = await page.evaluate(() => document.activeElement?.textContent === 'Exam configuration');
  }
  expect(found).toBe(true);
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('not-exam-config')).toHaveCount(0);
  // the numbers the exam asks for, as a screen reader gets them
  const uni = (2 / 4) * EXAM_X.reduce((s, x) => s + f(x), 0);
  await expect
    .poll(async () => (await axTree(page)).map((n) => n.name).join('\n'), { timeout: 15_000 })
    .toContain(`= ${Math.round(3 * I)}/3`);
  const names = (await axTree(page)).map((n) => n.name);
  expect(names).toContain(I.toPrecision(6));
  expect(names).toContain(uni.toPrecision(6));
  expect(names).toContain(`≈ ${uni.toFixed(2)} to 2 decimals`);
  expect(names.some((n) => /every term f\/p is the same \(zero variance\)/.test(n))).toBe(true);
  // (d): play the race from the keyboard and read the paused state from the figure's description
  let play = false;
  for (let i = 0; i < 40 && !play; i++) {
    await page.keyboard.press('Tab');
    play = await page.evaluate(() => document.activeElement?.getAttribute('data-testid') === 'timeline-play');
  }
  expect(play).toBe(true);
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
  await expect.poll(() => description(page)).toMatch(/importance \(p ∝ f\) 18\.67 ± 0 \(zero variance\)/);
});
