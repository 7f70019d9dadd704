// #/ray-sphere as a screen reader and a keyboard receive it, and as a lecture room sees it: the
// figures' names and live descriptions read from Chromium's accessibility tree (CDP), the handles
// as sliders, the audio traces, no handle over a label, ask=1 and the classroom stage. Expected
// numbers come from the scene's pure model, computed here.
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, waitForReadout } from './fixtures';
import { computeModel } from '../../src/scenes/ray-sphere/model';
import { formatNumber } from '../../src/ui/Readout';

test.describe.configure({ timeout: 120_000 });

type V = [number, number, number];
const URL_OF = (o: V, d: V, r = 1, extra = '') =>
  `#/ray-sphere?o=${o.join(',')}&d=${d.join(',')}&c=0,0,0&r=${r}${extra}`;
/** A number as the descriptions write it (4 significant digits, a real minus sign). */
const n4 = (x: number) => formatNumber(x, 4).replace(/^-/, '−');

interface Ax {
  role: string;
  name: string;
  description: string;
}

/** What the accessibility tree holds for the first element matching `selector`. */
async function ax(page: Page, selector: string): Promise<Ax | null> {
  const session = await page.context().newCDPSession(page);
  try {
    const { root } = await session.send('DOM.getDocument', { depth: 0 });
    const found = await session.send('DOM.querySelector', { nodeId: root.nodeId, selector });
    if (!found.nodeId) return null;
    const tree = (await session.send('Accessibility.getPartialAXTree', {
      nodeId: found.nodeId,
      fetchRelatives: false,
    })) as { nodes: { [k in 'role' | 'name' | 'description']?: { value?: unknown } }[] };
    const node = tree.nodes[0];
    const text = (k: 'role' | 'name' | 'description') => String(node?.[k]?.value ?? '');
    return node ? { role: text('role'), name: text('name'), description: text('description') } : null;
  } finally {
    await session.detach();
  }
}

/**
 * A handle's value text. Chromium's accessibility tree over CDP reports a slider's valuetext as
 * empty whatever aria-valuetext says (even for a native range input), so it is read from the
 * attribute, which is what the platform accessibility APIs pass to a screen reader.
 */
const valueText = async (page: Page, testId: string) =>
  (await page.getByTestId(testId).getAttribute('aria-valuetext')) ?? '';

/** The group of the whole accessibility tree named `name` (how a screen reader finds the figure). */
async function groupNamed(page: Page, name: string): Promise<Ax | null> {
  const session = await page.context().newCDPSession(page);
  try {
    const { nodes } = (await session.send('Accessibility.getFullAXTree')) as unknown as {
      nodes: { ignored?: boolean; [k: string]: unknown }[];
    };
    const v = (n: Record<string, unknown>, k: string) =>
      String((n[k] as { value?: unknown } | undefined)?.value ?? '');
    const hit = nodes.find((n) => !n.ignored && v(n, 'role') === 'group' && v(n, 'name') === name);
    return hit ? { role: 'group', name, description: v(hit, 'description') } : null;
  } finally {
    await session.detach();
  }
}

const FIG = 'Cross-section through the ray and the sphere';
const figDescription = async (page: Page) => (await groupNamed(page, FIG))?.description ?? '';

