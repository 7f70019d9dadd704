#!/usr/bin/env node
/**
 * Writes the web-app icons (public/icon-192.png, icon-512.png, icon-maskable-512.png) without any
 * image library: the brand's half-lit disc (◐, a hemisphere lit from one side) drawn with 4×4
 * supersampling and encoded as PNG with node:zlib. Run once; the PNGs are committed.
 */
import { writeFileSync, mkdirSync } from 'node:fs';
import { deflateSync } from 'node:zlib';

const crcTable = new Int32Array(256).map((_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c;
});
const crc32 = (buf) => {
  let c = -1;
  for (const b of buf) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ -1) >>> 0;
};
function chunk(type, data) {
  const len = Buffer.alloc(4);
  len.writeUInt32BE(data.length);
  const td = Buffer.concat([Buffer.from(type, 'ascii'), data]);
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(td));
  return Buffer.concat([len, td, crc]);
}
function png(size, pixel) {
  const raw = Buffer.alloc(size * (size * 4 + 1));
  const S = 4;
  for (let y = 0; y < size; y++) {
    raw[y * (size * 4 + 1)] = 0;
    for (let x = 0; x < size; x++) {
      const acc = [0, 0, 0, 0];
      for (let sy = 0; sy < S; sy++)
        for (let sx = 0; sx < S; sx++) {
          const p = pixel((x + (sx + 0.5) / S) / size, (y + (sy + 0.5) / S) / size);
          for (let i = 0; i < 4; i++) acc[i] += p[i];
        }
      const o = y * (size * 4 + 1) + 1 + x * 4;
      for (let i = 0; i < 4; i++) raw[o + i] = Math.round(acc[i] / (S * S));
    }
  }
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(size, 0);
  ihdr.writeUInt32BE(size, 4);
  ihdr[8] = 8;
  ihdr[9] = 6;
  return Buffer.concat([
    Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]),
    chunk('IHDR', ihdr),
    chunk('IDAT', deflateSync(raw, { level: 9 })),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}
const BG = [28, 29, 33, 255];
const LIT = [245, 166, 35, 255];
const DARK = [161, 63, 0, 255];
/** r: disc radius as a fraction of the icon; full: background fills the square (maskable). */
const icon = (r, full) => (u, v) => {
  const dx = u - 0.5;
  const dy = v - 0.5;
  const d = Math.hypot(dx, dy);
  const bgR = 0.5;
  if (d <= r) return dx < 0 ? LIT : DARK;
  if (full || Math.max(Math.abs(dx), Math.abs(dy)) <= bgR) {
    // rounded square background for the plain icons
    if (full) return BG;
    const q = 0.1;
    const ax = Math.max(Math.abs(dx) - (bgR - q), 0);
    const ay = Math.max(Math.abs(dy) - (bgR - q), 0);
    return Math.hypot(ax, ay) <= q ? BG : [0, 0, 0, 0];
  }
  return [0, 0, 0, 0];
};
mkdirSync('public', { recursive: true });
writeFileSync('public/icon-192.png', png(192, icon(0.36, false)));
writeFileSync('public/icon-512.png', png(512, icon(0.36, false)));
writeFileSync('public/icon-maskable-512.png', png(512, icon(0.28, true)));
console.log('wrote public/icon-192.png, icon-512.png, icon-maskable-512.png');
