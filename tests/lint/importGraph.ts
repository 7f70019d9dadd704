/**
 * The import graph of the sources, read with TypeScript's own import scanner: what a file reaches
 * through relative imports (static, re-exports and dynamic `import()`), and the packages on the way.
 */
import fs from 'node:fs';
import path from 'node:path';
import ts from 'typescript';

/** The module specifiers a file imports (static, re-exports, dynamic `import()`). */
function importsOf(file: string): string[] {
  const info = ts.preProcessFile(fs.readFileSync(file, 'utf8'), true, true);
  return info.importedFiles.map((f) => f.fileName);
}

/** The file a relative specifier names, trying the extensions Vite resolves. */
function resolveRelative(from: string, spec: string): string | null {
  const base = path.resolve(path.dirname(from), spec);
  for (const candidate of [
    base,
    `${base}.ts`,
    `${base}.tsx`,
    path.join(base, 'index.ts'),
    path.join(base, 'index.tsx'),
  ])
    if (fs.existsSync(candidate) && fs.statSync(candidate).isFile()) return candidate;
  return null;
}

/** Every file reachable from `entry` through relative imports, and the bare packages they import. */
export function closure(entry: string): { files: string[]; packages: string[] } {
  const files = new Set<string>([entry]);
  const packages = new Set<string>();
  const queue = [entry];
  while (queue.length) {
    const file = queue.pop()!;
    for (const spec of importsOf(file)) {
      if (!spec.startsWith('.')) {
        packages.add(spec);
        continue;
      }
      const to = resolveRelative(file, spec);
      if (to && !files.has(to)) {
        files.add(to);
        queue.push(to);
      }
    }
  }
  return { files: [...files], packages: [...packages] };
}
