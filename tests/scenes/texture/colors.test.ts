/**
 * The texture scene's tap colours where they sit on the page (the magnified cell and the list of
 * taps): each keeps 3 : 1 against the page and panel backgrounds in its theme (WCAG 1.4.11), and
 * the four stay four different colours. On the grid the bright set is drawn over the texture, whose
 * colours do not change with the theme.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { contrast, cssVars, deltaE2000, parseHex } from '../../ui/colorVision';

const ui = readFileSync('src/ui/theme.css', 'utf8');
const scene = readFileSync('src/scenes/texture/texture.css', 'utf8');
const stencil = readFileSync('src/scenes/texture/view/StencilDetail.css', 'utf8');
const LIGHT_UI = cssVars(ui, ':root');
const DARK_UI = { ...LIGHT_UI, ...cssVars(ui, ":root[data-theme='dark']") };
const LIGHT = cssVars(scene, '.scene-texture');
const DARK = { ...LIGHT, ...cssVars(scene, ":root[data-theme='dark'] .scene-texture") };
const TAPS = ['--tx-page-w00', '--tx-page-w10', '--tx-page-w01', '--tx-page-w11'];

describe.each([
  ['light', LIGHT, LIGHT_UI],
  ['dark', DARK, DARK_UI],
] as const)('the %s theme', (_theme, vars, uiVars) => {
  it('the taps on the page: ≥ 3 : 1 on --bg and --surface', () => {
    for (const tap of TAPS)
      for (const bg of ['--bg', '--surface']) {
        const c = contrast(parseHex(vars[tap]!), parseHex(uiVars[bg]!));
        expect(c, `${tap} ${vars[tap]} on ${bg}`).toBeGreaterThanOrEqual(3);
      }
  });

  it('the four taps stay apart', () => {
    for (let a = 0; a < TAPS.length; a++)
      for (let b = a + 1; b < TAPS.length; b++) {
        const d = deltaE2000(parseHex(vars[TAPS[a]!]!), parseHex(vars[TAPS[b]!]!));
        expect(d, `${TAPS[a]} / ${TAPS[b]}`).toBeGreaterThanOrEqual(10);
      }
  });
});

it('the magnified cell and the tap list use the page tones', () => {
  const row = cssVars(stencil, '.tx-closeup-row');
  for (const k of ['00', '10', '01', '11']) expect(row[`--tx-w${k}`]).toBe(`var(--tx-page-w${k})`);
});

it('the check itself fails the bright yellow on the light page', () => {
  expect(contrast(parseHex('#ffc914'), parseHex(LIGHT_UI['--surface']!))).toBeLessThan(3);
});
