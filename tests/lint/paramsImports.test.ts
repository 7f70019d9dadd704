/**
 * A scene's URL schema (src/scenes/<id>/params.ts) is the URL contract: the shell, the host API,
 * the docs and the tests read it without a page. So everything it imports, directly or through
 * other files, stays below the UI: no file under src/ui/, src/three/ or src/workers/, and no React.
 * The import graph is computed from the files with TypeScript's own import scanner.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { closure } from './importGraph';

const root = path.resolve(__dirname, '../..');
const src = path.join(root, 'src');

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
