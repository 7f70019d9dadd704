/**
 * A scene's URL schema (src/scenes/<id>/params.ts) is the URL contract: the shell, the host API,
 * the docs and the tests read it without a page. So everything it imports, directly or through
 * other files, stays below the UI: no file under src/ui/, src/three/ or src/workers/, and no React.
 * The import graph is computed from the files with TypeScript's own import scanner.
 */
import fs from 'node:fs';
import path from 'node:path';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';

const root = path.resolve(__dirname, '../..');
const src = path.join(root, 'src');

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
function closure(entry: string): { files: string[]; packages: string[] } {
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

const schemas = fs
  .readdirSync(path.join(src, 'scenes'))
  .map((id) => path.join(src, 'scenes', id, 'params.ts'))
  .filter((f) => fs.existsSync(f));

describe('scene URL schemas import nothing from the UI', () => {
  it('finds the schemas', () => {
    expect(schemas.length).toBeGreaterThanOrEqual(5);
  });

  it('follows relative imports from one folder into another', () => {
    const { files } = closure(path.join(src, 'ui', 'TimelineTransport.tsx'));
    expect(files.map((f) => path.relative(src, f))).toContain(path.join('kit', 'timeline.ts'));
  });

  for (const file of schemas) {
    it(path.relative(root, file), () => {
      const { files, packages } = closure(file);
      const aboveKit = files
        .map((f) => path.relative(src, f).split(path.sep)[0])
        .filter((top) => top === 'ui' || top === 'three' || top === 'workers');
      expect(aboveKit).toEqual([]);
      expect(packages.filter((p) => p === 'react' || p.startsWith('react/') || p === 'react-dom')).toEqual(
        [],
      );
    });
  }
});
