import { describe, expect, it } from 'vitest';
import { runInNewContext } from 'node:vm';
import {
  lateManifestLink,
  preloadScript,
  routePreload,
  sceneOfChunk,
  scenePreloadMap,
} from '../../scripts/routePreload';
// @ts-expect-error plain ESM helper without types
import { readPreloadMap } from '../../scripts/preloadMap.mjs';

type Chunk = Parameters<typeof scenePreloadMap>[0][string];
const chunk = (
  fileName: string,
  o: Partial<{
    imports: string[];
    isEntry: boolean;
    isDynamicEntry: boolean;
    facadeModuleId: string;
    css: string[];
  }> = {},
): Chunk => ({
  type: 'chunk',
  fileName,
  imports: o.imports ?? [],
  isEntry: o.isEntry ?? false,
  isDynamicEntry: o.isDynamicEntry ?? false,
  facadeModuleId: o.facadeModuleId ?? null,
  viteMetadata: { importedCss: new Set(o.css ?? []) },
});

// a bundle like the real one: an entry with a runtime chunk, two scenes sharing a chunk, a lazy
// chunk that is not a scene (practice), and a scene whose static imports form a chain
const bundle = Object.fromEntries(
  [
    chunk('assets/index.js', {
      isEntry: true,
      imports: ['assets/runtime.js'],
      facadeModuleId: '/p/src/app/main.tsx',
      css: ['assets/index.css'],
    }),
    chunk('assets/runtime.js'),
    chunk('assets/scene-a.js', {
      isDynamicEntry: true,
      facadeModuleId: '/p/src/scenes/alpha/index.ts',
      imports: ['assets/shared.js', 'assets/runtime.js'],
      css: ['assets/a.css'],
    }),
    chunk('assets/scene-b.js', {
      isDynamicEntry: true,
      facadeModuleId: '/p/src/scenes/beta-2/index.ts',
      imports: ['assets/shared.js', 'assets/deep1.js'],
    }),
    chunk('assets/shared.js', { css: ['assets/shared.css'] }),
    chunk('assets/deep1.js', { imports: ['assets/deep2.js'] }),
    chunk('assets/deep2.js', { imports: ['assets/deep1.js'] }), // a cycle must not loop
    chunk('assets/practice.js', {
      isDynamicEntry: true,
      facadeModuleId: '/p/src/practice/PracticeRoute.tsx',
      imports: ['assets/shared.js'],
    }),
    // a question page: the page's chunk and the question's generator, both loaded by the practice chunk
    chunk('assets/question.js', {
      isDynamicEntry: true,
      facadeModuleId: '/p/src/practice/QuestionRoute.tsx',
      imports: ['assets/shared.js', 'assets/marking.js'],
    }),
    chunk('assets/marking.js'),
    chunk('assets/q1.js', {
      isDynamicEntry: true,
      facadeModuleId: '/p/src/practice/q1.ts',
      imports: ['assets/core-a.js', 'assets/runtime.js'],
    }),
    chunk('assets/core-a.js'),
    // a generator in a chunk with no entry module (shared by a question page and the worksheet)
    { ...chunk('assets/q6.js'), moduleIds: ['/p/src/core/six.ts', '/p/src/practice/q6.ts'] },
  ].map((c) => [c.fileName, c]),
) as Parameters<typeof scenePreloadMap>[0];
(bundle as Record<string, unknown>)['assets/font.woff2'] = { type: 'asset', fileName: 'assets/font.woff2' };

describe('scenePreloadMap: the files to start with the entry, per scene', () => {
  it('maps each scene to its chunk and static import closure (scripts and CSS), minus what the entry loads', () => {
    const map = scenePreloadMap(bundle);
    // the practice page too (#/practice), and each question page (the question page's code is no
    // route by itself)
    expect(Object.keys(map).sort()).toEqual(['alpha', 'beta-2', 'practice', 'practice/q1', 'practice/q6']);
    expect(map.practice).toEqual({
      js: ['assets/practice.js', 'assets/shared.js'],
      css: ['assets/shared.css'],
    });
    // a question page: the practice chunk that loads it, the page, its own generator, nothing twice
    expect(map['practice/q1']).toEqual({
      js: [
        'assets/practice.js',
        'assets/shared.js',
        'assets/question.js',
        'assets/marking.js',
        'assets/q1.js',
        'assets/core-a.js',
      ],
      css: ['assets/shared.css'],
    });
    expect(map['practice/q6'].js).not.toContain('assets/core-a.js');
    expect(map.alpha).toEqual({
      js: ['assets/scene-a.js', 'assets/shared.js'],
      css: ['assets/a.css', 'assets/shared.css'],
    });
    expect(map['beta-2'].js.sort()).toEqual([
      'assets/deep1.js',
      'assets/deep2.js',
      'assets/scene-b.js',
      'assets/shared.js',
    ]);
    expect(map['beta-2'].css).toEqual(['assets/shared.css']);
  });
});

