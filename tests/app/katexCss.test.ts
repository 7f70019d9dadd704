import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { describe, expect, it } from 'vitest';
import { splitFontFaces } from '../../scripts/katexCss';

const katexCss = readFileSync(createRequire(import.meta.url).resolve('katex/dist/katex.min.css'), 'utf8');

describe('splitFontFaces: KaTeX’s font faces declared apart from its other rules', () => {
  it('keeps each face with its woff2 source alone, and every other rule in the rest', () => {
    const css =
      '@font-face{font-family:A;src:url(a.woff2) format("woff2"),url(a.woff) format("woff"),url(a.ttf) format("truetype")}' +
      ".k{color:red}@font-face{font-family:B;font-weight:700;src:url(b.woff2) format('woff2')}" +
      '@media print{.k{color:black}}';
    const { fonts, rules } = splitFontFaces(css);
    expect(fonts).toBe(
      '@font-face{font-family:A;src:url(a.woff2) format("woff2")}' +
        "@font-face{font-family:B;font-weight:700;src:url(b.woff2) format('woff2')}",
    );
    expect(rules).toBe('.k{color:red}@media print{.k{color:black}}');
  });

  it('a face with no woff2 source keeps the sources it has', () => {
    const css = '@font-face{font-family:C;src:url(c.woff) format("woff")}';
    expect(splitFontFaces(css).fonts).toBe(css);
  });

  it('on KaTeX’s own stylesheet: every face, each with one woff2 file; the rest has no face and loses no rule', () => {
    const faces = katexCss.match(/@font-face\{[^}]*\}/g) ?? [];
    expect(faces.length).toBeGreaterThan(10);
    const { fonts, rules } = splitFontFaces(katexCss);
    const kept = fonts.match(/@font-face\{[^}]*\}/g) ?? [];
    expect(kept).toHaveLength(faces.length);
    for (const f of kept) expect(f).toMatch(/src:url\([^)]*\.woff2\) ?format\("woff2"\)\}$/);
    expect(fonts).not.toMatch(/\.woff\)|\.ttf\)/);
    expect(rules).not.toContain('@font-face');
    expect(rules.length + faces.join('').length).toBe(katexCss.length);
    expect(rules).toContain('.katex{');
  });
});
