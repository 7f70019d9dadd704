/**
 * Conventions as the key grants them: the grid's v′ = 1 − v only on the grid's v axis (nearest,
 * bilinear and the sphere lookup), never for the sphere's v = θ/π, and one convention throughout a
 * variant (a mix is named).
 */
import { describe, expect, it } from 'vitest';
import { q3Variant } from '../../src/practice/q3';
import { allAnswers, type NumberAnswer, type Variant } from '../../src/practice/model';
import { gradeAnswers } from '../../src/practice/session';

const spec = (v: Variant, name: string) => allAnswers(v).find((a) => a.name === name) as NumberAnswer;
/** A Q3 variant where the flipped reading changes both the nearest and the bilinear value. */
function flippable(): Variant {
  for (let s = 0; ; s++) {
    const v = q3Variant(s);
    if (spec(v, 'nearest').alternatives.length && spec(v, 'bilinear').alternatives.length) return v;
  }
}

describe('the grid’s flipped v', () => {
  const v = flippable();
  const flipped = (n: string) => String(spec(v, n).alternatives[0].value);
  const right = (n: string) => String(spec(v, n).expected);
  it('is accepted, with a note, when every lookup uses it', async () => {
    const out = await gradeAnswers(v, { nearest: flipped('nearest'), bilinear: flipped('bilinear') });
    expect(out.nearest.value).toBe('correct');
    expect(out.nearest.message).toContain('1 − v');
    expect(out.bilinear.value).toBe('correct');
  });
  it('a mix of conventions is named, on the answer that breaks with the first', async () => {
    const out = await gradeAnswers(v, { nearest: right('nearest'), bilinear: flipped('bilinear') });
    expect(out.nearest.value).toBe('correct');
    expect(out.bilinear.value).toBe('mistake:mixed-convention');
    expect(out.bilinear.message).toContain('nearest');
    const back = await gradeAnswers(v, { nearest: flipped('nearest'), bilinear: right('bilinear') });
    expect(back.bilinear.value).toBe('mistake:mixed-convention');
  });
  it('does not apply to the sphere’s v = θ/π', async () => {
    for (let s = 0; s < 300; s++) {
      const w = q3Variant(s);
      const sv = spec(w, 'sphere-v');
      expect(sv.alternatives).toEqual([]);
      if (Math.abs(sv.expected! - 0.5) < 1e-6) continue;
      const out = await gradeAnswers(w, { 'sphere-v': String(1 - sv.expected!) });
      expect(out['sphere-v'].value).toBe('mistake:flipped-v');
    }
  });
});