describe('scenePreloadMap: what the practice pages load with the practice chunk', () => {
  it('preloads the results and LMS slots with #/practice and every question page (App loads them together)', () => {
    const b = Object.fromEntries(
      [
        chunk('assets/index.js', { isEntry: true, facadeModuleId: '/p/src/app/main.tsx' }),
        chunk('assets/practice.js', {
          isDynamicEntry: true,
          facadeModuleId: '/p/src/practice/PracticeRoute.tsx',
        }),
        chunk('assets/rslots.js', {
          isDynamicEntry: true,
          facadeModuleId: '/p/src/results/slots.ts',
          imports: ['assets/version.js'],
        }),
        chunk('assets/version.js'),
        chunk('assets/lslots.js', { isDynamicEntry: true, facadeModuleId: '/p/src/lms/slots.ts' }),
        chunk('assets/question.js', {
          isDynamicEntry: true,
          facadeModuleId: '/p/src/practice/QuestionRoute.tsx',
        }),
        chunk('assets/q2.js', { isDynamicEntry: true, facadeModuleId: '/p/src/practice/q2.ts' }),
      ].map((c) => [c.fileName, c]),
    ) as Parameters<typeof scenePreloadMap>[0];
    const map = scenePreloadMap(b);
    // the slots are parts of the practice pages, no routes of their own
    expect(Object.keys(map).sort()).toEqual(['practice', 'practice/q2']);
    const slots = ['assets/lslots.js', 'assets/rslots.js', 'assets/version.js'];
    expect(map.practice.js.sort()).toEqual(['assets/practice.js', ...slots].sort());
    expect(map['practice/q2'].js.sort()).toEqual(
      ['assets/practice.js', 'assets/q2.js', 'assets/question.js', ...slots].sort(),
    );
  });
});

/** Runs the inline script against a fake page with the given hash; returns the links it added. */
function run(
  hash: string,
  base = './',
): { rel: string; as?: string; href: string; crossOrigin: string | null }[] {
  const added: { rel: string; as?: string; href: string; crossOrigin: string | null }[] = [];
  const document = {
    head: { appendChild: (l: (typeof added)[number]) => added.push(l) },
    createElement: () => ({ rel: '', href: '', crossOrigin: null }),
  };
  // the links are added in a task of their own: run it at once (and check it was asked for)
  const timers: Array<() => void> = [];
  const setTimeout = (f: () => void) => void timers.push(f);
  runInNewContext(preloadScript(scenePreloadMap(bundle), base), { document, location: { hash }, setTimeout });
  expect(added).toEqual([]);
  timers.forEach((f) => f());
  return added;
}

/** The files the inline script preloads for this hash, sorted. */
const hrefs = (hash: string) =>
  run(hash)
    .map((l) => l.href)
    .sort();

