/**
 * The derivations' key formulas, typeset to MathML by KaTeX as the page does (with the speech
 * tidying of src/ui/mathmlSpeech.ts), read by speech-rule-engine, the engine behind ChromeVox's and
 * MathJax's speech: each must be heard as the formula it is.
 */
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import katex from 'katex';
import * as sreModule from 'speech-rule-engine';
import { KATEX_OPTIONS } from '../../src/ui/katexOptions';
import { speakableMathml } from '../../src/ui/mathmlSpeech';
import { previewLabel } from '../../src/ui/texPreview';

// CommonJS: under vitest its functions may sit on the default export
const sre = (sreModule as unknown as { default?: typeof sreModule }).default ?? sreModule;

/** The formulas and the scene files they come from (as the source writes them in a template literal). */
const FORMULAS = {
  normalization: { tex: String.raw`k = \frac{2}{e^{2\pi}-1}`, file: 'src/scenes/hemisphere/exam/Q1.tsx' },
  thetaInversion: {
    tex: String.raw`\theta = \tfrac12\cos^{-1}(1-2\xi_1)`,
    file: 'src/scenes/hemisphere/exam/Q1.tsx',
  },
  thetaInversionAsin: {
    tex: String.raw`\theta = \sin^{-1}\!\sqrt{\xi_1}`,
    file: 'src/scenes/hemisphere/exam/Q1.tsx',
  },
  phiInversion: {
    tex: String.raw`\phi = \ln\!\big[(e^{2\pi}-1)\,\xi_2 + 1\big]`,
    file: 'src/scenes/hemisphere/exam/Q1.tsx',
  },
  discriminant: { tex: String.raw`\Delta = b^2 - 4ac`, file: 'src/scenes/ray-sphere/exam/Q5Derivation.tsx' },
  roots: {
    tex: String.raw`t = \frac{-b \pm \sqrt{\Delta}}{2a}`,
    file: 'src/scenes/ray-sphere/exam/Q5Derivation.tsx',
  },
  solidAngle: {
    tex: String.raw`d\omega = \dfrac{dA\cos\theta_l}{r^2}`,
    file: 'src/scenes/area-light/exam/Q6a.tsx',
  },
  estimator: {
    tex: String.raw`\langle I\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f(X_i)}{p(X_i)}`,
    file: 'src/scenes/hemisphere/exam/Q2.tsx',
  },
} as const;

/** The MathML KaTeX gives the page for `tex` (its HTML part is aria-hidden). */
function pageMathml(tex: string, tidy = true): string {
  const html = katex.renderToString(tex, { ...KATEX_OPTIONS, displayMode: true });
  const out = tidy ? speakableMathml(html) : html;
  const m = /<math[\s\S]*<\/math>/.exec(out);
  if (!m) throw new Error(`no MathML for ${tex}`);
  return m[0];
}

async function domain(d: 'mathspeak' | 'clearspeak') {
  await sre.setupEngine({ locale: 'en', domain: d, modality: 'speech' });
  await sre.engineReady();
}
const say = (key: keyof typeof FORMULAS, tidy = true) => sre.toSpeech(pageMathml(FORMULAS[key].tex, tidy));

