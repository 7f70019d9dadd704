/**
 * PNG in and out, pure (no DOM), so that the FLIP command and the app read and write exactly the
 * same 8-bit pixels. Decodes non-interlaced PNGs of every colour type at bit depth 8 (16-bit
 * samples keep their high byte; palette and grey images of 1, 2 or 4 bits are unpacked) into RGBA8;
 * encodes RGBA8 as an 8-bit RGBA PNG. Written from the PNG specification (W3C, 2nd edition):
 * chunk layout, CRC-32, the five scanline filters and the Paeth predictor.
 */
import { unzlibSync, zlibSync } from 'fflate';

/** An RGBA image, 8 bits per channel, rows from the top. */
export interface Rgba8Image {
  width: number;
  height: number;
  data: Uint8Array | Uint8ClampedArray;
}

const SIGNATURE = [137, 80, 78, 71, 13, 10, 26, 10];

let crcTable: Uint32Array | null = null;

/** CRC-32 (ISO 3309, the polynomial PNG uses) of bytes. */
export function crc32(bytes: Uint8Array, start = 0, end = bytes.length): number {
  if (!crcTable) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (let i = start; i < end; i++) c = crcTable[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

const readU32 = (b: Uint8Array, o: number) =>
  ((b[o] << 24) | (b[o + 1] << 16) | (b[o + 2] << 8) | b[o + 3]) >>> 0;

function paeth(a: number, b: number, c: number): number {
  const p = a + b - c;
  const pa = Math.abs(p - a);
  const pb = Math.abs(p - b);
  const pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/** Decode a PNG file. Throws an Error saying what is wrong with a file it cannot read. */
export function decodePng(file: Uint8Array): Rgba8Image {
  for (let i = 0; i < 8; i++) if (file[i] !== SIGNATURE[i]) throw new Error('not a PNG file (bad signature)');
  let pos = 8;
  let width = 0;
  let height = 0;
  let depth = 0;
  let type = 0;
  let interlace = 0;
  let palette: Uint8Array | null = null;
  let paletteAlpha: Uint8Array | null = null;
  const idat: Uint8Array[] = [];
  while (pos + 8 <= file.length) {
    const len = readU32(file, pos);
    const name = String.fromCharCode(file[pos + 4], file[pos + 5], file[pos + 6], file[pos + 7]);
    const body = file.subarray(pos + 8, pos + 8 + len);
    if (body.length !== len) throw new Error(`PNG chunk ${name} is cut short`);
    if (name === 'IHDR') {
      width = readU32(body, 0);
      height = readU32(body, 4);
      depth = body[8];
      type = body[9];
      interlace = body[12];
    } else if (name === 'PLTE') palette = body.slice();
    else if (name === 'tRNS') paletteAlpha = body.slice();
    else if (name === 'IDAT') idat.push(body);
    else if (name === 'IEND') break;
    pos += 12 + len;
  }
  if (!(width > 0 && height > 0)) throw new Error('PNG has no image header');
  if (interlace !== 0) throw new Error('interlaced PNGs are not supported; save it without interlacing');
  const channels = { 0: 1, 2: 3, 3: 1, 4: 2, 6: 4 }[type];
  if (channels === undefined) throw new Error(`PNG colour type ${type} is not valid`);
  if (![1, 2, 4, 8, 16].includes(depth)) throw new Error(`PNG bit depth ${depth} is not valid`);
  if (type === 3 && !palette) throw new Error('palette PNG without a palette');
  let total = 0;
  for (const c of idat) total += c.length;
  const packed = new Uint8Array(total);
  let o = 0;
  for (const c of idat) {
    packed.set(c, o);
    o += c.length;
  }
  let raw: Uint8Array;
  try {
    raw = unzlibSync(packed);
  } catch (e) {
    throw new Error(`PNG image data is cut short or corrupt (${(e as Error).message})`);
  }
  const bpp = Math.max(1, (channels * depth) >> 3);
  const stride = Math.ceil((width * channels * depth) / 8);
  if (raw.length < height * (stride + 1)) throw new Error('PNG image data is cut short');
  const rows = new Uint8Array(height * stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)];
    if (f > 4) throw new Error(`PNG row ${y} has an unknown filter ${f}`);
    const src = y * (stride + 1) + 1;
    const dst = y * stride;
    for (let x = 0; x < stride; x++) {
      const a = x >= bpp ? rows[dst + x - bpp] : 0;
      const b = y > 0 ? rows[dst - stride + x] : 0;
      const c = x >= bpp && y > 0 ? rows[dst - stride + x - bpp] : 0;
      const v = raw[src + x];
      rows[dst + x] =
        f === 0 ? v : f === 1 ? v + a : f === 2 ? v + b : f === 3 ? v + ((a + b) >> 1) : v + paeth(a, b, c);
    }
  }
  const out = new Uint8Array(4 * width * height);
  const sample = (y: number, i: number): number => {
    // the i-th sample of row y, as 8 bits
    if (depth === 8) return rows[y * stride + i];
    if (depth === 16) return rows[y * stride + 2 * i];
    const perByte = 8 / depth;
    const byte = rows[y * stride + Math.floor(i / perByte)];
    const shift = 8 - depth * ((i % perByte) + 1);
    const v = (byte >> shift) & ((1 << depth) - 1);
    return type === 3 ? v : Math.round((v * 255) / ((1 << depth) - 1));
  };
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++) {
      const p = 4 * (y * width + x);
      const s = x * channels;
      if (type === 3) {
        const k = sample(y, x);
        out[p] = palette![3 * k];
        out[p + 1] = palette![3 * k + 1];
        out[p + 2] = palette![3 * k + 2];
        out[p + 3] = paletteAlpha && k < paletteAlpha.length ? paletteAlpha[k] : 255;
      } else if (type === 0 || type === 4) {
        const g = sample(y, s);
        out[p] = out[p + 1] = out[p + 2] = g;
        out[p + 3] = type === 4 ? sample(y, s + 1) : 255;
      } else {
        out[p] = sample(y, s);
        out[p + 1] = sample(y, s + 1);
        out[p + 2] = sample(y, s + 2);
        out[p + 3] = type === 6 ? sample(y, s + 3) : 255;
      }
    }
  return { width, height, data: out };
}

