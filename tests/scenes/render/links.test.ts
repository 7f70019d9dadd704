/** The inspector's links: each number opens the scene that teaches it, in the same state. */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/render/params';
import { buildRenderModel } from '../../../src/scenes/render/model';
import { raySphereHref, sampleHref, textureHref } from '../../../src/scenes/render/links';
import type { SampleRow } from '../../../src/core/render/inspector';

const model = (q: string) => buildRenderModel(parseParams(schema, q).values);
const query = (href: string) => new URLSearchParams(href.slice(href.indexOf('?') + 1));

const row = (technique: SampleRow['technique']): SampleRow => ({
  technique,
  direction: [0, 0, 1],
  lightPoint: null,
  f: 0.25,
  L: 1,
  cosTheta: 1,
  cosThetaL: null,
  r2: null,
  pdf: 1,
  measure: 'solid-angle',
  pdfSolidAngle: 1,
  weight: 1,
  term: 0.25,
});

describe('inspector links', () => {
  it('opens the ray–sphere scene on the same ray and sphere', () => {
    const h = raySphereHref({ center: [1, 2, 3], radius: 0.5 }, [0, -6, 3.5], [0.1, 0.9, -0.4]);
    expect(h.startsWith('#/ray-sphere?')).toBe(true);
    expect(Object.fromEntries(query(h))).toEqual({ o: '0,-6,3.5', d: '0.1,0.9,-0.4', c: '1,2,3', r: '0.5' });
  });

  it('opens the texture scene at the same (u, v) on the same grid', () => {
    const q = query(textureHref(model('grid=1,2;3,4'), 0.25, 0.75));
    expect([q.get('u'), q.get('v'), q.get('grid')]).toEqual(['0.25', '0.75', '1,2;3,4']);
  });

  it('sends light samples to the area-light scene with the exam light, and the point on its floor', () => {
    const h = sampleHref(model('lc=1,0,2&tilt=10'), row('area'), [0.5, 0.25, 0]);
    const q = query(h.href);
    expect(h.href.startsWith('#/area-light?')).toBe(true);
    expect([q.get('strategy'), q.get('lc'), q.get('tilt'), q.get('p')]).toEqual([
      'area',
      '1,0,2',
      '10',
      '0.5,0.25,0',
    ]);
    // a point off the floor (on the sphere) is not the area-light scene's point
    expect(query(sampleHref(model(''), row('solid-angle'), [0, 0, 1]).href).get('p')).toBeNull();
    // Veach's lights are not the exam's: only the strategy travels
    expect([...query(sampleHref(model('scene=veach'), row('area'), null).href).keys()]).toEqual(['strategy']);
  });

  it('sends hemisphere samples to the hemisphere scene’s density', () => {
    expect(sampleHref(model(''), row('uniform'), null).href).toBe('#/hemisphere?lobe=uniform');
    expect(sampleHref(model(''), row('cosine'), null).href).toBe('#/hemisphere?lobe=cosine');
    expect(sampleHref(model(''), row('bsdf'), null).href).toBe('#/hemisphere?lobe=cosine');
  });
});