describe('the inline preload script', () => {
  it('adds modulepreload links for the scene of the hash route, and style preloads for its CSS', () => {
    expect(run('#/alpha?x=1&y=2')).toEqual([
      { rel: 'modulepreload', href: './assets/scene-a.js', crossOrigin: '' },
      { rel: 'modulepreload', href: './assets/shared.js', crossOrigin: '' },
      { rel: 'preload', as: 'style', href: './assets/a.css', crossOrigin: '' },
      { rel: 'preload', as: 'style', href: './assets/shared.css', crossOrigin: '' },
    ]);
    // the spellings the router accepts: no leading slash, a trailing slash
    expect(run('#beta-2').map((l) => l.href)).toContain('./assets/scene-b.js');
    expect(run('#/beta-2/').map((l) => l.href)).toContain('./assets/scene-b.js');
    expect(run('#/alpha', '/sub/')[0].href).toBe('/sub/assets/scene-a.js');
  });

  it('preloads the practice page on #/practice (with or without a query)', () => {
    for (const h of ['#/practice', '#/practice?q=3'])
      expect(hrefs(h), h).toEqual(['./assets/practice.js', './assets/shared.css', './assets/shared.js']);
  });

  it('preloads a practice question with the practice chunk that loads it and its own generator only', () => {
    for (const h of ['#/practice/q1', '#/practice/q1?seed=3'])
      expect(hrefs(h), h).toEqual([
        './assets/core-a.js',
        './assets/marking.js',
        './assets/practice.js',
        './assets/q1.js',
        './assets/question.js',
        './assets/shared.css',
        './assets/shared.js',
      ]);
    expect(hrefs('#/practice/q6')).toEqual([
      './assets/marking.js',
      './assets/practice.js',
      './assets/q6.js',
      './assets/question.js',
      './assets/shared.css',
      './assets/shared.js',
    ]);
  });

  it('is read back from the page by scripts/preloadMap.mjs (for the size budgets) as it was given', () => {
    const map = scenePreloadMap(bundle);
    const html = `<head><script>${preloadScript(map, './')}</script></head>`;
    expect(readPreloadMap(html)).toEqual(map);
    expect(readPreloadMap('<head></head>')).toBeNull();
  });

  it('adds nothing for the home page, other routes, and hostile hashes (own keys only, never throws)', () => {
    for (const h of [
      '',
      '#/',
      '#/guide',
      '#/practice/alpha',
      '#/practice/q7',
      '#/practice/question',
      '#/practice/q1/x',
      '#/nope',
      '#/__proto__',
      '#/constructor',
      '#/toString',
      '#/hasOwnProperty',
      '#/alpha/extra',
      '#/%61lpha',
      `#/${'x'.repeat(5000)}`,
    ]) {
      expect(run(h), h).toEqual([]);
    }
  });

  it('cannot be broken out of by file names (no raw "<" in the script)', () => {
    const s = preloadScript({ x: { js: ['a</script><script>alert(1)</script>.js'], css: [] } }, './');
    expect(s).not.toContain('<');
  });
});

describe('routePreload: where the script goes in index.html', () => {
  const hook = routePreload().transformIndexHtml as {
    handler: (html: string, ctx: { bundle?: unknown }) => string;
  };
  it("goes after the entry's script and module preloads (the entry is requested first) and before the stylesheet", () => {
    const html =
      '<head><title>t</title>\n    <script type="module" crossorigin src="./assets/index.js"></script>\n' +
      '    <link rel="modulepreload" crossorigin href="./assets/runtime.js">\n' +
      '    <link rel="stylesheet" crossorigin href="./assets/index.css"></head><body></body>';
    const out = hook.handler(html, { bundle });
    const script = out.indexOf('<script>(function');
    expect(script).toBeGreaterThan(out.indexOf('<script type="module"'));
    expect(script).toBeGreaterThan(out.indexOf('rel="modulepreload"'));
    expect(script).toBeLessThan(out.indexOf('rel="stylesheet"'));
    expect(out.replace(/<script>\(function.*?<\/script>\n {4}/, '')).toBe(html);
  });
  it('goes at the end of the head when there is no stylesheet, and not at all without a bundle', () => {
    const html = '<head><script type="module" src="./assets/index.js"></script></head><body></body>';
    const out = hook.handler(html, { bundle });
    expect(out.indexOf('<script>(function')).toBeGreaterThan(out.indexOf('<script type="module"'));
    expect(out.indexOf('<script>(function')).toBeLessThan(out.indexOf('</head>'));
    expect(hook.handler(html, {})).toBe(html);
  });
});

describe('lateManifestLink', () => {
  it("takes the PWA plugin's manifest link out of index.html and leaves the rest", () => {
    const hook = lateManifestLink().transformIndexHtml as { handler: (html: string) => string };
    const html =
      '<head>\n  <link rel="stylesheet" href="./a.css">\n  <link rel="manifest" href="./manifest.webmanifest"></head><body></body>';
    expect(hook.handler(html)).toBe('<head>\n  <link rel="stylesheet" href="./a.css"></head><body></body>');
  });
});

describe('sceneOfChunk', () => {
  it('names the scene by the chunk’s entry module, else by a module it holds', () => {
    expect(sceneOfChunk({ facadeModuleId: '/p/src/scenes/beta-2/index.ts' })).toBe('beta-2');
    expect(
      sceneOfChunk({
        facadeModuleId: null,
        moduleIds: ['/p/src/scenes/alpha/view/Figure.tsx', '/p/src/scenes/alpha/index.ts'],
      }),
    ).toBe('alpha');
  });
  it('is null for a chunk holding no scene’s index (a scene’s other modules do not count)', () => {
    expect(sceneOfChunk({ facadeModuleId: '/p/src/practice/PracticeRoute.tsx', moduleIds: [] })).toBeNull();
    expect(
      sceneOfChunk({ moduleIds: ['/p/src/scenes/alpha/model.ts', '/p/src/scenes/index.ts'] }),
    ).toBeNull();
    expect(sceneOfChunk({})).toBeNull();
  });
});
