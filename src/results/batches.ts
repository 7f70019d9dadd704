/**
 * The class's files on #/results: each batch dropped or picked adds to those already there, and a
 * file handed in twice (same name and text) counts once; a file of the same name with other text
 * replaces the earlier one (a student's newer download).
 */
import type { InputFile } from './collate';

export function addBatch(have: readonly InputFile[], batch: readonly InputFile[]): InputFile[] {
  const byName = new Map<string, InputFile>();
  for (const f of [...have, ...batch]) byName.set(f.name, f);
  return [...byName.values()];
}
