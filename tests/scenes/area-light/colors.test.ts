/**
 * The scene's own colours keep 3 : 1 (WCAG 1.4.11): the patch colour against the page and the panels
 * in both themes, the plot lines that follow the theme, and each light/dark pair of the 3D view
 * against the view's background of its theme.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { contrast, cssVars, parseHex } from '../../ui/colorVision';

const theme = readFileSync('src/ui/theme.css', 'utf8');
const sceneCss = readFileSync('src/scenes/area-light/area-light.css', 'utf8');
const LIGHT = { ...cssVars(theme, ':root'), ...cssVars(sceneCss, ':root') };
const DARK = { ...LIGHT, ...cssVars(theme, ":root[data-theme='dark']") };
const ratio = (a: string, b: string) => contrast(parseHex(a), parseHex(b));

describe('area-light colours', () => {
  it('the patch colour: ≥ 3 : 1 on the page and the panels in both themes', () => {
    for (const vars of [LIGHT, DARK]) {
      for (const bg of ['--bg', '--surface']) {
        expect(ratio(vars['--al-patch']!, vars[bg]!)).toBeGreaterThanOrEqual(3);
      }
    }
  });

  it('strokes and fills of the scene CSS use theme variables, not fixed colours', () => {
    const fixed = [...sceneCss.matchAll(/(?:stroke|fill):\s*(#[0-9a-fA-F]{3,6})/g)].map((m) => m[1]);
    expect(fixed).toEqual([]);
  });

  it('the Q6(a) plot draws in the patch colour', () => {
    const src = readFileSync('src/scenes/area-light/view/PatchErrorPlot.tsx', 'utf8');
    expect(src.match(/#[0-9a-fA-F]{6}\b/g)).toBeNull();
    expect(src).toContain("'var(--al-patch)'");
  });

  it('each light/dark colour pair of the 3D view: ≥ 3 : 1 on the view of its theme', () => {
    const src = readFileSync('src/scenes/area-light/view/Scene3D.tsx', 'utf8');
    const pairs = [...src.matchAll(/dk \? 0x([0-9a-f]{6}) : 0x([0-9a-f]{6})/g)];
    expect(pairs.length).toBeGreaterThanOrEqual(3);
    for (const [, dark, light] of pairs) {
      expect(ratio(`#${dark}`, DARK['--viewport-bg']!)).toBeGreaterThanOrEqual(3);
      expect(ratio(`#${light}`, LIGHT['--viewport-bg']!)).toBeGreaterThanOrEqual(3);
    }
  });
});
