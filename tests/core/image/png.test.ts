import { deflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { crc32, decodePng, encodePng, rgbFromRgba8 } from '../../../src/core/image/png';
import { poolError, weightedPercentile } from '../../../src/core/image/pooling';

/** A PNG written here by hand with Node's zlib and the forward filters, independent of the module. */
function handPng(w: number, h: number, rgb: Uint8Array, filterOf: (y: number) => number): Uint8Array {
  const stride = 3 * w;
  const raw: number[] = [];
  const px = (y: number, x: number) => (y < 0 || x < 0 ? 0 : rgb[y * stride + x]);
  for (let y = 0; y < h; y++) {
    const f = filterOf(y);
    raw.push(f);
    for (let x = 0; x < stride; x++) {
      const v = px(y, x);
      const a = px(y, x - 3);
      const b = px(y - 1, x);
      const c = px(y - 1, x - 3);
      const p = a + b - c;
      const pr =
        Math.abs(p - a) <= Math.abs(p - b) && Math.abs(p - a) <= Math.abs(p - c)
          ? a
          : Math.abs(p - b) <= Math.abs(p - c)
            ? b
            : c;
      raw.push((v - [0, a, b, (a + b) >> 1, pr][f] + 256) & 255);
    }
  }
  const chunk = (name: string, body: Uint8Array) => {
    const out = Buffer.alloc(12 + body.length);
    out.writeUInt32BE(body.length, 0);
    out.write(name, 4, 'ascii');
    Buffer.from(body).copy(out, 8);
    out.writeUInt32BE(crc32(out, 4, 8 + body.length), 8 + body.length);
    return out;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(w, 0);
  ihdr.writeUInt32BE(h, 4);
  ihdr[8] = 8;
  ihdr[9] = 2;
  return new Uint8Array(
    Buffer.concat([
      Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]),
      chunk('IHDR', ihdr),
      chunk('IDAT', deflateSync(Buffer.from(raw))),
      chunk('IEND', new Uint8Array(0)),
    ]),
  );
}

describe('PNG', () => {
  it('CRC-32 of "IEND" is the constant every PNG ends with', () => {
    expect(crc32(new TextEncoder().encode('IEND'))).toBe(0xae426082);
  });

  it('decodes every scanline filter (None, Sub, Up, Average, Paeth)', () => {
    const w = 7;
    const h = 10;
    const rgb = Uint8Array.from({ length: 3 * w * h }, (_, i) => (i * 73 + (i >> 3) * 19) & 255);
    const img = decodePng(handPng(w, h, rgb, (y) => y % 5));
    expect([img.width, img.height]).toEqual([w, h]);
    for (let i = 0; i < w * h; i++) {
      expect([img.data[4 * i], img.data[4 * i + 1], img.data[4 * i + 2], img.data[4 * i + 3]]).toEqual([
        rgb[3 * i],
        rgb[3 * i + 1],
        rgb[3 * i + 2],
        255,
      ]);
    }
  });

  it('round-trips RGBA pixels through its own encoder', () => {
    const data = Uint8Array.from({ length: 4 * 13 * 5 }, (_, i) => (i * 151) & 255);
    const back = decodePng(encodePng({ width: 13, height: 5, data }));
    expect(Array.from(back.data)).toEqual(Array.from(data));
    const rgb = rgbFromRgba8(back);
    expect(rgb.data[0]).toBe(data[0] / 255);
    expect(rgb.data.length).toBe(3 * 13 * 5);
  });

  it('says what is wrong with a file it cannot read', () => {
    expect(() => decodePng(new Uint8Array([1, 2, 3, 4, 5, 6, 7, 8]))).toThrow(/not a PNG/);
    const good = encodePng({ width: 2, height: 2, data: new Uint8Array(16) });
    expect(() => decodePng(good.subarray(0, 30))).toThrow(/cut short|no image header/);
    expect(() => encodePng({ width: 3, height: 3, data: new Uint8Array(8) })).toThrow(/3×3/);
  });
});

describe('pooling an error map', () => {
  it('weighted percentiles split the total error, not the pixels', () => {
    const sorted = Float64Array.from([0.1, 0.2, 0.3, 0.4]);
    expect(weightedPercentile(sorted, 0.5, 1)).toBe(0.3);
    expect(weightedPercentile(sorted, 0.25, 1)).toBe(0.2);
    const p = poolError([0.4, 0.1, 0.3, 0.2]);
    expect(p.mean).toBeCloseTo(0.25, 15);
    expect([p.min, p.max, p.weightedMedian]).toEqual([0.1, 0.4, 0.3]);
    expect(p.histogram[10] + p.histogram[20] + p.histogram[30] + p.histogram[40]).toBe(4);
  });

  it('an all-zero map pools to zeros, an empty one to NaN', () => {
    const z = poolError(new Float64Array(9));
    expect([z.mean, z.weightedMedian, z.max]).toEqual([0, 0, 0]);
    expect(z.histogram[0]).toBe(9);
    expect(Number.isNaN(poolError([]).mean)).toBe(true);
  });
});
