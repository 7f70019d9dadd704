// #/ray-sphere, exam first and the sweep animation on the shared timeline.
// Expected values are computed here, by the scene's own pure model or by plain arithmetic.
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { checkInputs } from '../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../src/scenes/ray-sphere/model';
import { makeSweep, paramsAt, sweepAt } from '../../src/scenes/ray-sphere/sweep';
import type { RaySphereParams } from '../../src/scenes/ray-sphere/params';

type V = [number, number, number];
const P = (o: V, d: V, extra = '') => `#/ray-sphere?o=${o.join(',')}&d=${d.join(',')}&c=0,0,0&r=1${extra}`;

/** The scene's model at timeline position t, computed in the test. */
function modelAt(
  p: {
    o: V;
    d: V;
    c?: V;
    r?: number;
    sweep?: 'offset' | 'rotate';
    extent?: number;
    method?: 'stable' | 'naive';
  },
  t: number,
) {
  const params: RaySphereParams = {
    o: p.o,
    d: p.d,
    c: p.c ?? [0, 0, 0],
    r: p.r ?? 1,
    method: p.method ?? 'stable',
    precision: 'f64',
    sweep: p.sweep ?? 'offset',
    extent: p.extent ?? 2.5,
    t,
    play: false,
  };
  const sw = makeSweep(checkInputs(params), params.sweep as 'offset' | 'rotate', params.extent);
  return { m: computeModel(paramsAt(params, sw, t)), s: sweepAt(sw, t) };
}

async function expectReadoutsAt(
  page: import('@playwright/test').Page,
  want: ReturnType<typeof modelAt>['m'],
) {
  const r = want.chosen!;
  expect(await readoutNumber(page, 'a')).toBe(r.a);
  expect(await readoutNumber(page, 'b')).toBe(r.b);
  expect(await readoutNumber(page, 'c')).toBe(r.c);
  expect(await readoutNumber(page, 'discriminant')).toBe(r.discriminant);
  expect(await readout(page, 'case')).toBe(r.case);
  expect(await readout(page, 't-hit')).toBe(r.tHit === null ? 'none' : String(r.tHit));
}

