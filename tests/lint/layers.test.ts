/**
 * The layer rule (eslint-rules/layers.js): imports under src/ point down, core ← kit ← ui ← scenes
 * ← app. The rule's own cases, then the repository's ESLint config on text placed in src/: an
 * upward import is an error there, so `npm run lint` (and `npm test`) fails on one.
 */
import path from 'node:path';
import { ESLint, RuleTester } from 'eslint';
import { describe, expect, it } from 'vitest';
// @ts-expect-error plain ESM rule without types
import layers from '../../eslint-rules/layers.js';

RuleTester.describe = describe;
RuleTester.it = it;
RuleTester.itOnly = it.only;

const root = path.resolve(__dirname, '../..');
const at = (rel: string) => path.join(root, rel);
const upward = [{ messageId: 'upward' }];

new RuleTester({ languageOptions: { ecmaVersion: 'latest', sourceType: 'module' } }).run('layers', layers, {
  valid: [
    {
      filename: at('src/scenes/texture/model.ts'),
      code: "import { lookup } from '../../core/texture/lookup';",
    },
    { filename: at('src/scenes/texture/view/A.tsx'), code: "import { m } from '../model';" },
    { filename: at('src/ui/exam.tsx'), code: "import { QUESTIONS } from '../kit/catalogue';" },
    { filename: at('src/three/Viewport.tsx'), code: "import { x } from '../ui/Deferred';" },
    { filename: at('src/workers/run.ts'), code: "import { y } from '../ui/whenQuiet';" },
    { filename: at('src/app/App.tsx'), code: "import { Guide } from '../guide/Guide';" },
    { filename: at('src/app/App.tsx'), code: "const g = () => import('../practice/PracticeRoute');" },
    { filename: at('src/kit/params.ts'), code: "import { fail } from '../core/failure';" },
    { filename: at('src/core/x.ts'), code: "import React from 'react';" },
  ],
  invalid: [
    { filename: at('src/core/sampling/a.ts'), code: "import { k } from '../../kit/params';", errors: upward },
    { filename: at('src/kit/params.ts'), code: "import { t } from '../ui/timeline';", errors: upward },
    {
      filename: at('src/ui/exam.tsx'),
      code: "import { sceneLoader } from '../scenes/registry';",
      errors: upward,
    },
    {
      filename: at('src/ui/exam.tsx'),
      code: "export { parseHash } from '../app/useHashRoute';",
      errors: upward,
    },
    {
      filename: at('src/scenes/texture/TextureScene.tsx'),
      code: "import { A } from '../../app/App';",
      errors: upward,
    },
    { filename: at('src/guide/Guide.tsx'), code: "const m = import('../app/main');", errors: upward },
    {
      filename: at('src/ui/useJob.ts'),
      code: "const w = new Worker(new URL('../scenes/monte-carlo/worker.ts', import.meta.url));",
      errors: upward,
    },
    // side by side in the feature layer: a scene may not reach into another scene or into practice
    {
      filename: at('src/scenes/texture/model.ts'),
      code: "import { m } from '../ray-sphere/model';",
      errors: upward,
    },
    {
      filename: at('src/practice/q5.ts'),
      code: "import { m } from '../scenes/ray-sphere/model';",
      errors: upward,
    },
  ],
});

describe("the repository's ESLint config", () => {
  it('reports an upward import in src/ as an error, and a downward one not at all', async () => {
    const eslint = new ESLint({ cwd: root });
    const [bad] = await eslint.lintText(
      "import { SCENES } from '../kit/catalogue';\nexport const n = SCENES.length;\n",
      {
        filePath: at('src/core/upward.ts'),
      },
    );
    expect(bad!.messages.map((m) => m.ruleId)).toContain('local/layers');
    expect(bad!.errorCount).toBeGreaterThan(0);
    const [good] = await eslint.lintText(
      "import { SCENES } from '../kit/catalogue';\nexport const n = SCENES.length;\n",
      {
        filePath: at('src/ui/downward.ts'),
      },
    );
    expect(good!.messages).toEqual([]);
  }, 60_000);
});
