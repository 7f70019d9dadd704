/**
 * Vite build plugin: writes `app-files.json`, the list of the static build's files (every chunk,
 * stylesheet, worker and public file), so the practice sheet page can fetch the app and pack it
 * into SCORM and cmi5 zips in the browser (src/lms/browserBuild.ts). The service worker's files
 * are not listed: inside an LMS the app runs without one.
 */
import { readdirSync, statSync, writeFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import type { Plugin } from 'vite';

function walk(dir: string, root = dir): string[] {
  let out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out = out.concat(walk(p, root));
    else out.push(relative(root, p).split('\\').join('/'));
  }
  return out;
}

export function appFiles(publicDir = 'public'): Plugin {
  return {
    name: 'rml:app-files',
    apply: 'build',
    // writeBundle: the bundle as written (pure-CSS chunks that Vite drops are gone by then)
    writeBundle(options, bundle) {
      let pub: string[] = [];
      try {
        pub = walk(publicDir);
      } catch {
        pub = [];
      }
      const files = [...new Set(['index.html', ...Object.keys(bundle), ...pub])]
        .filter(
          (f) =>
            !/^(sw\.js|workbox-[^/]+\.js|registerSW\.js|app-files\.json)$/.test(f) && !f.endsWith('.map'),
        )
        .sort();
      if (options.dir) writeFileSync(join(options.dir, 'app-files.json'), `${JSON.stringify(files)}\n`);
    },
  };
}