test.describe('exam first', () => {
  test('question, then the figure, the derivation with live numbers, the live answer, then explore further', async ({
    page,
  }) => {
    const o: V = [-3, 0.3, 0.2];
    // the t_min note is a fold of the derivation
    await openScene(page, P(o, [1, 0, 0], '&open=tmin'));
    const part = page.getByTestId('part-5');
    await expect(part).toContainText('The exam asks');
    await expect(part.locator('.exam-asks')).toContainText('centre C');
    await expect(part.locator('.exam-asks')).toContainText('Δ ≥ 0');
    // live numbers: c = |o − C|² − r² = 8.13, t-hit = 3 − √0.87 (8 significant digits)
    const c = 9 + 0.09 + 0.04 - 1;
    await expect(page.getByTestId('step-numbers')).toContainText(String(Number(c.toPrecision(6))));
    const hit = 3 - Math.sqrt(1 - 0.13);
    await expect(page.getByTestId('step-hit')).toContainText(String(Number(hit.toPrecision(8))));
    await expect(page.getByTestId('step-conditions')).toContainText('Δ ≥ 0');
    await expect(page.getByTestId('step-conditions')).toContainText('t ≥ 0');
    await expect(page.getByTestId('step-substitute')).toContainText('C');
    // t_min: the live example and the survey say self-intersection happens with t ≥ 0, never with t > t_min
    await expect(page.getByTestId('step-tmin')).toContainText('shadow acne');
    const survey = page.getByTestId('tmin-survey');
    // its rays are cast in short tasks after the derivation mounts: wait for the counts
    await expect(survey).toHaveAttribute('data-count', /^[1-9]\d*$/, { timeout: 30_000 });
    expect(Number(await survey.getAttribute('data-zero'))).toBeGreaterThan(0);
    expect(Number(await survey.getAttribute('data-tmin'))).toBe(0);
    await expect(page.getByTestId('tmin-example')).toContainText('p itself');
    await expect(page.getByTestId('q5-keynote')).toContainText('Ray Tracing in One Weekend');
    // page order
    const y = async (id: string) => (await page.getByTestId(id).boundingBox())!.y;
    const order = [
      await y('part-5'),
      await y('cross-section'),
      await y('derivation'),
      await y('live-answer'),
      await y('explore-further'),
    ];
    expect([...order].sort((a, b) => a - b)).toEqual(order);
  });

  test('Δ beside a, b, c: b² − 4ac of the shown numbers, and which method computed which', async ({
    page,
  }) => {
    await openScene(page, P([-3, -1.2, 0.6], [1, 0.4, -0.15], '&open=more'));
    const [a, b, c] = [
      await readoutNumber(page, 'a'),
      await readoutNumber(page, 'b'),
      await readoutNumber(page, 'c'),
    ];
    expect(await readoutNumber(page, 'disc-abc')).toBe(b * b - 4 * a * c);
    await expect(page.getByTestId('disc-method-note')).toContainText('robust form');
    // the textbook method: Δ is exactly b² − 4ac of the numbers shown, and there is no second readout
    await page.getByTestId('method').selectOption('naive');
    await waitForReadout(page, 'discriminant', (v) => Number(v) === b * b - 4 * a * c);
    await expect(page.getByTestId('disc-abc')).toHaveCount(0);
    await expect(page.getByTestId('disc-method-note')).toContainText('textbook way');
    // far sphere, robust: the two differ and the page says by how much
    await page.getByTestId('method').selectOption('stable');
    await page.getByTestId('preset-far').click();
    await waitForReadout(page, 'case', (v) => v === 'two-hits');
    expect(await readoutNumber(page, 'disc-abc')).not.toBe(await readoutNumber(page, 'discriminant'));
    await expect(page.getByTestId('disc-method-note')).toContainText('differs from b² − 4ac');
  });
});

test.describe('sweep animation on the shared timeline', () => {
  test('play, pause: readouts equal the model at the paused t; the link restores them; step advances by 1/120', async ({
    page,
  }) => {
    const cfg = { o: [-3, 0.3, 0.2] as V, d: [1, 0, 0] as V, extent: 2 };
    await openScene(page, P(cfg.o, cfg.d, '&extent=2'));
    const tl = page.getByTestId('timeline');
    await expect(tl).toHaveAttribute('data-t', '0.5');
    await expectReadoutsAt(page, modelAt(cfg, 0.5).m);
    await page.getByTestId('timeline-play').click();
    await expect
      .poll(async () => Number(await tl.getAttribute('data-t')), { timeout: 20_000 })
      .toBeGreaterThan(0.56);
    await page.getByTestId('timeline-play').click();
    await expect(tl).toHaveAttribute('data-playing', '0');
    const t = Number(await tl.getAttribute('data-t'));
    const want = modelAt(cfg, t);
    await expectReadoutsAt(page, want.m);
    expect(await readoutNumber(page, 'sweep-x')).toBe(want.s.x);
    await expect(page).toHaveURL(new RegExp(`t=${String(t).replace('.', '\\.')}`));
    // the link restores exactly these readouts
    await page.goto(page.url());
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', String(t));
    await expectReadoutsAt(page, want.m);
    // step: one step forward, paused
    // (the sweep loops: a step past the end wraps to 0, as the timeline does; a slow machine may have
    // paused within the last step)
    await page.getByTestId('timeline-step').click();
    const stepped = t + 1 / 120 > 1 ? 0 : t + 1 / 120;
    await expect
      .poll(async () => Number(await page.getByTestId('timeline').getAttribute('data-t')))
      .toBeCloseTo(stepped, 12);
    const t2 = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    await expectReadoutsAt(page, modelAt(cfg, t2).m);
  });
});

test.describe('layout', () => {});
