/**
 * What a reader meets on a page, counted the way a keyboard user meets it: tab stops (links,
 * buttons, fields, summaries, anything with tabindex ≥ 0) that are shown and enabled, a radio group
 * counting once (one Tab enters it, arrows move inside), the site header left out (it is the same
 * on every page). `firstScreen` counts those that show, at least in part, in the first screen
 * (scrolled to the top); `page` every one on the page as it is (folded parts closed). `screens` is
 * the page's height in screens.
 *
 * A plot's tool buttons (zoom, reset, save) are drawn only once the plot has come near the screen,
 * so whether they are there depends on how far the page has been scrolled and how fast the machine
 * is. They are left out of the walk and counted instead as `toolStops` per plot (`figure.plot`,
 * ../../src/ui/Plot.tsx), drawn or not: the count is the same on every machine.
 *
 * The function runs in the page (page.evaluate), so it must not use anything from its module scope.
 */
export interface CalmCount {
  firstScreen: number;
  page: number;
  screens: number;
  /** A short description of each tab stop in the first screen, to say what to fold. */
  first: string[];
}

export function countTabStops(toolStops: number): CalmCount {
  const selector =
    'a[href], button, input, select, textarea, summary, iframe, audio[controls], video[controls], [tabindex], [contenteditable="true"]';
  const seenRadio = new Set<string>();
  let firstScreen = 0;
  let page = 0;
  const first: string[] = [];
  const top = window.scrollY;
  for (const el of Array.from(document.querySelectorAll<HTMLElement>(selector))) {
    if (el.closest('.site-header, [inert], [hidden], [aria-hidden="true"], .plot-tools')) continue;
    if (el.tabIndex < 0) continue;
    if ((el as HTMLButtonElement).disabled) continue;
    if (el instanceof HTMLInputElement && el.type === 'hidden') continue;
    const rects = el.getClientRects();
    if (rects.length === 0) continue;
    const style = getComputedStyle(el);
    if (style.visibility === 'hidden') continue;
    // a summary's details inside a closed details is not rendered (no rects): already skipped
    if (el instanceof HTMLInputElement && el.type === 'radio') {
      const key = `${el.form ? 'f' : ''}:${el.name || el.id}`;
      if (el.name && seenRadio.has(key)) continue;
      seenRadio.add(key);
    }
    page++;
    const r = el.getBoundingClientRect();
    const y0 = r.top + window.scrollY - top;
    if (y0 < window.innerHeight && y0 + r.height > 0) {
      firstScreen++;
      const label =
        el.getAttribute('aria-label') ||
        el.getAttribute('data-testid') ||
        (el.textContent ?? '').trim().slice(0, 30) ||
        el.tagName.toLowerCase();
      first.push(`${el.tagName.toLowerCase()}:${label}`);
    }
  }
  for (const plot of Array.from(document.querySelectorAll<HTMLElement>('figure.plot'))) {
    if (plot.closest('.site-header, [inert], [hidden], [aria-hidden="true"]')) continue;
    if (plot.getClientRects().length === 0) continue;
    page += toolStops;
    const r = plot.getBoundingClientRect();
    const y0 = r.top + window.scrollY - top;
    if (y0 < window.innerHeight && y0 + r.height > 0) {
      firstScreen += toolStops;
      first.push(`plot tools:${plot.getAttribute('aria-label') ?? ''} (${toolStops})`);
    }
  }
  return {
    firstScreen,
    page,
    screens: Math.round((document.documentElement.scrollHeight / window.innerHeight) * 10) / 10,
    first,
  };
}
