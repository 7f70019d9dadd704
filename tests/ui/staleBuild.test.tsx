/**
 * A lazy route whose chunk (or its stylesheet) cannot be loaded: it reloads onto a newer build once,
 * and otherwise says what happened; it never leaves the page blank.
 */
import { describe, expect, it } from 'vitest';
import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { shouldReload } from '../../src/ui/staleBuild';
import { loadPage } from '../../src/ui/lazyPage';

const HERE = 'https://lab.example/#/results';
const NOW = 1_800_000_000_000;
const guard = (href: string, at: number) => JSON.stringify({ href, at });

describe('after a chunk failed to load', () => {
  it('reloads only onto a newer build, and not twice a minute for one address', () => {
    expect(shouldReload(false, null, HERE, NOW)).toBe(false);
    expect(shouldReload(true, null, HERE, NOW)).toBe(true);
    expect(shouldReload(true, guard(HERE, NOW - 5_000), HERE, NOW)).toBe(false);
    expect(shouldReload(true, guard(HERE, NOW - 61_000), HERE, NOW)).toBe(true);
    expect(shouldReload(true, guard('https://lab.example/#/guide', NOW - 5_000), HERE, NOW)).toBe(true);
    for (const junk of ['{', '[]', '"x"', '{"href":1,"at":"now"}', 'null'])
      expect(shouldReload(true, junk, HERE, NOW)).toBe(true);
  });

  it('a page that cannot be loaded, with no reload to follow, says so', async () => {
    const cssGone = () => Promise.reject(new Error('Unable to preload CSS for /assets/Guide-x.css'));
    for (const what of ['The class results page', 'The guide']) {
      const page = await loadPage(cssGone, what, (load) => load());
      const html = renderToStaticMarkup(createElement(page.default));
      expect(html).toContain('data-testid="route-load-failed"');
      expect(html).toContain(`${what} could not be loaded`);
      expect(html).toMatch(/<button[^>]*>reload<\/button>/);
    }
  });

  it('a page that loads is the page', async () => {
    const Page = () => createElement('h1', null, 'Class results');
    const page = await loadPage(() => Promise.resolve({ default: Page }), 'The class results page');
    expect(renderToStaticMarkup(createElement(page.default))).toBe('<h1>Class results</h1>');
  });
});
