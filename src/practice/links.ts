/**
 * Links between the practice pages: the seed a fresh link draws, and the shell flags (embed,
 * present, …) every practice link carries on so that the page keeps its look.
 */
import { shellExtras, type ShellFlags } from '../kit/shell';

/** The largest variant seed (seeds are unsigned 32-bit integers). */
export const MAX_SEED = 0xffffffff;

/** A fresh variant seed: short numbers read well in a link ("variant 17"). */
export function randomSeed(): number {
  const a = new Uint32Array(1);
  crypto.getRandomValues(a);
  return a[0] % 100000;
}

/** The shell flags of the page as `&name=value` pairs, to append to a practice link. */
export function flagSuffix(flags: ShellFlags): string {
  const e = shellExtras(flags);
  return Object.entries(e)
    .filter(([, v]) => v !== undefined)
    .map(([k, v]) => `&${k}=${v}`)
    .join('');
}
