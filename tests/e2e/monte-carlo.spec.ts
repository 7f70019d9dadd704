/**
 * Browser tests of #/monte-carlo (exam Q2, Q4). Every expected value is computed here from the
 * formula (f(x) = (x + 2)², p = 1/(b − a), p = 3(x + 2)²/((b + 2)³ − (a + 2)³), ∫ eˣ dx = eᵇ − eᵃ),
 * never pasted from the answer key or from the app.
 */
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { drawnEstimate } from '../../src/scenes/monte-carlo/drawnEstimate';
import { raceAt, raceTrack } from '../../src/scenes/monte-carlo/race';
import { squarePdf1D, uniformPdf1D } from '../../src/core/sampling/pdf1d';
import { compileXFast } from '../../src/scenes/monte-carlo/expr';

const EXAM_X = [1.16, 1.98, 0.54, 1.26];
const f = (x: number) => (x + 2) ** 2;
const cube = (x: number) => x * x * x;
const exactSquare = (a: number, b: number) => (cube(b + 2) - cube(a + 2)) / 3;
const close = (got: number, want: number, tol: number) =>
  expect(Math.abs(got - want), `${got} ≈ ${want} (±${tol})`).toBeLessThanOrEqual(tol);

test.describe('exam Q4', () => {
  test('default page: the worked table of the exam’s four samples, 56/3, and the key’s differing figures', async ({
    page,
  }) => {
    await openScene(page, '#/monte-carlo');
    close(await readoutNumber(page, 'exact'), exactSquare(0, 2), 1e-13);
    for (const [i, x] of EXAM_X.entries()) {
      close(await readoutNumber(page, `f-${i}`), f(x), 1e-12);
      close(await readoutNumber(page, `p-${i}`), 1 / 2, 0);
    }
    const uniform = (2 / 4) * EXAM_X.reduce((s, x) => s + f(x), 0);
    close(await readoutNumber(page, 'q4-uniform'), uniform, 1e-12);
    close(await readoutNumber(page, 'q4-importance'), exactSquare(0, 2), 1e-12);
    // the key prints 18.84 for f(1.98); the page says the computed value differs
    const notes = page.getByTestId('key-notes');
    await expect(notes).toContainText(String(f(1.98)));
    await expect(notes).toContainText('18.84');
    await expect(notes).toContainText('slip');
    // no samples given: the estimate comes from N drawn samples (in short tasks after the first
    // render) and is within 5 standard errors
    const est = Number(await waitForReadout(page, 'estimate', (v) => v !== 'none'));
    const se = await readoutNumber(page, 'stderr');
    expect(se).toBeGreaterThan(0);
    close(est, exactSquare(0, 2), 5 * se);
    // exactly the model's estimate with these settings (N = 10000 i.i.d. uniform points, seed 1)
    const want = drawnEstimate(compileXFast('(x+2)^2')!.fn, uniformPdf1D(0, 2), 'independent', 1, 10000);
    expect(est).toBe(want.estimate);
    expect(se).toBe(want.stderr);
  });
});

test.describe('typed integrands and pdfs', () => {
  test('exp(x) on [−1, 1.5]: exact by quadrature, given samples, and a custom pdf ∝ eˣ', async ({ page }) => {
    const a = -1;
    const b = 1.5;
    const I = Math.exp(b) - Math.exp(a);
    await openScene(page, `#/monte-carlo?f=exp(x)&a=${a}&b=${b}&samples=0.3,-0.5`);
    close(await waitForReadout(page, 'exact', (v) => v !== 'none').then(Number), I, 1e-13);
    close(await readoutNumber(page, 'f-0'), Math.exp(0.3), 1e-14);
    close(await readoutNumber(page, 'p-1'), 1 / (b - a), 1e-15);
    close(await readoutNumber(page, 'estimate'), ((Math.exp(0.3) + Math.exp(-0.5)) / 2) * (b - a), 1e-12);
    await expect(page.getByText(/Gauss–Kronrod/).first()).toBeVisible();

    await openScene(page, `#/monte-carlo?f=exp(x)&a=${a}&b=${b}&pdf=custom&pdfexpr=exp(x)&samples=0.3,-0.5`);
    close(await waitForReadout(page, 'p-0', (v) => v !== 'none').then(Number), Math.exp(0.3) / I, 1e-12);
    close(await readoutNumber(page, 'estimate'), I, 1e-11);

    // drawn from the tabulated custom pdf: nearly zero variance, unbiased
    await openScene(page, `#/monte-carlo?f=exp(x)&a=${a}&b=${b}&pdf=custom&pdfexpr=exp(x)&n=20000`);
    const est = Number(await waitForReadout(page, 'estimate', (v) => v !== 'none'));
    const se = await readoutNumber(page, 'stderr');
    expect(se).toBeLessThan(1e-3);
    close(est, I, 5 * se + 1e-12);
  });

  test('bad pdfs get a clear message and no estimate; a bad f falls back with a message', async ({
    page,
  }) => {
    // one pdf that is wrong as a density and one that does not parse (each kind of message is a
    // unit test of the model: tests/scenes/monte-carlo/model.test.ts)
    const cases: [string, RegExp][] = [
      ['x-1', /negative/],
      ['x+', /syntax|character|not valid/i],
    ];
    for (const [expr, msg] of cases) {
      await openScene(page, `#/monte-carlo?pdf=custom&pdfexpr=${encodeURIComponent(expr)}`);
      await expect(page.getByTestId('pdf-error')).toContainText(msg);
      expect(await readout(page, 'estimate')).toBe('none');
      expect(await readout(page, 'p-0')).toBe('none');
      // the exact integral and f stay available
      close(await readoutNumber(page, 'exact'), exactSquare(0, 2), 1e-13);
    }
    await openScene(page, '#/monte-carlo?f=y%2B1');
    await expect(page.getByText(/using \(x\+2\)\^2/)).toBeVisible();
    close(await readoutNumber(page, 'exact'), exactSquare(0, 2), 1e-13);
    await openScene(page, '#/monte-carlo?a=3&b=1');
    await expect(page.getByText(/must satisfy a < b/)).toBeVisible();
  });
});

