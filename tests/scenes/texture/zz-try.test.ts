import { it } from 'vitest';
import { pathProfile, creases, resolveGrid, lookupOptions, pathOf } from '../../../src/scenes/texture/model';
it('try', () => {
  const base = { grid: '', preset: 'grid', size: 8, seed: 1 } as any;
  const exam = resolveGrid({ ...base, grid: '1,2,3,4,5;6,7,8,9,10;11,12,13,14,15;16,17,18,19,20;21,22,23,24,25' }).grid;
  const chk = resolveGrid({ ...base, preset: 'checker' }).grid;
  const o = lookupOptions({ align: 'corner', vflip: false, wrap: 'clamp' } as any);
  const path = pathOf({ u: 0.4, v: 0.24, u2: 0.85, v2: 0.8, path: 'line' } as any);
  for (const g of [exam, chk]) {
    const p = pathProfile(g, o, path);
    console.log(p.borders, p.nearSwitches, p.near.length, p.ts.length, p.breaks, p.min, p.max);
    const c = creases(g, o);
    console.log(c.lines, c.creased, c.list.length);
  }
  const pr = pathProfile(exam, lookupOptions({ align: 'corner', vflip: false, wrap: 'repeat' } as any), pathOf({ u: 0.4, v: 0.24, u2: 1.6, v2: 0.3, path: 'line' } as any));
  console.log(pr.borders, pr.breaks);
  console.log(creases(exam, lookupOptions({ align: 'center', vflip: false, wrap: 'clamp' } as any)));
  console.log(creases(exam, lookupOptions({ align: 'center', vflip: false, wrap: 'repeat' } as any)).creased);
});