test('the cross-section is a named figure whose description holds the live numbers and follows r', async ({
  page,
}) => {
  const o: V = [-3, 0.3, 0.2];
  await openScene(page, URL_OF(o, [1, 0, 0]));
  const m = computeModel({ o, d: [1, 0, 0], c: [0, 0, 0], r: 1, method: 'stable' }).chosen!;
  const said = await figDescription(page);
  expect(said).toContain(`Δ = ${n4(m.discriminant)} > 0`);
  expect(said).toContain(`t₀ = ${n4(m.t0!)} and t₁ = ${n4(m.t1!)}`);
  expect(said).toContain(`hit point p = (${n4(o[0] + m.t0!)}, 0.3, 0.2)`);
  // the readouts say the same (full precision in data-value)
  expect(n4(Number(await readout(page, 't-hit')))).toBe(n4(m.t0!));

  // a parameter: r = 0.25 makes it a miss, and the description says so, with the closest approach
  const r = page.getByTestId('input-r');
  await r.fill('0.25');
  await r.press('Enter');
  await waitForReadout(page, 'case', (v) => v === 'miss');
  const miss = computeModel({ o, d: [1, 0, 0], c: [0, 0, 0], r: 0.25, method: 'stable' }).chosen!;
  await expect.poll(() => figDescription(page)).toContain(`The ray misses: Δ = ${n4(miss.discriminant)} < 0`);
  const now = await figDescription(page);
  expect(now).toContain('passes 0.3606 from C, 0.1106 beyond the radius');
  expect(now).toContain('r = 0.25');
  // announced once settled
  await expect(page.getByTestId('live-region')).toHaveText(/The ray misses/, { timeout: 15_000 });
});

test('paused, the description says where the sweep stopped (τ) and what the ray does there', async ({
  page,
}) => {
  await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0]));
  const before = await figDescription(page);
  expect(before).toContain('Sweep τ = 0.500, h / r = 0.361');
  await page.getByTestId('timeline-play').click();
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
  await expect
    .poll(async () => Number(await page.getByTestId('timeline').getAttribute('data-t')), { timeout: 30_000 })
    .toBeGreaterThan(0.56);
  await page.getByTestId('timeline-play').click();
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
  const tau = Number(await page.getByTestId('timeline').getAttribute('data-t'));
  await expect.poll(() => figDescription(page)).toContain(`Sweep τ = ${tau.toFixed(3)}`);
  expect(await figDescription(page)).not.toBe(before);
  // on pause the description is spoken
  await expect(page.getByTestId('live-region')).toContainText(`τ = ${tau.toFixed(3)}`, { timeout: 15_000 });
  // the transport names its position τ, never t (the ray's t is on the g(t) axis beside it)
  await expect(page.getByTestId('timeline-pos')).toHaveText(/^τ = \d\.\d{3}, h \/ r = /);
  await expect(page.getByTestId('timeline-scrub')).toHaveAttribute('aria-valuetext', /^τ = /);
});

test('handles are sliders that say what they are, where they are and what the ray does; keys move them', async ({
  page,
}) => {
  await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0]));
  const o = await ax(page, '[data-testid="handle-o"]');
  expect(o).toMatchObject({ role: 'slider', name: 'ray origin o' });
  expect(await valueText(page, 'handle-o')).toMatch(/^o = \(−3, 0\.3, 0\.2\); the ray hits at t₀ = /);
  const rh = await ax(page, '[data-testid="handle-r"]');
  expect(rh).toMatchObject({ role: 'slider', name: 'sphere radius r' });
  expect(await valueText(page, 'handle-r')).toMatch(/^r = 1; the ray hits/);
  // the radius grows with ↑ and shrinks with ↓ (a slider), and the value text follows
  await page.getByTestId('handle-r').focus();
  for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowDown');
  await expect.poll(async () => await valueText(page, 'handle-r')).toMatch(/^r = 0\.\d+; /);
  // the direction tip, moved up by keys, turns the ray away: a miss, said by its value text
  await page.getByTestId('handle-tip').focus();
  for (let i = 0; i < 12; i++) await page.keyboard.press('ArrowUp');
  await waitForReadout(page, 'case', (v) => v === 'miss');
  await expect
    .poll(async () => await valueText(page, 'handle-tip'))
    .toMatch(/^d = \(.*\), at -?\d+° in the figure; the ray misses \(Δ = −/);
});

