/** The repository's own files, for tests that read its sources (stylesheets, components…). */
import { readdirSync } from 'node:fs';
import path from 'node:path';

/** Every file under `dir` (its folders too) whose name matches `name`, as paths joined onto `dir`. */
export function filesUnder(dir: string, name: RegExp): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) return filesUnder(p, name);
    return name.test(e.name) ? [p] : [];
  });
}
