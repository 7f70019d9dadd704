/**
 * The exam parts of #/ray-sphere (Q5) and #/area-light (Q6) rendered outside the browser
 * (react-dom/server, the whole scene for a link's parameters): the worked steps carry the live
 * numbers of the model for those parameters, the key's notes say what the key prints, and the
 * robust Δ beside a, b, c says which method computed which. Formulas are not typeset here (they
 * render as their plain-text preview), so only words and numbers are checked. The order of the
 * parts on the page, and everything that needs effects or workers, is checked in the browser
 * (tests/e2e/catalogue.spec.ts, ray-sphere.spec.ts, area-light.spec.ts).
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import type { ComponentType } from 'react';
import { defaultValues, parseParams, type ParamSchema } from '../../src/kit/params';
import type { SceneProps } from '../../src/kit/scene';
import * as raySphere from '../../src/scenes/ray-sphere';
import * as areaLight from '../../src/scenes/area-light';
import { PRECISION_PRESETS } from '../../src/scenes/ray-sphere/params';
import { buildModel, givenSamples } from '../../src/scenes/area-light/model';
import { patchModel } from '../../src/scenes/area-light/patch';

/** The scene's markup for a link's query, as the page renders it before any effect runs. */
function render<S extends ParamSchema>(
  scene: { schema: S; default: ComponentType<SceneProps<S>> },
  query: string,
): string {
  const params = parseParams(scene.schema, query).values;
  const Scene = scene.default;
  return renderToStaticMarkup(
    <Scene
      params={params}
      setParams={() => {}}
      mode={{ embed: false, present: false, ask: false, theme: 'light' }}
    />,
  );
}

/** The opening tag and the whole element of the first element with this test id ('' if none). */
function element(html: string, testId: string): { tag: string; outer: string } {
  const at = html.indexOf(`data-testid="${testId}"`);
  if (at < 0) return { tag: '', outer: '' };
  const start = html.lastIndexOf('<', at);
  const name = /^<([a-zA-Z][\w-]*)/.exec(html.slice(start))![1];
  const tag = html.slice(start, html.indexOf('>', at) + 1);
  if (tag.endsWith('/>')) return { tag, outer: tag };
  const re = new RegExp(`<(/?)${name}\\b[^>]*?(/?)>`, 'g');
  re.lastIndex = start;
  let depth = 0;
  for (let m = re.exec(html); m; m = re.exec(html)) {
    if (m[2]) continue;
    depth += m[1] ? -1 : 1;
    if (depth === 0) return { tag, outer: html.slice(start, re.lastIndex) };
  }
  throw new Error(`unclosed <${name}> for ${testId}`);
}

const ENTITIES: Record<string, string> = { amp: '&', lt: '<', gt: '>', quot: '"', '#x27': "'", nbsp: ' ' };

