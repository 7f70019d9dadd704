import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { texPreview, texPreviewParts, type PreviewPart } from '../../src/ui/texPreview';
import { NAMED_OPERATORS } from '../../src/ui/texSymbols';
import { filesUnder } from '../lint/sourceFiles';

describe('texPreview: TeX read as plain text while KaTeX is on its way', () => {
  it('reads the formulas of the exam as a person would write them', () => {
    expect(texPreview(String.raw`p(\omega) = k\cos\theta\,e^{\phi}`)).toBe('p(ω) = k cos θ e^φ');
    expect(texPreview(String.raw`k = \frac{2}{e^{2\pi} - 1}`)).toBe('k = 2/(e^(2π) − 1)');
    expect(texPreview(String.raw`\xi_1, \xi_2 \in [0, 1)`)).toBe('ξ₁, ξ₂ ∈ [0, 1)');
    expect(texPreview(String.raw`\theta = \arccos\sqrt{1 - \xi_1}`)).toBe('θ = arccos √(1 − ξ₁)');
    expect(texPreview(String.raw`\left(x + 2\right)^2`)).toBe('(x + 2)²');
    expect(texPreview(String.raw`\text{Var}[\hat I] \approx 1.23\times10^{-4}`)).toBe('Var[Î] ≈ 1.23×10⁻⁴');
    expect(texPreview(String.raw`t = \frac{-b \pm \sqrt{b^2 - 4ac}}{2a}`)).toBe('t = (−b ± √(b² − 4ac))/2a');
  });

  it('an aligned derivation: one line per row when displayed, spaces inline; environments and & disappear', () => {
    const tex = String.raw`\begin{aligned} a &= b \\[4pt] &= c \end{aligned}`;
    expect(texPreview(tex, true)).toBe('a = b\n= c');
    expect(texPreview(tex, false)).toBe('a = b = c');
    expect(texPreview(String.raw`\begin{array}{cc} 1 & 2 \end{array}`)).toBe('1 2');
  });

  it('keeps what it does not know, drops colour and sizing, and survives unbalanced input', () => {
    expect(texPreview(String.raw`\foo{x}`)).toBe('foox');
    expect(texPreview(String.raw`\color{red}{x} + \Big( y \Big)`)).toBe('x + (y)');
    expect(texPreview('a}b{c')).toBe('abc');
    expect(texPreview('x^')).toBe('x');
    expect(texPreview('\\')).toBe('');
    expect(texPreview(String.raw`\sqrt[3]{x}`)).toBe('√x');
  });

  it('never throws, and never returns a backslash for input made of known commands', () => {
    const known = [
      '\\alpha',
      '\\frac{1}{2}',
      '\\sqrt{x}',
      '\\int_0^1',
      '\\sum_{i=1}^{n}',
      '\\cdot',
      '\\left(',
      '\\right)',
      '\\text{ab}',
      '\\hat{x}',
      '\\\\',
      '&',
      'x^2',
      'y_i',
      '{',
      '}',
      ' ',
      'a',
      '1',
      '+',
      '=',
    ];
    fc.assert(
      fc.property(fc.array(fc.constantFrom(...known), { maxLength: 40 }), fc.boolean(), (parts, display) => {
        const out = texPreview(parts.join(''), display);
        expect(out).not.toContain('\\');
      }),
    );
    fc.assert(
      fc.property(fc.string({ maxLength: 200 }), fc.boolean(), (s, display) => {
        expect(typeof texPreview(s, display)).toBe('string');
      }),
    );
  });

  it('hostile input: long and deeply nested strings are read in one pass', () => {
    const deep = '{'.repeat(5000) + 'x' + '}'.repeat(5000);
    expect(texPreview(deep)).toBe('x');
    const long = '\\frac{a}{b}'.repeat(50_000);
    const t0 = performance.now();
    const out = texPreview(long);
    expect(performance.now() - t0).toBeLessThan(2000);
    expect(out.length).toBeGreaterThan(0);
  });
});

describe('texPreview under hostile nesting', () => {
  it('commands nested past the stack give back the source instead of throwing', () => {
    const tex = '\\frac{'.repeat(3000) + 'x' + '}{y}'.repeat(3000);
    const out = texPreview(tex);
    expect(typeof out).toBe('string');
    expect(texPreview('\\sqrt{'.repeat(20) + 'x' + '}'.repeat(20))).toBe(
      '√('.repeat(19) + '√x' + ')'.repeat(19),
    );
  });
});

