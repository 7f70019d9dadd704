/**
 * The hemisphere scene's colours (WCAG 1.4.11): every plot line, marker and bar keeps 3 : 1 against
 * the page and panel backgrounds in both themes, the see-through bars composited over them; the plot
 * files take their colours from ./view/plotColors (no colour written into them by hand); and the
 * (ξ₁, ξ₂) colours of the points and grid, as drawn in each theme, keep 3 : 1 on the 3D view's and
 * the panels' backgrounds over the whole unit square.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { contrast, cssVars, parseHex, type RGB } from '../../ui/colorVision';
import {
  BAR_OPACITY,
  IMPORTANCE,
  MODEL,
  REFERENCE,
  SAMPLED,
  UNIFORM,
} from '../../../src/scenes/hemisphere/view/plotColors';
import { pointShade, xiColor } from '../../../src/scenes/hemisphere/view/colors';

const css = `${readFileSync('src/ui/theme.css', 'utf8')}\n${readFileSync('src/ui/palette.css', 'utf8')}`;
const LIGHT = cssVars(css, ':root');
const THEMES = { light: LIGHT, dark: { ...LIGHT, ...cssVars(css, ":root[data-theme='dark']") } };

/** A `var(--x)` reference's colour in a theme, following references. */
function resolve(vars: Record<string, string>, ref: string, depth = 0): string {
  const m = /^var\((--[\w-]+)\)$/.exec(ref.trim());
  if (!m) return ref;
  const v = vars[m[1]!];
  if (v === undefined) throw new Error(`${m[1]} is not set`);
  return depth < 8 ? resolve(vars, v, depth + 1) : v;
}

const over = (c: RGB, bg: RGB, alpha: number): RGB =>
  c.map((x, i) => alpha * x + (1 - alpha) * bg[i]!) as RGB;

const LINES = { SAMPLED, MODEL, REFERENCE, UNIFORM, IMPORTANCE };
const BARS = { SAMPLED, UNIFORM, IMPORTANCE };

describe.each(Object.entries(THEMES))('the %s theme', (_theme, vars) => {
  const backgrounds = ['--bg', '--surface'].map((n) => parseHex(resolve(vars, `var(${n})`)));

  it('lines and markers: ≥ 3 : 1 on the page and panel backgrounds', () => {
    for (const [name, ref] of Object.entries(LINES))
      for (const bg of backgrounds)
        expect(contrast(parseHex(resolve(vars, ref)), bg), name).toBeGreaterThanOrEqual(3);
  });

  it(`bars at opacity ${BAR_OPACITY}: ≥ 3 : 1 once composited over each background`, () => {
    for (const [name, ref] of Object.entries(BARS))
      for (const bg of backgrounds)
        expect(
          contrast(over(parseHex(resolve(vars, ref)), bg, BAR_OPACITY), bg),
          name,
        ).toBeGreaterThanOrEqual(3);
  });
});

describe.each(Object.entries(THEMES))('the (ξ₁, ξ₂) colours in the %s theme', (theme, vars) => {
  it('≥ 3 : 1 on the 3D view, the page and the panels, everywhere in the square', () => {
    const shade = pointShade(theme === 'dark');
    const backgrounds = ['--viewport-bg', '--bg', '--surface'].map((n) =>
      parseHex(resolve(vars, `var(${n})`)),
    );
    const rgb = [0, 0, 0];
    let least = Infinity;
    for (let i = 0; i <= 16; i++)
      for (let j = 0; j <= 16; j++) {
        xiColor(i / 16, j / 16, rgb);
        const c = rgb.map((x) => x * shade) as RGB;
        for (const bg of backgrounds) least = Math.min(least, contrast(c, bg));
      }
    expect(least).toBeGreaterThanOrEqual(3);
  });
});

it('the plot files write no colour of their own', () => {
  for (const f of ['Q2Panel', 'InvertedJacobian', 'Plots', 'CdfPlots']) {
    const src = readFileSync(`src/scenes/hemisphere/view/${f}.tsx`, 'utf8');
    expect(src.match(/#[0-9a-fA-F]{3,8}\b|rgba?\(/g), f).toBeNull();
  }
});

it('the check fails a colour under 3 : 1', () => {
  const white = parseHex('#ffffff');
  expect(contrast(over(parseHex('#1f5fa8'), white, 0.4), white)).toBeLessThan(3);
});
