/**
 * The app's catalogue (src/kit/catalogue.ts) for Node scripts: the perf scripts read the list of
 * scenes from it, so a new scene is measured without editing them. The catalogue is pure data
 * with no imports; TypeScript's own transpiler turns it into a module here.
 */
import { readFileSync } from 'node:fs';
import ts from 'typescript';

const file = new URL('../src/kit/catalogue.ts', import.meta.url);
const js = ts.transpileModule(readFileSync(file, 'utf8'), {
  compilerOptions: { module: ts.ModuleKind.ESNext, target: ts.ScriptTarget.ES2022 },
}).outputText;
const mod = await import(`data:text/javascript;base64,${Buffer.from(js).toString('base64')}`);

/** @type {readonly {id: string, path: string, title: string, keyReadout: string}[]} */
export const SCENES = mod.SCENES;
/** @type {readonly {n: number, title: string, scene: string}[]} */
export const QUESTIONS = mod.QUESTIONS;
