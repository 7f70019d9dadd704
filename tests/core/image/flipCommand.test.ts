/** The command a researcher runs, `node scripts/flip.mjs REF.png TEST.png`, against the library it wraps. */
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { colorInto, MAGMA } from '../../../src/core/colormap';
import { flipErrorMap } from '../../../src/core/image/flip';
import { decodePng, encodePng, rgbFromRgba8 } from '../../../src/core/image/png';
import { poolError } from '../../../src/core/image/pooling';

const script = new URL('../../../scripts/flip.mjs', import.meta.url).pathname;

function pair(dir: string) {
  const w = 24;
  const h = 16;
  const ref = new Uint8Array(4 * w * h);
  const test = new Uint8Array(4 * w * h);
  for (let i = 0; i < w * h; i++) {
    const x = i % w;
    ref.set([x * 10, 255 - x * 10, 128, 255], 4 * i);
    test.set([x * 10 + (i % 7 === 0 ? 60 : 0), 255 - x * 10, 128, 255], 4 * i);
  }
  const r = join(dir, 'ref.png');
  const t = join(dir, 'test.png');
  writeFileSync(r, encodePng({ width: w, height: h, data: ref }));
  writeFileSync(t, encodePng({ width: w, height: h, data: test }));
  return {
    r,
    t,
    ref: rgbFromRgba8({ width: w, height: h, data: ref }),
    test: rgbFromRgba8({ width: w, height: h, data: test }),
  };
}

describe('scripts/flip.mjs', () => {
  it('prints the pooled figures of the library and writes the magma map', () => {
    const dir = mkdtempSync(join(tmpdir(), 'flip-'));
    const { r, t, ref, test } = pair(dir);
    const map = join(dir, 'map.png');
    const out = execFileSync(process.execPath, [script, r, t, '--ppd', '40', '--map', map], {
      encoding: 'utf8',
    });
    const errors = flipErrorMap(ref, test, 40);
    const p = poolError(errors);
    expect(out).toContain(`mean: ${p.mean.toFixed(6)}`);
    expect(out).toContain(`weighted median: ${p.weightedMedian.toFixed(6)}`);
    expect(out).toContain(`max: ${p.max.toFixed(6)}`);
    const img = decodePng(new Uint8Array(readFileSync(map)));
    expect([img.width, img.height]).toEqual([24, 16]);
    // each pixel is magma at its error (quantized to 1/255, as the reference tool's 256-entry table)
    const c = [0, 0, 0];
    for (let i = 0; i < errors.length; i++) {
      colorInto(Math.round(errors[i] * 255) / 255, c, 0, MAGMA);
      expect([img.data[4 * i], img.data[4 * i + 1], img.data[4 * i + 2]]).toEqual(c);
    }
  });

  it('names a bad argument and a bad file, and exits non-zero', () => {
    const dir = mkdtempSync(join(tmpdir(), 'flip-'));
    const { r } = pair(dir);
    const bad = join(dir, 'bad.png');
    writeFileSync(bad, 'not a png');
    const usage = spawnSync(process.execPath, [script, r], { encoding: 'utf8' });
    expect(usage.status).toBe(2);
    expect(usage.stderr).toMatch(/usage: node scripts\/flip\.mjs/);
    const ppd = spawnSync(process.execPath, [script, r, r, '--ppd', '-3'], { encoding: 'utf8' });
    expect(ppd.status).toBe(2);
    expect(ppd.stderr).toMatch(/--ppd must be a positive number/);
    const file = spawnSync(process.execPath, [script, r, bad], { encoding: 'utf8' });
    expect(file.status).toBe(1);
    expect(file.stderr).toMatch(/bad\.png: not a PNG file/);
  });
});