test('a pointer drag says what was moved, where to, and what the ray does', async ({ page }) => {
  await openScene(page, URL_OF([-3, 0.3, 0], [1, 0, 0]));
  const h = page.getByTestId('handle-o');
  const b = (await h.boundingBox())!;
  await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2);
  await page.mouse.down();
  await page.mouse.move(b.x + b.width / 2, b.y - 120, { steps: 8 });
  await page.mouse.up();
  await waitForReadout(page, 'case', (v) => v === 'miss');
  await expect(page.getByTestId('live-region')).toContainText(
    /Ray origin o: o = \(.*\); the ray misses|The ray misses/,
    {
      timeout: 15_000,
    },
  );
});

/** The page boxes of the cross-section's visible labels and of its handles. */
async function labelsAndHandles(page: Page) {
  return page.evaluate(() => {
    const fig = document.querySelector('[data-testid="cross-section"]')!;
    const box = (el: Element) => {
      const r = el.getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height };
    };
    const shown = (el: Element) => !el.closest('[display="none"]') && el.getBoundingClientRect().width > 0;
    const labels = [...fig.querySelectorAll('text')]
      .filter(shown)
      .map((t) => ({ text: t.textContent ?? '', ...box(t) }));
    const handles = [...fig.querySelectorAll('[data-testid^="handle-"]')]
      .filter(shown)
      .map((h) => ({ id: h.getAttribute('data-testid')!, ...box(h) }));
    return { labels, handles };
  });
}

const overlap = (a: { x: number; y: number; w: number; h: number }, b: typeof a) =>
  Math.min(a.x + a.w, b.x + b.w) > Math.max(a.x, b.x) && Math.min(a.y + a.h, b.y + b.h) > Math.max(a.y, b.y);

test('no handle covers a label, on the page and on the classroom stage', async ({ page }) => {
  const s = Math.SQRT1_2;
  const cases: [string, { width: number; height: number }][] = [
    // the exit point at 45° on the rim, where the radius handle used to sit on the t₁ label
    [URL_OF([s - 3, s, 0], [1, 0, 0]), { width: 1280, height: 900 }],
    [URL_OF([-3, -1.2, 0.6], [1, 0.4, -0.15]), { width: 1280, height: 900 }],
    [URL_OF([0.2, -0.3, 0.1], [1, 0.5, 0]), { width: 375, height: 800 }],
    [URL_OF([-5, 1, 0], [1, 0, 0], 1, '&present=1'), { width: 1280, height: 720 }],
    [URL_OF([3, 0.3, 0.2], [1, 0, 0], 1, '&present=1'), { width: 1920, height: 1080 }],
  ];
  for (const [href, size] of cases) {
    await page.setViewportSize(size);
    await openScene(page, href);
    const { labels, handles } = await labelsAndHandles(page);
    expect(labels.length, href).toBeGreaterThanOrEqual(4);
    expect(handles.length, href).toBe(4);
    for (const l of labels)
      for (const h of handles)
        expect(overlap(l, h), `${href}: handle ${h.id} covers “${l.text}”`).toBe(false);
  }
});

test('handles differ in colour (and shape) from the markers beside them', async ({ page }) => {
  for (const theme of ['light', 'dark']) {
    await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0], 1, `&theme=${theme}`));
    const c = await page.evaluate(() => {
      const fig = document.querySelector('[data-testid="cross-section"]')!;
      const style = (sel: string, prop: 'fill' | 'stroke') => getComputedStyle(fig.querySelector(sel)!)[prop];
      return {
        tipFill: style('[data-testid="handle-tip"] .rs-handle-dot', 'fill'),
        tipStroke: style('[data-testid="handle-tip"] .rs-handle-dot', 'stroke'),
        rFill: style('[data-testid="handle-r"] .rs-handle-dot', 'fill'),
        hitFill: style('.rs-root.hit circle', 'fill'),
        rootFill: style('.rs-root:not(.hit) circle', 'fill'),
        ray: style('.rs-ray', 'stroke'),
        circle: style('.rs-circle', 'stroke'),
      };
    });
    for (const handle of [c.tipFill, c.tipStroke, c.rFill])
      for (const marker of [c.hitFill, c.rootFill, c.ray, c.circle]) expect(handle, theme).not.toBe(marker);
  }
});

