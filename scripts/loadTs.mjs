/**
 * Loads a TypeScript module of src/ into a Node script: TypeScript's own transpiler turns the file
 * and every file it imports by a relative path into JavaScript under node_modules/.cache (so bare
 * imports such as 'fflate' resolve from the project's node_modules), then the module is imported.
 * For pure modules only (no DOM, no Vite-specific imports).
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import ts from 'typescript';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const cache = join(root, 'node_modules', '.cache', 'render-math-lab-ts');

function emit(file, done) {
  if (done.has(file)) return;
  done.add(file);
  const source = readFileSync(file, 'utf8');
  let js = ts.transpileModule(source, {
    compilerOptions: { module: ts.ModuleKind.ESNext, target: ts.ScriptTarget.ES2022 },
  }).outputText;
  js = js.replace(/(from\s+|import\s*\()(['"])(\.{1,2}\/[^'"]+)\2/g, (m, head, q, spec) => {
    const target = resolve(dirname(file), spec.endsWith('.ts') ? spec : `${spec}.ts`);
    emit(target, done);
    return `${head}${q}${spec.replace(/\.ts$/, '')}.mjs${q}`;
  });
  const out = join(cache, relative(root, file)).replace(/\.ts$/, '.mjs');
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, js);
}

/** Import src/<path>.ts (path relative to the repository root) as a module. */
export async function loadTs(path) {
  const file = resolve(root, path);
  emit(file, new Set());
  const out = join(cache, relative(root, file)).replace(/\.ts$/, '.mjs');
  return import(pathToFileURL(out).href);
}
