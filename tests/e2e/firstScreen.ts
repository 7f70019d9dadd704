/**
 * The first screen first: while a page opens, the work that belongs to it far below the screen
 * (exam sections mounted late by src/ui/Deferred.tsx, formulas typeset by src/ui/MathTex.tsx) waits
 * until the page has settled (`data-settled` on <html>, src/ui/whenQuiet.ts's pageSettled) unless
 * the reader acts first. Done earlier, in the idle moments between the opening's own frames, it
 * competed with the opening for a phone's cores and stretched its tasks.
 *
 * The opened scene's first paint is the scene itself, not the shell saying "Loading the scene…"
 * (src/app/main.tsx waits for the scene's chunk before the first render).
 *
 * `recordFirstScreen` installs, before the page's own scripts run, a recorder of what changed far
 * from the screen before the page settled; the page's reader then only looks (the fixtures' reader
 * who acts at once stays away: ./fixtures.ts `readerActs`). The page's own observers say what is
 * near; the recorder's observer, with a wider margin than any of the page's, says what was
 * certainly far: an element it last saw outside that margin must not change before the page has
 * settled.
 */
import type { Page } from '@playwright/test';

export interface FirstScreen {
  /** far elements (sections, formulas) seen while the page was opening */
  farSeen: number;
  /** far ones that mounted ("section") or were typeset ("formula") before the page settled */
  early: string[];
  /** whether the page has settled */
  settled: boolean;
  /** whether the shell was shown without its scene ("Loading the scene…") */
  loadingShown: boolean;
}

/** Records, from the next document's first script on, what is done far below the screen early. */
export async function recordFirstScreen(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const rec = { farSeen: 0, early: [] as string[], settled: false, loadingShown: false };
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
      if (root.matches('.loading') || root.querySelector('.loading')) rec.loadingShown = true;
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
}

/** What the recorder saw so far. */
export function firstScreen(page: Page): Promise<FirstScreen> {
  return page.evaluate(() => (window as unknown as { __firstScreen: FirstScreen }).__firstScreen);
}