function chunk(name: string, body: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + body.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, body.length);
  for (let i = 0; i < 4; i++) out[4 + i] = name.charCodeAt(i);
  out.set(body, 8);
  view.setUint32(8 + body.length, crc32(out, 4, 8 + body.length));
  return out;
}

/** Encode RGBA8 pixels as an 8-bit RGBA PNG (every row unfiltered, zlib-compressed). */
export function encodePng(img: Rgba8Image): Uint8Array {
  const { width, height, data } = img;
  if (data.length !== 4 * width * height)
    throw new RangeError(`RGBA data of ${data.length} bytes for a ${width}×${height} image`);
  const raw = new Uint8Array(height * (4 * width + 1));
  for (let y = 0; y < height; y++)
    raw.set(data.subarray(4 * width * y, 4 * width * (y + 1)), y * (4 * width + 1) + 1);
  const header = new Uint8Array(13);
  const hv = new DataView(header.buffer);
  hv.setUint32(0, width);
  hv.setUint32(4, height);
  header[8] = 8;
  header[9] = 6;
  const parts = [
    Uint8Array.from(SIGNATURE),
    chunk('IHDR', header),
    chunk('IDAT', zlibSync(raw, { level: 6 })),
    chunk('IEND', new Uint8Array(0)),
  ];
  const out = new Uint8Array(parts.reduce((s, p) => s + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

/** The sRGB values in [0, 1] of an RGBA8 image, three channels per pixel (alpha dropped, as FLIP's tool reads PNGs). */
export function rgbFromRgba8(img: Rgba8Image): { width: number; height: number; data: Float64Array } {
  const n = img.width * img.height;
  const data = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    data[3 * i] = img.data[4 * i] / 255;
    data[3 * i + 1] = img.data[4 * i + 1] / 255;
    data[3 * i + 2] = img.data[4 * i + 2] / 255;
  }
  return { width: img.width, height: img.height, data };
}
