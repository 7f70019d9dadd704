/**
 * Vite plugin: KaTeX's stylesheet in two parts, imported as `katex/dist/katex.min.css?fonts` (its
 * `@font-face` rules alone, each with its woff2 file only) and `katex/dist/katex.min.css?rules`
 * (everything else).
 *
 * Why: a stylesheet that brings `@font-face` rules makes the browser recompute the style and
 * layout of every element of the page (a font its text may use has changed), so the lazily loaded
 * KaTeX stylesheet cost a scene a full style recalculation and layout at the moment it arrived,
 * with the whole scene on the page (a 20–25 ms task in load traces here). The shell's own
 * stylesheet declares the faces instead: a declared face costs nothing until text uses it (the
 * browser downloads a font only then), and the lazy sheet, with no faces, restyles only the
 * formulas' elements.
 *
 * Only the woff2 source is kept: every browser that runs the app (ES2022) reads woff2, and it is
 * the one the offline cache holds.
 */
import { readFileSync } from 'node:fs';
import type { Plugin } from 'vite';

const FACE = /@font-face\s*\{[^}]*\}/g;

/** `css` split into its @font-face rules (woff2 sources only) and the rest. */
export function splitFontFaces(css: string): { fonts: string; rules: string } {
  const faces = css.match(FACE) ?? [];
  const fonts = faces
    .map((face) =>
      face.replace(/src\s*:\s*([^;}]*)/, (whole, list: string) => {
        const woff2 = list.split(/,(?=\s*url\()/).filter((s) => /format\(\s*["']?woff2["']?\s*\)/.test(s));
        return woff2.length ? `src:${woff2.map((s) => s.trim()).join(',')}` : whole;
      }),
    )
    .join('');
  return { fonts, rules: css.replace(FACE, '') };
}

const KATEX_CSS = /[\\/]katex[\\/]dist[\\/]katex(?:\.min)?\.css\?(fonts|rules)$/;

export function katexCssSplit(): Plugin {
  return {
    name: 'rml:katex-css-split',
    enforce: 'pre',
    load(id) {
      const m = KATEX_CSS.exec(id);
      if (!m) return null;
      const parts = splitFontFaces(readFileSync(id.slice(0, id.indexOf('?')), 'utf8'));
      return m[1] === 'fonts' ? parts.fonts : parts.rules;
    },
  };
}