/** The text of the element with this test id, tags dropped and white space collapsed. */
function textOf(html: string, testId: string): string {
  const { outer } = element(html, testId);
  expect(outer, `an element with data-testid="${testId}"`).not.toBe('');
  return outer
    .replace(/<[^>]+>/g, ' ')
    .replace(/&([#\w]+);/g, (all, e: string) => ENTITIES[e] ?? all)
    .replace(/\s+/g, ' ')
    .trim();
}

/** The data-value of the element with this test id, as a number. */
function valueOf(html: string, testId: string): number {
  const m = /data-value="([^"]*)"/.exec(element(html, testId).tag);
  expect(m, `data-value of ${testId}`).not.toBeNull();
  return Number(m![1]);
}

/** As the steps print a number: `digits` significant digits. */
const sig = (x: number, digits: number) => String(Number(x.toPrecision(digits)));

describe('#/ray-sphere, Q5', () => {
  it('the question, the substitution, the live numbers, the two conditions, the t_min note and the key', () => {
    const html = render(raySphere, 'o=-3,0.3,0.2&d=1,0,0&c=0,0,0&r=1&open=tmin');
    const asks = textOf(html, 'part-5');
    expect(asks).toContain('The exam asks');
    expect(asks).toContain('centre C');
    expect(asks).toContain('Δ ≥ 0');
    // c = |o − C|² − r² = 8.13; the hit t₀ = 3 − √0.87 (the steps print 8 significant digits)
    expect(textOf(html, 'step-numbers')).toContain(sig(9 + 0.09 + 0.04 - 1, 6));
    expect(textOf(html, 'step-hit')).toContain(sig(3 - Math.sqrt(1 - 0.13), 8));
    const conditions = textOf(html, 'step-conditions');
    expect(conditions).toContain('Δ ≥ 0');
    expect(conditions).toContain('t ≥ 0');
    expect(textOf(html, 'step-substitute')).toContain('C');
    expect(textOf(html, 'step-tmin')).toContain('shadow acne');
    expect(textOf(html, 'q5-keynote')).toContain('Ray Tracing in One Weekend');
  });

  it('Δ beside a, b, c: b² − 4ac of the numbers shown, and which method computed which', () => {
    const q = 'o=-3,-1.2,0.6&d=1,0.4,-0.15&open=more';
    const robust = render(raySphere, q);
    const [a, b, c] = ['a', 'b', 'c'].map((id) => valueOf(robust, id));
    expect(valueOf(robust, 'disc-abc')).toBe(b * b - 4 * a * c);
    expect(textOf(robust, 'disc-method-note')).toContain('robust form');
    // the textbook method: Δ is exactly b² − 4ac of the numbers shown, and there is no second readout
    const naive = render(raySphere, `${q}&method=naive`);
    expect(valueOf(naive, 'discriminant')).toBe(b * b - 4 * a * c);
    expect(element(naive, 'disc-abc').outer).toBe('');
    expect(textOf(naive, 'disc-method-note')).toContain('textbook way');
    // the far sphere, robust: the two differ and the page says by how much
    const far = PRECISION_PRESETS.find((p) => p.id === 'far')!.params;
    const farHtml = render(
      raySphere,
      `o=${far.o!.join(',')}&d=${far.d!.join(',')}&c=${far.c!.join(',')}&r=${far.r}&open=more`,
    );
    expect(textOf(farHtml, 'case-banner')).toContain('Two hits');
    expect(valueOf(farHtml, 'disc-abc')).not.toBe(valueOf(farHtml, 'discriminant'));
    expect(textOf(farHtml, 'disc-method-note')).toContain('differs from b² − 4ac');
  });
});

describe('#/area-light, Q6', () => {
  it('(a) similar triangles with dl, dωₗ and dω; (b) four steps with the Jacobian; (c) p_A and the four given samples', () => {
    const q = 'psize=0.3&ptilt=40&seed=9&occluder=1';
    const html = render(areaLight, q);
    const values = { ...defaultValues(areaLight.schema), ...parseParams(areaLight.schema, q).values };
    const model = buildModel(values);
    const patch = patchModel(model, values.pu, values.pv, values.psize, values.ptilt);
    expect(textOf(html, 'derivation-6a')).toContain('similar triangles');
    const dl = Math.sqrt(patch.area * patch.cosThetaL);
    expect(textOf(html, 'step-6a-perp')).toContain(`dl = ${sig(dl, 4)}`);
    // dωₗ is written with a real subscript (dω<sub>l</sub>)
    expect(textOf(html, 'step-6a-similar').replace(/dω l/, 'dωl')).toContain(`dωl = ${sig(dl / patch.r, 4)}`);
    expect(textOf(html, 'step-6a-result')).toContain(sig(patch.approx, 6));
    expect(valueOf(html, 'patch-approx')).toBeCloseTo(patch.approx, 7);
    // (b): four display formulas, then the Jacobian's value for the patch of (a)
    const d6b = element(html, 'derivation-6b').outer;
    expect(d6b.match(/class="math math-display/g)).toHaveLength(4);
    expect(textOf(html, 'step-6b-jacobian')).toContain(sig(patch.cosThetaL / patch.r ** 2, 4));
    // (c): p_A = 1/|A|, each given sample's term, and their mean as the N = 4 estimate
    expect(textOf(html, 'step-6c-pdf')).toContain(`|A| = ${sig(model.light.area, 4)}`);
    const g = givenSamples(model, values.seed, 4);
    for (let i = 0; i < 4; i++)
      expect(valueOf(html, `given-term-${i + 1}`)).toBeCloseTo(g.samples[i].term, 12);
    expect(valueOf(html, 'given-estimate')).toBeCloseTo(g.estimate, 6);
    // beyond the exam the strategies' table is a closed fold with nothing in it
    expect(element(html, 'fold-strategies').tag).not.toMatch(/\bopen\b/);
    expect(element(html, 'estimate-area').outer).toBe('');
  });
});
