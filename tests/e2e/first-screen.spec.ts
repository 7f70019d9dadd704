/**
 * The first screen first, on every scene of the catalogue: while a scene opens on a phone, the
 * work that belongs to the page far below the screen (exam sections mounted late by
 * src/ui/Deferred.tsx, formulas typeset by src/ui/MathTex.tsx) waits until the page has settled
 * (`data-settled` on <html>, src/ui/whenQuiet.ts's pageSettled); then all of it is done without a
 * scroll. A reader who acts sooner (here a turn of the mouse wheel) gets it at once. Done
 * earlier, in the idle moments between the opening's own frames, it competed with the opening for
 * the phone's cores and stretched its tasks.
 *
 * The page's own observer says what is near; the test's observer, with a wider margin than any of
 * the page's, says what was certainly far: an element it last saw outside that margin must not
 * change before the page has settled.
 */
import { SCENES } from '../../src/kit/catalogue';
import { test, expect } from './fixtures';

test.use({ viewport: { width: 412, height: 823 } });

interface FirstScreen {
  /** far elements (sections, formulas) seen while the page was opening */
  farSeen: number;
  /** far ones that mounted or were typeset before the page settled: "section" / "formula" */
  early: string[];
  settled: boolean;
}

test('while a scene opens, nothing far below the first screen is mounted or typeset before the page settles; after it, or at once when the reader acts, every section mounts', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await page.addInitScript(() => {
    const rec = { farSeen: 0, early: [] as string[], settled: false };
    (window as unknown as { __firstScreen: typeof rec }).__firstScreen = rec;
    /** last report per element: true near, false far (no entry: not reported yet) */
    const near = new WeakMap<Element, boolean>();
    // wider than the page's own margins (800 px for sections, 600 px for formulas)
    const io = new IntersectionObserver(
      (entries) => {
        for (const e of entries) {
          if (!e.isIntersecting && !near.has(e.target)) rec.farSeen++;
          near.set(e.target, e.isIntersecting);
        }
      },
      { rootMargin: '1000px 0px' },
    );
    const watch = (root: Node) => {
      if (!(root instanceof Element)) return;
      const els = [root, ...root.querySelectorAll('[data-deferred="pending"], .math-pending')];
      for (const el of els) if (el.matches('[data-deferred="pending"], .math-pending')) io.observe(el);
    };
    const early = (el: Element, what: string) => {
      if (!rec.settled && near.get(el) === false) rec.early.push(what);
    };
    new MutationObserver((muts) => {
      for (const m of muts) {
        if (m.type === 'attributes' && m.attributeName === 'data-settled') {
          rec.settled = document.documentElement.hasAttribute('data-settled');
        } else if (m.type === 'attributes' && m.attributeName === 'class') {
          const el = m.target as Element;
          if (/\bmath-pending\b/.test(m.oldValue ?? '') && !el.classList.contains('math-pending'))
            early(el, 'formula');
          else if (el.classList.contains('math-pending')) watch(el);
        } else {
          for (const n of m.removedNodes)
            if (n instanceof Element && n.matches('[data-deferred="pending"]')) early(n, 'section');
          for (const n of m.addedNodes) watch(n);
        }
      }
    }).observe(document, {
      subtree: true,
      childList: true,
      attributes: true,
      attributeOldValue: true,
      attributeFilter: ['class', 'data-settled'],
    });
  });

  for (const s of SCENES) {
    await test.step(s.id, async () => {
      // a new document each time: the page settles once per load
      await page.goto('about:blank');
      await page.goto(`./#${s.path}${s.examQuery ? `?${s.examQuery}` : ''}`);
      await page.waitForSelector('main#main');
      await expect(page.locator('html[data-settled]')).toBeAttached({ timeout: 60_000 });
      // with no scroll, every section below the screen mounts once the page has settled
      await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
      const rec = await page.evaluate(
        () => (window as unknown as { __firstScreen: FirstScreen }).__firstScreen,
      );
      expect(await page.evaluate(() => scrollY), 'the page was not scrolled').toBe(0);
      expect(rec.early, `${s.id}: far sections or formulas done before the page settled`).toEqual([]);
      expect(rec.farSeen, `${s.id}: the page has work far below its first screen`).toBeGreaterThan(0);
    });
  }

  await test.step('a reader who acts before the page settles gets the far sections at once', async () => {
    // a frame requested every frame: no idle period is a whole one, so the page cannot settle by
    // being quiet (only by pageSettled's 3 s cap), and the reader's act is what opens the far work
    await page.addInitScript(() => {
      const frame = () => requestAnimationFrame(frame);
      frame();
    });
    await page.goto('about:blank');
    await page.goto('./#/hemisphere');
    await page.waitForSelector('main#main .exam-part');
    const read = () =>
      page.evaluate(() => (window as unknown as { __firstScreen: FirstScreen }).__firstScreen);
    // (a machine too slow to show the page before it settles cannot tell the two apart)
    test.skip((await read()).settled, 'the page settled before it could be acted on');
    await page.mouse.wheel(0, 0); // a turn of the wheel that scrolls nothing
    await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 60_000 });
    // far sections mounted before the page settled: the reader's act opened the idle time
    expect((await read()).early.filter((w) => w === 'section').length).toBeGreaterThan(0);
  });
});