test.describe('long runs in the worker', () => {
  test('n = 3·10⁶ runs off the main thread and finishes; the convergence plot notes the exact strategy', async ({
    page,
  }) => {
    await openScene(page, '#/monte-carlo?pdf=proportional&n=3000000&open=convergence');
    const est = Number(await waitForReadout(page, 'estimate', (v) => v !== 'none', 45000));
    close(est, exactSquare(0, 2), 1e-10);
    await page.getByRole('heading', { name: /Convergence as N grows/ }).scrollIntoViewIfNeeded();
    await expect(page.getByTestId('exact-strategies')).toContainText('p ∝ f', { timeout: 45000 });
    await expect(page.locator('.mc-plots .js-plotly-plot').first()).toBeVisible();
  });
});

test('cancel stops a 10⁷-sample run; the page stays responsive and shows no estimate', async ({ page }) => {
  // a slow-ish integrand and sequence, so that the run is still going when we cancel it
  const f = encodeURIComponent('sin(x)^2 + cos(3*x)*exp(-x) + sqrt(x+1) + log(x+2) + atan(x)^3');
  await openScene(page, `#/monte-carlo?n=10000000&strategy=halton&pdf=linear&f=${f}`);
  await expect(page.getByText(/Estimating with 10,000,000 samples/)).toBeVisible();
  // dispatchEvent: the progress text re-renders every frame, so do not wait for a "stable" box
  await page.locator('.mc-progress button', { hasText: 'Cancel' }).dispatchEvent('click');
  await expect(page.getByText(/Estimating with 10,000,000 samples/)).toHaveCount(0);
  expect(await readout(page, 'estimate')).toBe('none');
  // still responsive: a control change goes through at once
  await page.getByTestId('pdf-select').selectOption('proportional');
  await expect(page).toHaveURL(/pdf=proportional/);
});

// ---------------------------------------------------------------------------------------------
// Exam first and the animation
// ---------------------------------------------------------------------------------------------

/** The race as the model computes it, for the exam's f on [0, 2], p ∝ f, seed s. */
const examTrack = (seed: number) => raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), exactSquare(0, 2), seed);

