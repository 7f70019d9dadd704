/**
 * The hemisphere page as it opens: beside the figure only N and the statistics' state, the other
 * settings folded (and not rendered) under "More settings"; on the classroom stage's drawer every
 * control. And a derivation's formula box is a tab stop exactly while it overflows (scrolls).
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/hemisphere/params';
import { Settings } from '../../../src/scenes/hemisphere/view/Settings';
import { focusOverflowing } from '../../../src/scenes/hemisphere/view/scrollFocus';

const params = parseParams(schema, '').values;
const stats = { result: null, running: false, waiting: true, progress: 0 };
const render = (folded: boolean) =>
  renderToStaticMarkup(
    <Settings
      params={params}
      setParams={() => {}}
      pdfError={null}
      stats={stats}
      folded={folded}
      more={<span data-testid="figure-options" />}
    />,
  );

describe('Settings', () => {
  it('on the page: N and the state show; density, Jacobian, point set, seed and the figure’s options wait in a closed fold', () => {
    const html = render(true);
    expect(html).toContain('data-testid="n"');
    expect(html).toContain('data-testid="stats-status"');
    expect(html).toMatch(/<details[^>]*data-fold="settings"/);
    expect(html).not.toMatch(/<details[^>]*\sopen/);
    for (const id of ['lobe', 'jacobian', 'points', 'figure-options'])
      expect(html, id).not.toContain(`data-testid="${id}"`);
    expect(html).not.toContain('>Seed<');
  });

  it('on the stage’s drawer: every control, nothing folded', () => {
    const html = render(false);
    for (const id of ['lobe', 'jacobian', 'points', 'n', 'figure-options', 'stats-status'])
      expect(html, id).toContain(`data-testid="${id}"`);
    expect(html).toContain('>Seed<');
    expect(html).not.toContain('<details');
  });
});

/** A formula box as focusOverflowing sees it: its widths and its attributes. */
function box(scrollWidth: number, clientWidth: number, tabindex = false) {
  const attrs = new Map<string, string>(tabindex ? [['tabindex', '0']] : []);
  return {
    scrollWidth,
    clientWidth,
    hasAttribute: (n: string) => attrs.has(n),
    setAttribute: (n: string, v: string) => void attrs.set(n, v),
    removeAttribute: (n: string) => void attrs.delete(n),
    attrs,
  };
}

describe('focusOverflowing', () => {
  it('gives a tab stop to the boxes whose formula is wider than they are, and takes it from the others', () => {
    const wide = box(520, 300);
    const fits = box(300, 300, true);
    const rounding = box(301, 300); // a sub-pixel difference is no overflow
    const boxes = [wide, fits, rounding];
    const root = { querySelectorAll: (sel: string) => (sel === '.deriv-formula' ? boxes : []) };
    focusOverflowing(root as unknown as ParentNode);
    expect(wide.attrs.get('tabindex')).toBe('0');
    expect(fits.attrs.has('tabindex')).toBe(false);
    expect(rounding.attrs.has('tabindex')).toBe(false);
    // the window widens: the wide one fits now
    wide.clientWidth = 600;
    focusOverflowing(root as unknown as ParentNode);
    expect(wide.attrs.has('tabindex')).toBe(false);
  });

  it('measures every box before it changes any (a change between two measurements lays the page out again)', () => {
    const log: string[] = [];
    const logged = (w: number, c: number, tab: boolean) => {
      const b = box(w, c, tab);
      return {
        get scrollWidth() {
          log.push('read');
          return b.scrollWidth;
        },
        get clientWidth() {
          return b.clientWidth;
        },
        hasAttribute: b.hasAttribute,
        setAttribute: (n: string, v: string) => {
          log.push('write');
          b.setAttribute(n, v);
        },
        removeAttribute: (n: string) => {
          log.push('write');
          b.removeAttribute(n);
        },
      };
    };
    const boxes = [logged(520, 300, false), logged(300, 300, true), logged(700, 300, false)];
    const root = { querySelectorAll: (sel: string) => (sel === '.deriv-formula' ? boxes : []) };
    focusOverflowing(root as unknown as ParentNode);
    expect(log.filter((x) => x === 'write')).toHaveLength(3);
    expect(log.lastIndexOf('read')).toBeLessThan(log.indexOf('write'));
  });
});
