/**
 * ESLint rule `local/layers`: every import under src/ points down the layers.
 *
 *   core  ←  kit  ←  ui, workers, three  ←  scenes, practice, guide  ←  lms  ←  results, deck  ←  app
 *
 * lms (SCORM, cmi5, question banks) builds on practice's generators and checker, and results (the
 * class results page) on lms's grading; practice shows their parts through the slots of
 * src/practice/extensions.ts, registered by the app, never by importing them.
 *
 * A file may import from its own folder (for scenes: its own scene's folder) and from any lower
 * layer. ui, workers and three may import each other; folders of the feature layer (scenes,
 * practice, guide, …) and two scenes may not. Applies to static imports, re-exports, dynamic
 * `import()` and `new URL('…', import.meta.url)` (how workers are started). Bare package imports
 * are not checked. docs/ARCHITECTURE.md explains the layers.
 */
import path from 'node:path';

export const LAYERS = {
  core: 0,
  kit: 1,
  ui: 2,
  workers: 2,
  three: 2,
  scenes: 3,
  practice: 3,
  guide: 3,
  lms: 4,
  results: 5,
  deck: 5,
  app: 6,
};

/** Where a file under src/ sits: its top folder (for a scene, `scenes/<id>`) and its layer. */
export function placeOf(absFile) {
  const parts = absFile.split(path.sep);
  const i = parts.lastIndexOf('src');
  if (i < 0 || i + 1 >= parts.length - 1) return null;
  const top = parts[i + 1];
  if (!(top in LAYERS)) return null;
  const unit = top === 'scenes' && parts.length > i + 3 ? `scenes/${parts[i + 2]}` : top;
  return { top, unit, layer: LAYERS[top] };
}

/** Why importing `to` from `from` breaks the layering, or null when it is allowed. */
export function violation(from, to) {
  if (!from || !to || from.unit === to.unit) return null;
  if (to.layer < from.layer) return null;
  if (to.layer === 2 && from.layer === 2) return null;
  if (to.layer > from.layer)
    return `${from.unit} (layer ${from.layer}) must not import from ${to.unit} (layer ${to.layer}): imports point down`;
  return `${from.unit} must not import from ${to.unit}: they are side by side in layer ${from.layer}; move what both need down to kit, ui or core`;
}

export default {
  meta: {
    type: 'problem',
    docs: { description: 'Imports under src/ point down the layers (core ← kit ← ui ← scenes ← app).' },
    schema: [],
    messages: { upward: '{{why}}' },
  },
  create(context) {
    const filename = context.filename ?? context.getFilename();
    const from = placeOf(path.resolve(filename));
    if (!from) return {};
    const check = (node, spec) => {
      if (typeof spec !== 'string' || !spec.startsWith('.')) return;
      const to = placeOf(path.resolve(path.dirname(filename), spec));
      const why = violation(from, to);
      if (why) context.report({ node, messageId: 'upward', data: { why } });
    };
    const fromSource = (node) => node.source && check(node.source, node.source.value);
    return {
      ImportDeclaration: fromSource,
      ExportNamedDeclaration: fromSource,
      ExportAllDeclaration: fromSource,
      ImportExpression: (node) => node.source.type === 'Literal' && check(node.source, node.source.value),
      NewExpression(node) {
        const [a, b] = node.arguments;
        if (
          node.callee.type === 'Identifier' &&
          node.callee.name === 'URL' &&
          a?.type === 'Literal' &&
          b?.type === 'MemberExpression' &&
          b.object.type === 'MetaProperty'
        )
          check(a, a.value);
      },
    };
  },
};
