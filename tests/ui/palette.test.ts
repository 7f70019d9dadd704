/**
 * The colour-vision check of the palettes (WCAG 1.4.11 and 1.4.1): plot lines, the two Monte Carlo
 * strategies, the accents and the focus ring, read from src/ui/theme.css and src/ui/palette.css for
 * both themes, keep
 * 3 : 1 against the page and panel backgrounds, and the lines stay apart (CIEDE2000) in normal
 * vision and simulated protanopia, deuteranopia and tritanopia (Machado et al. 2009; Viénot et al.
 * 1999 for protan and deutan). The scenes' own hard-coded colours are listed at the end.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MACHADO, VIENOT, contrast, cssVars, deltaE2000, parseHex, simulate, type RGB } from './colorVision';
import { SERIES, STRATEGY_COLOR } from '../../src/ui/palette';

// the theme's colours, then the palette's (loaded after them)
const css = `${readFileSync('src/ui/theme.css', 'utf8')}\n${readFileSync('src/ui/palette.css', 'utf8')}`;
const LIGHT = cssVars(css, ':root');
const DARK = { ...LIGHT, ...cssVars(css, ":root[data-theme='dark']") };
const THEMES = { light: LIGHT, dark: DARK } as const;

/** A custom property's value, following var(--other) references. */
function value(vars: Record<string, string>, name: string, seen = 0): string {
  const v = vars[name];
  if (v === undefined) throw new Error(`${name} is not set`);
  const m = /^var\((--[\w-]+)\)$/.exec(v);
  return m && seen < 8 ? value(vars, m[1]!, seen + 1) : v;
}
const varName = (ref: string) => /^var\((--[\w-]+)\)$/.exec(ref)![1]!;

const VISIONS: { name: string; see: (c: RGB) => RGB }[] = [
  { name: 'normal vision', see: (c) => c },
  ...Object.entries(MACHADO).map(([k, m]) => ({ name: `${k} (Machado)`, see: (c: RGB) => simulate(c, m) })),
  ...Object.entries(VIENOT).map(([k, m]) => ({ name: `${k} (Viénot)`, see: (c: RGB) => simulate(c, m) })),
];

/** Smallest CIEDE2000 difference of any pair, as some reader sees them. */
function closestPair(colors: string[], see: (c: RGB) => RGB): { d: number; pair: string } {
  let best = { d: Infinity, pair: '' };
  for (let i = 0; i < colors.length; i++)
    for (let j = i + 1; j < colors.length; j++) {
      const d = deltaE2000(see(parseHex(colors[i]!)), see(parseHex(colors[j]!)));
      if (d < best.d) best = { d, pair: `${colors[i]} / ${colors[j]}` };
    }
  return best;
}

/** Lines this far apart (CIEDE2000) are told apart at a glance; 2.3 is a just-noticeable difference. */
const LINES_APART = 10;
/** The two strategies are compared side by side in one plot: they must be far apart. */
const STRATEGIES_APART = 30;

describe.each(Object.entries(THEMES))('the %s theme', (_theme, vars) => {
  const backgrounds = ['--bg', '--surface', '--surface-2'].map((n) => value(vars, n));
  const lines = SERIES.map((s) => value(vars, varName(s)));
  const strategies = [STRATEGY_COLOR.uniform, STRATEGY_COLOR.importance].map((s) => value(vars, varName(s)));

  it('plot lines, strategies, accents and the focus ring: ≥ 3 : 1 on every background', () => {
    const named = [
      ...SERIES.map(varName),
      varName(STRATEGY_COLOR.uniform),
      varName(STRATEGY_COLOR.importance),
      '--accent',
      '--accent-2',
      '--focus',
      '--ok',
    ];
    for (const n of named)
      for (const bg of backgrounds) {
        const c = contrast(parseHex(value(vars, n)), parseHex(bg));
        expect(c, `${n} ${value(vars, n)} on ${bg}`).toBeGreaterThanOrEqual(3);
      }
  });

  it.each(VISIONS)('plot lines stay apart in $name', ({ see }) => {
    const { d, pair } = closestPair(lines, see);
    expect(d, pair).toBeGreaterThanOrEqual(LINES_APART);
  });

  it.each(VISIONS)('the two Monte Carlo strategies stay far apart in $name', ({ see }) => {
    const { d, pair } = closestPair(strategies, see);
    expect(d, pair).toBeGreaterThanOrEqual(STRATEGIES_APART);
  });

  it('muted text keeps 4.5 : 1 (it carries captions and units)', () => {
    for (const bg of backgrounds)
      expect(contrast(parseHex(value(vars, '--muted')), parseHex(bg)), bg).toBeGreaterThanOrEqual(4.5);
  });
});

describe('the check itself', () => {
  it('fails a red/green pair under deuteranopia that normal vision tells apart', () => {
    const pair = ['#d03030', '#3a9a3a'];
    expect(closestPair(pair, (c) => c).d).toBeGreaterThan(LINES_APART);
    const deutan = VISIONS.find((v) => v.name.startsWith('deuteranopia (Machado'))!;
    expect(closestPair(pair, deutan.see).d).toBeLessThan(LINES_APART);
  });
});

/**
 * The scenes' own colours, hard-coded in their sources (not yet the shared palette): reported, with
 * the themes where they fall under 3 : 1 on the page background. Each scene moves its plot colours
 * to SERIES / STRATEGY_COLOR (or its own theme-aware CSS variables); the list only reports.
 */
describe('scene palettes (report)', () => {
  it('reads every scene plot file and lists its hard-coded colours under 3 : 1 on either theme', () => {
    const files = [
      'src/scenes/hemisphere/view/Q2Panel.tsx',
      'src/scenes/hemisphere/view/Plots.tsx',
      'src/scenes/hemisphere/view/InvertedJacobian.tsx',
      'src/scenes/monte-carlo/view/plotStyle.tsx',
      'src/scenes/ray-sphere/view/Precision.tsx',
      'src/scenes/ray-sphere/view/float32Traces.ts',
      'src/scenes/area-light/view/Explore.tsx',
      'src/scenes/area-light/view/PatchErrorPlot.tsx',
    ];
    const low: string[] = [];
    for (const f of files) {
      // a moved or renamed file fails here, so the report keeps covering the scenes' plots
      const src = readFileSync(f, 'utf8');
      for (const m of new Set(src.match(/#[0-9a-fA-F]{6}\b/g) ?? [])) {
        for (const [theme, vars] of Object.entries(THEMES)) {
          const c = contrast(parseHex(m), parseHex(value(vars, '--bg')));
          if (c < 3) low.push(`${f}: ${m} ${c.toFixed(2)}:1 on the ${theme} background`);
        }
      }
    }
    if (low.length)
      console.info(`Scene colours under 3:1 (move them to the shared palette):\n${low.join('\n')}`);
    expect(Array.isArray(low)).toBe(true);
  });
});