async function raceReadouts(page: import('@playwright/test').Page) {
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

test.describe('exam first: Q4 (a)–(d)', () => {
  test('each part asks, derives with live numbers and answers; the key’s Σ from i = 0 is flagged', async ({
    page,
  }) => {
    await openScene(page, '#/monte-carlo');
    const I = exactSquare(0, 2);
    // order: the question (with the animation) before the parts, the parts before "explore further"
    const ys = await Promise.all(
      ['question-4', 'race', 'part-4a', 'part-4b', 'part-4c', 'part-4d', 'explore-further'].map(
        async (id) => (await page.getByTestId(id).boundingBox())!.y,
      ),
    );
    expect([...ys].sort((p, q) => p - q)).toEqual(ys);
    // (a): expansion, antiderivative, the evaluation F(2) = 8/3 + 8 + 8, and the exact readout
    const a = page.getByTestId('derivation-4a');
    await expect(a).toContainText('4x');
    await expect(a).toContainText(String((8 / 3).toPrecision(6)));
    await expect(a).toContainText('56');
    close(await readoutNumber(page, 'exact'), I, 1e-13);
    // (b): every f(xᵢ) and the average; the headline is the exam's answer, computed
    const b = page.getByTestId('derivation-4b');
    for (const x of EXAM_X) await expect(b).toContainText(String(Number(f(x).toPrecision(6))));
    const uni = (2 / 4) * EXAM_X.reduce((s, x) => s + f(x), 0);
    close(await readoutNumber(page, 'q4-uniform'), uni, 1e-12);
    await expect(page.getByTestId('answer-4b')).toContainText(uni.toFixed(2));
    await expect(page.getByTestId('key-sum-4b')).toContainText('i = 1 to 4');
    await expect(page.getByTestId('key-sum-4c')).toBeVisible();
    // (c): p(x) = 3(x + 2)²/56 stated in the default (uniform) configuration, each term = I
    await expect(page.getByTestId('pdf-4c')).toContainText(String(cube(4) - cube(2)));
    close(await readoutNumber(page, 'q4-importance'), I, 1e-12);
    await expect(page.getByTestId('derivation-4c')).toContainText(I.toFixed(10).slice(0, 12));
    // (d): the key's remark, with the errors after the whole run computed by the model
    const end = raceAt(examTrack(1), 8192);
    close(await readoutNumber(page, 'q4d-uniform-error'), end.uniform.absError, 1e-10);
    expect(await readoutNumber(page, 'q4d-importance-error')).toBeLessThan(1e-12);
    await expect(page.getByTestId('answer-4d')).toContainText('(c) converges faster');

    // beyond the exam, folded: the race's table and sounds are not mounted until opened; opening
    // writes open= into the link, and the link opens it again
    const fold = page.getByTestId('fold-race-data');
    await expect(fold).not.toHaveAttribute('open');
    await expect(fold.getByTestId('race-table')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(fold.getByTestId('race-table')).toBeVisible();
    await expect(fold.getByTestId('trace-uniform-estimate')).toBeVisible();
    await expect(page).toHaveURL(/[?&]open=race-data(&|$)/);
    await page.reload();
    await expect(page.getByTestId('fold-race-data')).toHaveAttribute('open');
    await expect(page.getByTestId('race-table')).toBeVisible({ timeout: 30_000 });
  });
});

test.describe('animation: samples arrive one by one', () => {
  test('play, pause: readouts equal the model at the paused t; the link restores them; step adds one sample', async ({
    page,
  }) => {
    await openScene(page, '#/monte-carlo?seed=5');
    const tl = page.getByTestId('timeline');
    await page.getByTestId('timeline-play').click();
    await expect
      .poll(async () => Number(await tl.getAttribute('data-t')), { timeout: 20000 })
      .toBeGreaterThan(40);
    await page.getByTestId('timeline-play').click();
    await expect(tl).toHaveAttribute('data-playing', '0');
    const t = Number(await tl.getAttribute('data-t'));
    await expect(page).toHaveURL(new RegExp(`[?&]t=${t}(&|$)`));
    const track = examTrack(5);
    const r = await raceReadouts(page);
    expectFrame(r, raceAt(track, t));

    await openScene(page, `#/monte-carlo?seed=5&t=${t}`);
    expect(await raceReadouts(page)).toEqual(r);

    await page.getByTestId('timeline-step').click();
    await expect(tl).toHaveAttribute('data-t', String(t + 1));
    expectFrame(await raceReadouts(page), raceAt(track, t + 1));
    // the term appears, and the uniform term is (b − a) f(xᵢ)
    close(
      await readoutNumber(page, 'race-uniform-term'),
      2 * f(await readoutNumber(page, 'race-uniform-x')),
      1e-10,
    );
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
async function histograms(page: import('@playwright/test').Page) {
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

test.describe('the race’s histograms and the answers first', () => {
  test('the histograms count every sample drawn so far, paused, playing, stepped and reset', async ({
    page,
  }) => {
    await openScene(page, '#/monte-carlo?seed=3&open=race-histograms');
    const track = examTrack(3);
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
    await page.getByTestId('timeline-step').click();
    await expect(tl).toHaveAttribute('data-t', String(t + 1));
    expect(check(await histograms(page))).toBe(t + 1);
    await page.getByTestId('timeline-reset').click();
    await expect(tl).toHaveAttribute('data-t', '0');
    expect(check(await histograms(page))).toBe(0);
  });

  test('a spread that is zero to rounding says “zero variance”; a real one does not', async ({ page }) => {
    await openScene(page, '#/monte-carlo?t=500');
    const imp = page.getByTestId('race-importance-stderr');
    await expect(imp).toHaveText(/zero variance/);
    expect(await readoutNumber(page, 'race-importance-stderr')).toBeLessThan(1e-12);
    const uni = page.getByTestId('race-uniform-stderr');
    await expect(uni).not.toHaveText(/zero variance/);
    close(await readoutNumber(page, 'race-uniform-stderr'), raceAt(examTrack(1), 500).uniform.stderr, 1e-10);
    // the page's own estimate with p ∝ f (drawn samples), and with a ramp that only approximates f
    await openScene(page, '#/monte-carlo?pdf=proportional&n=2000');
    await waitForReadout(page, 'estimate', (v) => v !== 'none');
    await expect(page.getByTestId('stderr').locator('..')).toContainText('zero variance');
    await openScene(page, '#/monte-carlo?pdf=linear&n=2000');
    await waitForReadout(page, 'estimate', (v) => v !== 'none');
    await expect(page.getByTestId('stderr').locator('..')).not.toContainText('zero variance');
    await expect(page.getByTestId('race-importance-stderr')).not.toHaveText(/zero variance/);
  });
});
