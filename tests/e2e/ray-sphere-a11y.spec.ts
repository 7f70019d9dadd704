// #/ray-sphere as a screen reader and a keyboard receive it: the cross-section's name and live
// description read from Chromium's accessibility tree (CDP), the handles as sliders that say where
// they are and what the ray does, and the case presets worked by keyboard alone. Expected numbers
// come from the scene's pure model, computed here. The descriptions' wording for every case is a
// unit test (tests/scenes/ray-sphere/describe.test.ts); the whole page's tab stops, axe and focus,
// ask=1 and the classroom stage are in catalogue.spec.ts.
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

/**
 * Presses a key `n` times on a handle faster than frames: each press a task of its own, none
 * waiting for a frame (what a held key does on a busy page).
 */
const pressFasterThanFrames = (page: Page, testId: string, key: string, n: number) =>
  page.getByTestId(testId).evaluate(
    async (el, [key, n]) => {
      for (let i = 0; i < n; i++) {
        el.dispatchEvent(new KeyboardEvent('keydown', { key, bubbles: true, cancelable: true }));
        await new Promise((next) => {
          const ch = new MessageChannel();
          ch.port1.onmessage = next;
          ch.port2.postMessage(null);
        });
      }
    },
    [key, n] as const,
  );

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

test('keyboard and accessibility tree: presets by keyboard alone, the handles as sliders, the figure’s live description', async ({
  page,
}) => {
  await test.step('keyboard only: pick the case presets and read Δ, the roots and the hit from the tree', async () => {
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
      await expect.poll(() => figDescription(page), id).toContain(`Δ = ${n4(m.discriminant)}`);
      const said = await figDescription(page);
      expect(said, id).toContain(`t₀ = ${n4(m.t0!)}`);
      expect(said, id).toContain(`t₁ = ${n4(m.t1!)}`);
      if (id === 'two-hits') expect(said).toContain('It enters at t₀, the hit point');
      if (id === 'inside') expect(said).toContain(`the hit is the exit t₁ = ${n4(m.t1!)}`);
      if (id === 'behind') expect(said).toContain('so the ray (t ≥ 0) has no hit');
    }
    // then move the origin by keys: the slider's value text says where it is and what the ray does
    // (a key's step is a fixed distance in the figure, so how many steps reach a miss depends on the
    // figure's size: step until the value text says so)
    await tabTo('handle-o', 'Shift+Tab');
    let said = '';
    for (let i = 0; i < 40 && !/the ray misses/.test(said); i++) {
      for (let k = 0; k < 5; k++) await page.keyboard.press('ArrowUp');
      said = await valueText(page, 'handle-o');
    }
    expect(said).toMatch(/the ray misses/);
  });

  await test.step('the handles are sliders that say what they are, where they are and what the ray does', async () => {
    await openScene(page, URL_OF([-3, 0.3, 0.2], [1, 0, 0]));
    await expect
      .poll(() => valueText(page, 'handle-o'))
      .toMatch(/^o = \(−3, 0\.3, 0\.2\); the ray hits at t₀ = /);
    const o = await ax(page, '[data-testid="handle-o"]');
    expect(o).toMatchObject({ role: 'slider', name: 'ray origin o' });
    const rh = await ax(page, '[data-testid="handle-r"]');
    expect(rh).toMatchObject({ role: 'slider', name: 'sphere radius r' });
    expect(await valueText(page, 'handle-r')).toMatch(/^r = 1; the ray hits/);
    // the radius grows with ↑ and shrinks with ↓ (a slider), and the value text follows; every
    // press counts, also three faster than frames (each steps on from the one before it)
    const rOf = async () => Number(/^r = ([\d.]+); /.exec(await valueText(page, 'handle-r'))?.[1]);
    await page.getByTestId('handle-r').focus();
    await page.keyboard.press('ArrowDown');
    await expect.poll(rOf).toBeLessThan(1);
    const r1 = await rOf();
    await pressFasterThanFrames(page, 'handle-r', 'ArrowDown', 3);
    await expect.poll(rOf).toBeCloseTo(r1 - 3 * (1 - r1), 6);
    // the direction tip, moved up by keys, turns the ray away: a miss, said by its value text
    await page.getByTestId('handle-tip').focus();
    for (let i = 0; i < 12; i++) await page.keyboard.press('ArrowUp');
    await waitForReadout(page, 'case', (v) => v === 'miss');
    await expect
      .poll(async () => await valueText(page, 'handle-tip'))
      .toMatch(/^d = \(.*\), at -?\d+° in the figure; the ray misses \(Δ = −/);
  });

  await test.step('the cross-section is a named figure whose description holds the live numbers and follows r', async () => {
    const o: V = [-3, 0.3, 0.2];
    await openScene(page, URL_OF(o, [1, 0, 0], 1, '&open=values'));
    const m = computeModel({ o, d: [1, 0, 0], c: [0, 0, 0], r: 1, method: 'stable' }).chosen!;
    await expect.poll(() => figDescription(page)).toContain(`Δ = ${n4(m.discriminant)} > 0`);
    const said = await figDescription(page);
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
    await expect
      .poll(() => figDescription(page))
      .toContain(`The ray misses: Δ = ${n4(miss.discriminant)} < 0`);
    const now = await figDescription(page);
    expect(now).toContain('passes 0.3606 from C, 0.1106 beyond the radius');
    expect(now).toContain('r = 0.25');
    // announced once settled
    await expect(page.getByTestId('live-region')).toHaveText(/The ray misses/, { timeout: 15_000 });
  });
});