describe('texPreview: the commands the scenes use', () => {
  it('line-break hints, boxes, arrows with labels and ticks read cleanly', () => {
    expect(texPreview(String.raw`a = 1,\allowbreak b = 2`)).toBe('a = 1, b = 2');
    expect(texPreview(String.raw`\colorbox{yellow}{x} \checkmark`)).toBe('x ✓');
    expect(texPreview(String.raw`a \xrightarrow{\text{swap}} b`)).toBe('a →(swap) b');
    expect(texPreview(String.raw`\begin{array}{c} 1 \\ \hline 2 \end{array}`, true)).toBe('1\n2');
    expect(texPreview(String.raw`\lVert o - C \rVert^2`)).toBe('‖o − C‖²');
  });

  it('every command in the scenes, the practice questions and the guide is read, never printed by name', async () => {
    const { readFileSync } = await import('node:fs');
    const files = ['src/scenes', 'src/practice', 'src/guide'].flatMap((d) => filesUnder(d, /\.tsx?$/));
    const names = new Set<string>();
    for (const f of files) {
      const text = readFileSync(f, 'utf8');
      // TeX in String.raw templates (\cmd) and in ordinary strings (\\cmd)
      for (const m of text.matchAll(/(?<![\\A-Za-z])\\{1,2}([A-Za-z]{2,})/g)) names.add(m[1]);
    }
    // JavaScript escapes and regular expressions, not TeX
    const notTex = (n: string) =>
      /^(n|b|u|t|r|s|d|w|x)[a-z]*$/.test(n) &&
      ![
        'theta',
        'tau',
        'times',
        'tan',
        'text',
        'tfrac',
        'to',
        'sin',
        'sum',
        'sqrt',
        'sim',
        'sigma',
        'delta',
        'dfrac',
        'big',
        'boldsymbol',
        'begin',
        'rangle',
        'rfloor',
        'rVert',
        'right',
        'rho',
        'xi',
        'xrightarrow',
        'nu',
        'neq',
        'nabla',
      ].includes(n);
    const used = [...names].filter((n) => !notTex(n));
    expect(used.length).toBeGreaterThan(30);
    for (const n of used) {
      const out = texPreview(`\\${n}{x}`);
      expect(out, `\\${n}`).not.toContain('\\');
      if (!NAMED_OPERATORS.has(n)) expect(out, `\\${n}`).not.toContain(n);
    }
  });
});

describe('texPreview: norms', () => {
  it('norm bars hug their contents and keep their distance from what is outside', () => {
    expect(
      texPreview(String.raw`\lVert p - C \rVert^2 = r^2 \Rightarrow \lVert o + t d - C \rVert^2 = r^2`),
    ).toBe('‖p − C‖² = r² ⇒ ‖o + t d − C‖² = r²');
    expect(texPreview(String.raw`c = \lVert o - C\rVert^2 - r^2`)).toBe('c = ‖o − C‖² − r²');
  });
});

/** The text a reader sees of the shown form (scripts as their text). */
const shown = (parts: PreviewPart[]): string =>
  parts.map((p) => (typeof p === 'string' ? p : shown(p.parts))).join('');

describe('texPreviewParts: the reading as shown, with no caret', () => {
  it('writes scripts in Unicode where it has every character, letters and the slash included', () => {
    expect(texPreviewParts(String.raw`p(\omega) = k\cos\theta\,e^{\phi}`)).toEqual(['p(ω) = k cos θ eᵠ']);
    expect(texPreviewParts(String.raw`x^{-1/2} = x^{-\frac{1}{2}}`)).toEqual(['x⁻¹ᐟ² = x⁻¹ᐟ²']);
    expect(texPreviewParts(String.raw`k \cos^m\theta\, e^{a\phi}`)).toEqual(['k cosᵐθ eᵃᵠ']);
    expect(texPreviewParts(String.raw`\theta_l`)).toEqual(['θₗ']);
  });

  it('sets the rest as <sup> / <sub> parts, nested as in the source', () => {
    expect(texPreviewParts(String.raw`k = \frac{2}{e^{2\pi} - 1}`)).toEqual([
      'k = 2/(e',
      { tag: 'sup', parts: ['2π'] },
      ' − 1)',
    ]);
    expect(texPreviewParts(String.raw`\cos\theta_{\text{light}}`)).toEqual([
      'cos θ',
      { tag: 'sub', parts: ['light'] },
    ]);
    expect(texPreviewParts(String.raw`e^{x^{\pi}}`)).toEqual([
      'e',
      { tag: 'sup', parts: ['x', { tag: 'sup', parts: ['π'] }] },
    ]);
  });

  it('the one-string form keeps its marks where Unicode lacks a script (the accessible name says them)', () => {
    expect(texPreview(String.raw`k = \frac{2}{e^{2\pi} - 1}`)).toBe('k = 2/(e^(2π) − 1)');
    expect(texPreview(String.raw`e^{x^{\pi}}`)).toBe('e^(x^π)');
    expect(texPreview(String.raw`\cos\theta_{\text{light}}`)).toBe('cos θ_light');
  });

  it('never shows a caret or an underscore for TeX made of known commands', () => {
    const known = ['\\alpha', '\\frac{1}{2}', '\\pi', 'x^2', 'y_i', 'e^{', '}', '_{', 'a', '1', '+', ' '];
    fc.assert(
      fc.property(fc.array(fc.constantFrom(...known), { maxLength: 40 }), fc.boolean(), (parts, display) => {
        const out = shown(texPreviewParts(parts.join(''), display));
        expect(out).not.toMatch(/[\^_]/);
      }),
    );
  });

  it('hostile input: scripts nested thousands deep, and the marks’ own characters in the source', () => {
    const deep = 'x^{'.repeat(3000) + 'π' + '}'.repeat(3000);
    const parts = texPreviewParts(deep);
    expect(shown(parts)).toBe('x'.repeat(3000) + 'π');
    let depth = 0;
    for (let p: PreviewPart | undefined = parts[1]; p && typeof p !== 'string'; p = p.parts[1]) depth++;
    expect(depth).toBeLessThan(5);
    expect(texPreview('a\u0001b\u0003c^{\u0002π}')).toBe('abc^π');
    expect(texPreviewParts('a\u0001b\u0003c^{\u0002π}')).toEqual(['abc', { tag: 'sup', parts: ['π'] }]);
  });
});
