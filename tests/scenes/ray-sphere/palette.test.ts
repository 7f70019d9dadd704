/**
 * The ray–sphere scene's own colours (WCAG 1.4.11): the plot colours of ray-sphere.css keep 3 : 1
 * (text colours 4.5 : 1) against the page and panel backgrounds in both themes, the 3D view's
 * colours are the cross-section's CSS variables and keep 3 : 1 on the viewport, and no scene file
 * draws a line in a colour of its own outside those.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { contrast, cssVars, parseHex } from '../../ui/colorVision';
import { filesUnder } from '../../lint/sourceFiles';
import { VIEW3D_COLOURS } from '../../../src/scenes/ray-sphere/view/View3D';
import { ERROR_COLOURS } from '../../../src/scenes/ray-sphere/view/errorCurves';

const SCENE = 'src/scenes/ray-sphere';
const sceneCss = readFileSync(`${SCENE}/ray-sphere.css`, 'utf8');
const css = [
  readFileSync('src/ui/theme.css', 'utf8'),
  readFileSync('src/ui/palette.css', 'utf8'),
  sceneCss,
].join('\n');
const LIGHT = cssVars(css, ':root');
const THEMES = { light: LIGHT, dark: { ...LIGHT, ...cssVars(css, ":root[data-theme='dark']") } } as const;

/** A custom property's value, following var(--other) references. */
function value(vars: Record<string, string>, name: string, depth = 0): string {
  const v = vars[name];
  if (v === undefined) throw new Error(`${name} is not set`);
  const m = /^var\((--[\w-]+)\)$/.exec(v);
  return m && depth < 8 ? value(vars, m[1]!, depth + 1) : v;
}

const sceneVars = Object.keys(cssVars(sceneCss, ':root'));
const TEXT = ['--rs-tangent-text', '--rs-meh-text', '--rs-hole-text'];
const hex = (n: number) => `#${n.toString(16).padStart(6, '0')}`;

describe.each(Object.entries(THEMES))('the %s theme', (_theme, vars) => {
  const backgrounds = ['--bg', '--surface'].map((n) => value(vars, n));

  it('every scene colour: ≥ 3 : 1 on the page and the panels (text ≥ 4.5 : 1)', () => {
    expect(sceneVars.length).toBeGreaterThan(8);
    for (const n of sceneVars)
      for (const bg of backgrounds) {
        const c = contrast(parseHex(value(vars, n)), parseHex(bg));
        expect(c, `${n} ${value(vars, n)} on ${bg}`).toBeGreaterThanOrEqual(TEXT.includes(n) ? 4.5 : 3);
      }
  });

  it('the error plot uses only the scene colours', () => {
    for (const ref of Object.values(ERROR_COLOURS)) {
      const name = /^var\((--rs-[\w-]+)\)$/.exec(ref)?.[1];
      expect(name && sceneVars.includes(name), ref).toBe(true);
    }
  });
});

describe('the 3D view', () => {
  it.each(['light', 'dark'] as const)('%s: the cross-section’s colours, ≥ 3 : 1 on the viewport', (theme) => {
    const vars = THEMES[theme];
    const pal = VIEW3D_COLOURS[theme];
    const same = { ray: '--accent', root: '--accent-2', behind: '--muted', origin: '--fg' } as const;
    for (const [k, n] of Object.entries(same))
      expect(hex(pal[k as keyof typeof same]), k).toBe(value(vars, n));
    const bg = parseHex(value(vars, '--viewport-bg'));
    for (const [k, c] of Object.entries(pal))
      expect(contrast(parseHex(hex(c)), bg), k).toBeGreaterThanOrEqual(3);
  });
});

describe('hard-coded colours', () => {
  it('no hex colour in the scene’s stylesheet outside its theme blocks, none in its plot code', () => {
    const rules = sceneCss.replace(/:root(\[data-theme='dark'\])?\s*\{[^}]*\}/g, '');
    expect(rules.match(/#[0-9a-f]{3,8}\b/gi) ?? []).toEqual([]);
    const found = filesUnder(SCENE, /\.tsx?$/).flatMap((f) =>
      (readFileSync(f, 'utf8').match(/['"`]#[0-9a-f]{3,8}['"`]/gi) ?? []).map((m) => `${f}: ${m}`),
    );
    expect(found).toEqual([]);
  });
});