test('g(t) and Δ are named, summarised, as tables and as audio traces with events at roots and tangency', async ({
  page,
}) => {
  await page.addInitScript(() => {
    const w = window as unknown as { __osc: number };
    w.__osc = 0;
    const orig = AudioContext.prototype.createOscillator;
    AudioContext.prototype.createOscillator = function (this: AudioContext) {
      w.__osc++;
      return orig.call(this);
    };
  });
  await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0]));
  const g = await groupNamed(page, 'g(t) along the ray: the quadratic and its roots');
  expect(g!.description).toMatch(
    /lowest at t = 3 where g = −0\.87; it crosses zero at t₀ = 2\.067 and t₁ = 3\.933: t₀ is the hit/,
  );
  const d = await groupNamed(page, 'Δ against the sweep');
  expect(d!.description).toMatch(/crosses zero at h \/ r = −1 and 1 \(tangent\)/);
  expect(d!.description).toContain('Now at h / r = 0.361: Δ = 3.48.');

  // the tables: real tables of what is plotted
  const gt = page.getByTestId('g-table');
  await gt.locator('summary').click();
  await expect(gt.locator('th[scope="col"]')).toHaveText(['t', 'g(t)']);
  await expect(gt.locator('tbody tr')).toHaveCount(49);
  const dt = page.getByTestId('delta-table');
  await dt.locator('summary').click();
  await expect(dt.locator('th[scope="col"]')).toHaveText(['h / r', 'robust Δ', 'textbook Δ', 'case']);

  // the g trace: nothing sounds until asked; stepping speaks each point and names the roots
  const osc = () => page.evaluate(() => (window as unknown as { __osc: number }).__osc);
  const trace = page.getByTestId('g-trace');
  await trace.focus();
  const live = page.getByTestId('live-region');
  await page.keyboard.press('ArrowRight');
  await expect(live).toHaveText(/^t = −?[\d.]+, g = .*\(point 1 of 49\)/);
  let named = false;
  for (let i = 0; i < 48 && !named; i++) {
    await page.keyboard.press('ArrowRight');
    named = /root t₀ = 2\.067/.test((await live.textContent()) ?? '');
  }
  expect(named, 'stepping onto t₀ names the root').toBe(true);
  expect(await osc()).toBe(0);
  await page.keyboard.press('Enter');
  await expect(live).toHaveText(/^Playing g\(t\) along the ray/);
  await expect.poll(osc, { timeout: 15_000 }).toBeGreaterThan(0);
  await page.keyboard.press('Escape');

  // the Δ trace names the tangencies (Δ = 0)
  const dtrace = page.getByTestId('delta-trace');
  await dtrace.focus();
  await page.keyboard.press('Home');
  let tangent = false;
  for (let i = 0; i < 240 && !tangent; i += 1) {
    await page.keyboard.press('ArrowRight');
    tangent = /tangent, Δ = 0 at h \/ r = −1/.test((await live.textContent()) ?? '');
  }
  expect(tangent, 'stepping onto a tangency names it').toBe(true);
});

test('ask=1: the ray and the sphere only, until Reveal; then the roots and the readouts', async ({
  page,
}) => {
  await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0], 1, '&ask=1'));
  await expect(page.getByTestId('ask-prompt')).toBeVisible();
  await expect(page.locator('[data-testid="cross-section"] .rs-root:not([display="none"])')).toHaveCount(0);
  await expect(page.getByTestId('t-hit')).toHaveCount(0);
  await expect(page.getByTestId('case-banner')).toHaveCount(0);
  await expect(page.getByTestId('g-plot')).toHaveCount(0);
  await expect(page.locator('.timeline')).toHaveCount(0);
  const hidden = await figDescription(page);
  expect(hidden).toContain('hidden until you reveal it');
  expect(hidden).not.toMatch(/t₀|Δ =/);
  expect(await valueText(page, 'handle-o')).toBe('o = (−3, 0.3, 0.2)');
  await page.getByTestId('reveal').click();
  await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
  await waitForReadout(page, 'case', (v) => v === 'two-hits');
  await expect(page.locator('[data-testid="cross-section"] .rs-root:not([display="none"])')).toHaveCount(2);
  await expect.poll(() => figDescription(page)).toContain('The ray hits');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', '0.5');
});