describe('formulas heard right (speech-rule-engine, MathSpeak)', () => {
  beforeAll(() => domain('mathspeak'));

  it('each formula is the one its scene shows', () => {
    for (const [name, f] of Object.entries(FORMULAS)) {
      const src = readFileSync(f.file, 'utf8');
      const escaped = f.tex.replace(/\\/g, '\\\\');
      expect(src.includes(f.tex) || src.includes(escaped), `${name} in ${f.file}`).toBe(true);
    }
  });

  it('the KaTeX HTML is hidden from screen readers and the MathML is not', () => {
    const html = speakableMathml(katex.renderToString(FORMULAS.solidAngle.tex, { ...KATEX_OPTIONS }));
    expect(html).toMatch(/<span class="katex-html" aria-hidden="true">/);
    expect(html).toMatch(/<span class="katex-mathml"><math/);
    expect(html.slice(0, html.indexOf('<math'))).not.toContain('aria-hidden');
  });

  it('the normalization constant k', () => {
    expect(say('normalization')).toBe(
      'k equals StartFraction 2 Over e Superscript 2 pi Baseline minus 1 EndFraction',
    );
  });

  it('the CDF inversions: θ from ξ₁ (both forms), φ from ξ₂ (no stray "comma" from a kern)', () => {
    expect(say('thetaInversion')).toBe(
      'theta equals one half cosine Superscript negative 1 Baseline left parenthesis 1 minus 2 xi 1 right parenthesis',
    );
    expect(say('thetaInversionAsin')).toBe(
      'theta equals sine Superscript negative 1 Baseline StartRoot xi 1 EndRoot',
    );
    const phi = say('phiInversion');
    expect(phi).toBe(
      'phi equals ln left bracket left parenthesis e Superscript 2 pi Baseline minus 1 right parenthesis xi 2 plus 1 right bracket',
    );
    // KaTeX's own MathML, untidied, is heard with a comma after "ln": the tidying is what fixes it
    expect(say('phiInversion', false)).toContain('ln comma');
  });

  it('the discriminant and the roots: Δ is "upper Delta", not "normal upper Delta"', () => {
    expect(say('discriminant')).toBe('upper Delta equals b squared minus 4 a c');
    expect(say('discriminant', false)).toContain('normal upper Delta');
    expect(say('roots')).toBe(
      't equals StartFraction negative b plus or minus StartRoot upper Delta EndRoot Over 2 a EndFraction',
    );
  });

  it('the solid angle dω = cos θ_l dA / r²', () => {
    expect(say('solidAngle')).toBe(
      'd omega equals StartFraction d upper A cosine theta Subscript l Baseline Over r squared EndFraction',
    );
  });

  it('the Monte Carlo estimator', () => {
    expect(say('estimator')).toBe(
      'left angle bracket upper I right angle bracket equals StartFraction 1 Over upper N EndFraction sigma summation Underscript i equals 1 Overscript upper N Endscripts StartFraction f left parenthesis upper X Subscript i Baseline right parenthesis Over p left parenthesis upper X Subscript i Baseline right parenthesis EndFraction',
    );
  });
});

describe('formulas heard right (speech-rule-engine, ClearSpeak)', () => {
  beforeAll(() => domain('clearspeak'));

  it('reads the fractions, inverses and subscripts in words', () => {
    expect(say('normalization')).toBe(
      'k equals the fraction with numerator 2 and denominator e raised to the 2 pi power minus 1',
    );
    expect(say('thetaInversion')).toBe(
      'theta equals one half the inverse cosine of open paren 1 minus 2 xi sub 1 close paren',
    );
    expect(say('phiInversion')).not.toContain('comma');
    expect(say('solidAngle')).toBe(
      'd omega equals the fraction with numerator d A the cosine of theta sub l and denominator r squared',
    );
  });
});

describe('speech tidying and the preview label', () => {
  it('drops spacing-only mtext and the upright mark of capital Greek, nothing else', () => {
    const m =
      '<span class="katex-html" aria-hidden="true"><mtext> </mtext></span><math><mi mathvariant="normal">Ω</mi><mtext>\u2009\u2063</mtext><mtext>area</mtext><mi mathvariant="normal">d</mi></math>';
    expect(speakableMathml(m)).toBe(
      '<span class="katex-html" aria-hidden="true"><mtext> </mtext></span><math><mi>Ω</mi><mtext>area</mtext><mi mathvariant="normal">d</mi></math>',
    );
  });
  it('the plain-text preview is named in words', () => {
    expect(previewLabel('p(ω) = k cos θ e^φ')).toBe('p(ω) = k cos θ e to the power φ');
    expect(previewLabel('θ_l')).toBe('θ sub l');
  });
});
