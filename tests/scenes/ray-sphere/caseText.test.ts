// The case banner over the figure: where rounding made the chosen method's case wrong, the banner
// says so where it states the case, and names the exact case.
import { describe, expect, it } from 'vitest';
import { caseBanner } from '../../../src/scenes/ray-sphere/caseText';
import { activeRows, computeModel } from '../../../src/scenes/ray-sphere/model';
import { PRECISION_PRESETS } from '../../../src/scenes/ray-sphere/params';

const far = PRECISION_PRESETS.find((p) => p.id === 'far')!.params;
const model = (method: 'naive' | 'stable') =>
  computeModel({ o: [...far.o!], d: [...far.d!], c: [...far.c!], r: far.r!, method });

describe('caseBanner', () => {
  it('the far preset, textbook form: “Tangent” comes with the exact case and the reason', () => {
    const m = model('naive');
    expect(m.chosen!.case).toBe('tangent');
    const b = caseBanner(m.chosen!.case, activeRows(m).reference!.case, 'textbook', 'double');
    expect(b.name).toBe('Tangent');
    expect(b.wrong).toMatch(/textbook form computes in double arithmetic/);
    expect(b.wrong).toMatch(/“Two hits”/);
  });
  it('a right case says nothing more', () => {
    const m = model('stable');
    const b = caseBanner(m.chosen!.case, activeRows(m).reference!.case, 'robust', 'double');
    expect(b.name).toBe('Two hits');
    expect(b.wrong).toBeNull();
  });
});