// the projector's common size (the stage's general checks run for every scene in catalogue.spec.ts)
for (const size of [{ width: 1280, height: 720 }]) {
  test(`present=1 at ${size.width}×${size.height}: the whole cross-section, the readouts and the transport on the first screen`, async ({
    page,
  }) => {
    await page.setViewportSize(size);
    await openScene(page, '#/ray-sphere?present=1');
    await page.evaluate(() => window.scrollTo(0, 0));
    const stage = page.getByTestId('scene-stage');
    for (const el of [
      page.getByTestId('cross-section'),
      stage.getByTestId('case-banner'),
      stage.getByTestId('stage-t-hit'),
      stage.getByTestId('timeline'),
    ]) {
      const b = (await el.boundingBox())!;
      expect(b.y).toBeGreaterThanOrEqual(0);
      expect(b.y + b.height).toBeLessThanOrEqual(size.height + 0.5);
      expect(b.x + b.width).toBeLessThanOrEqual(size.width + 0.5);
    }
    // the figure takes a good part of the screen, not a strip
    expect((await page.getByTestId('cross-section').boundingBox())!.height).toBeGreaterThan(
      0.4 * size.height,
    );
    await expect(page.getByTestId('controls-drawer')).toBeHidden();
  });
}

test('keyboard only: pick the case presets and read Δ, the roots and the hit from the accessibility tree', async ({
  page,
}) => {
  await openScene(page, '#/ray-sphere');
  /** Tab (or Shift+Tab) from where focus is until the element with this test id has it. */
  const tabTo = async (testId: string, key = 'Tab') => {
    for (let i = 0; i < 120; i++) {
      await page.keyboard.press(key);
      if (await page.evaluate((id) => document.activeElement?.getAttribute('data-testid') === id, testId))
        return;
    }
    throw new Error(`Tab never reached ${testId}`);
  };
  const presets: [string, V, V][] = [
    ['two-hits', [-3, 0.3, 0.2], [1, 0, 0]],
    ['inside', [0.2, -0.3, 0.1], [1, 0.5, 0]],
    ['behind', [3, 0.3, 0.2], [1, 0, 0]],
  ];
  for (const [id, o, d] of presets) {
    await tabTo(`preset-${id}`);
    await page.keyboard.press('Enter');
    await waitForReadout(page, 'case', (v) => v === id);
    const m = computeModel({ o, d, c: [0, 0, 0], r: 1, method: 'stable' }).chosen!;
    const said = await figDescription(page);
    expect(said, id).toContain(`Δ = ${n4(m.discriminant)}`);
    expect(said, id).toContain(`t₀ = ${n4(m.t0!)}`);
    expect(said, id).toContain(`t₁ = ${n4(m.t1!)}`);
    if (id === 'two-hits') expect(said).toContain('It enters at t₀, the hit point');
    if (id === 'inside') expect(said).toContain(`the hit is the exit t₁ = ${n4(m.t1!)}`);
    if (id === 'behind') expect(said).toContain('so the ray (t ≥ 0) has no hit');
  }
  // then move the origin by keys: the slider's value text says where it is and what the ray does
  await tabTo('handle-o', 'Shift+Tab');
  for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowUp');
  await expect.poll(async () => await valueText(page, 'handle-o')).toMatch(/the ray misses/);
});
