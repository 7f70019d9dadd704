/**
 * The Monte Carlo scene's own colours (WCAG 1.4.11): its stylesheet names no colour of its own (only
 * the theme's and the shared palette's variables), the bars of the histogram of estimates keep
 * 3 : 1 on the page and panel backgrounds in both themes at their opacity, and the race's light
 * bars carry an outline in the lane's full colour.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { contrast, cssVars, parseHex, type RGB } from '../../ui/colorVision';
import { BAR_OPACITY, COLORS } from '../../../src/scenes/monte-carlo/view/plotStyle';

const themeCss = `${readFileSync('src/ui/theme.css', 'utf8')}\n${readFileSync('src/ui/palette.css', 'utf8')}`;
const sceneCss = readFileSync('src/scenes/monte-carlo/monte-carlo.css', 'utf8');
const LIGHT = cssVars(themeCss, ':root');
const DARK = { ...LIGHT, ...cssVars(themeCss, ":root[data-theme='dark']") };

function value(vars: Record<string, string>, name: string): string {
  const v = vars[name];
  if (v === undefined) throw new Error(`${name} is not set`);
  const m = /^var\((--[\w-]+)\)$/.exec(v);
  return m ? value(vars, m[1]!) : v;
}
/** fg drawn at `alpha` over bg (sRGB, 0…1, as browsers blend). */
const over = (fg: RGB, bg: RGB, alpha: number): RGB =>
  fg.map((c, k) => alpha * c + (1 - alpha) * bg[k]!) as RGB;

describe('the Monte Carlo scene’s colours', () => {
  it('its stylesheet uses only variables for colour', () => {
    const css = sceneCss.replace(/\/\*[\s\S]*?\*\//g, '');
    expect(css.match(/#[0-9a-f]{3,8}\b|rgba?\(|hsla?\(/gi)).toBeNull();
  });

  describe.each([
    ['light', LIGHT],
    ['dark', DARK],
  ] as const)('the %s theme', (_name, vars) => {
    it('the histogram of estimates: its bars ≥ 3 : 1 on --bg and --surface', () => {
      const bar = parseHex(value(vars, /^var\((--[\w-]+)\)$/.exec(COLORS[0])![1]!));
      for (const bg of ['--bg', '--surface']) {
        const back = parseHex(value(vars, bg));
        expect(contrast(over(bar, back, BAR_OPACITY), back), bg).toBeGreaterThanOrEqual(3);
      }
    });
  });

  it('the race’s bars are outlined (their fill alone is lighter than 3 : 1)', () => {
    const rule = /\.mc-svg-bars\s*\{([^}]*)\}/.exec(sceneCss)?.[1] ?? '';
    expect(rule).toMatch(/stroke-width:\s*[1-9]/);
    expect(rule).not.toMatch(/stroke:\s*none/);
    const src = readFileSync('src/scenes/monte-carlo/view/RaceHistogram.tsx', 'utf8');
    expect(src).toMatch(/className="mc-svg-bars"\s+style=\{\{ fill: color, stroke: color \}\}/);
  });
});
