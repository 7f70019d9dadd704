/**
 * A deck as a link: `#/deck?d=<code>`, the code being the deck's fields as a JSON array, deflated
 * (fflate) and written in base64url, so a deck of a dozen slides fits in a QR code. Decoding
 * refuses, with a message, anything that is not such a code, and bounds what it unpacks (a short
 * hostile code cannot inflate into megabytes).
 */
import { deflateSync, inflateSync, strFromU8, strToU8 } from 'fflate';
import { fail } from '../core/failure';
import { readDeck, type Checked, type Deck } from './deck';

/** The version of the code's layout (its first element). */
const CODE_VERSION = 1;
/** The longest code read from a link. */
export const MAX_CODE = 12_000;
/** The most bytes a code may unpack to. */
const MAX_UNPACKED = 200_000;

function toBase64Url(bytes: Uint8Array): string {
  let bin = '';
  for (let i = 0; i < bytes.length; i++) bin += String.fromCharCode(bytes[i]);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(code: string): Uint8Array {
  const b64 = code.replace(/-/g, '+').replace(/_/g, '/');
  const bin = atob(b64 + '='.repeat((4 - (b64.length % 4)) % 4));
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

/** The deck as a link's `d=` code (URL-safe: letters, digits, `-` and `_`). */
export function encodeDeck(deck: Deck): string {
  const rows = deck.slides.map((s) => {
    const row = [s.link, s.title, s.question, s.caption];
    return s.highlight ? [...row, s.highlight] : row;
  });
  return toBase64Url(deflateSync(strToU8(JSON.stringify([CODE_VERSION, deck.title, rows])), { level: 9 }));
}

/** The deck a `d=` code holds, or a message saying why the code is not one. */
export function decodeDeck(code: string): Checked<Deck> {
  if (!code) return fail('deck', 'the deck code is empty');
  if (code.length > MAX_CODE)
    return fail('deck', `the deck code has ${code.length} characters; at most ${MAX_CODE}`);
  if (!/^[A-Za-z0-9_-]+$/.test(code) || code.length % 4 === 1)
    return fail('deck', 'the deck code has characters a deck link never has; was the link cut or retyped?');
  let json: string;
  try {
    const out = inflateSync(fromBase64Url(code), { out: new Uint8Array(MAX_UNPACKED + 1) });
    if (out.length > MAX_UNPACKED) return fail('deck', 'the deck code unpacks to more than a deck can hold');
    json = strFromU8(out);
  } catch {
    return fail('deck', 'the deck code does not unpack; was the link cut short?');
  }
  let data: unknown;
  try {
    data = JSON.parse(json);
  } catch {
    return fail('deck', 'the deck code does not hold a deck; was the link cut short?');
  }
  if (!Array.isArray(data) || data[0] !== CODE_VERSION || !Array.isArray(data[2]))
    return fail('deck', `the deck code is not a deck of version ${CODE_VERSION}`);
  const slides = (data[2] as unknown[]).map((row) =>
    Array.isArray(row)
      ? { link: row[0], title: row[1], question: row[2], caption: row[3], highlight: row[4] }
      : row,
  );
  return readDeck({ title: data[1], slides });
}
