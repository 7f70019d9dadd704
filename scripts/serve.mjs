#!/usr/bin/env node
/**
 * A tiny static server for the built app (no dependencies). Serves DIR at /app/ (a sub-folder, to
 * prove the build works from any folder) and at /. Binds 127.0.0.1 only.
 *   node scripts/serve.mjs [dir=dist] [port=4173] [--gzip]
 * --gzip: compress text responses (JS, CSS, HTML, JSON, SVG) with gzip when the client accepts it,
 * as a production static host would (used by `npm run perf`, so Lighthouse sees real transfer sizes).
 */
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { gzipSync } from 'node:zlib';
import { extname, join, normalize, resolve } from 'node:path';

const argv = process.argv.slice(2);
const gzip = argv.includes('--gzip');
const positional = argv.filter((a) => !a.startsWith('--'));
const dir = resolve(positional[0] ?? 'dist');
const port = Number(positional[1] ?? 4173);
const types = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.woff2': 'font/woff2',
  '.woff': 'font/woff',
  '.ttf': 'font/ttf',
  '.wasm': 'application/wasm',
  '.ico': 'image/x-icon',
};
const COMPRESSIBLE = new Set(['.html', '.js', '.mjs', '.css', '.json', '.svg', '.ttf']);
/** gzip output per file path and modification time (the build does not change while served). */
const gzCache = new Map();

const server = createServer(async (req, res) => {
  try {
    let path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    if (path.startsWith('/app/')) path = path.slice(4);
    else if (path === '/app') path = '/';
    if (path.endsWith('/')) path += 'index.html';
    const file = normalize(join(dir, path));
    if (!file.startsWith(dir)) throw Object.assign(new Error('forbidden'), { code: 'ENOENT' });
    const st = await stat(file);
    if (!st.isFile()) throw Object.assign(new Error('not a file'), { code: 'ENOENT' });
    let body = await readFile(file);
    const headers = {
      'content-type': types[extname(file)] ?? 'application/octet-stream',
      // hashed build files never change under their name (as a production host serves them), so
      // a browser may keep them, and V8 its compiled code; the rest (index.html, the service
      // worker, the manifest) is fetched fresh so that a new build is seen at once
      'cache-control': path.startsWith('/assets/') ? 'public, max-age=31536000, immutable' : 'no-store',
    };
    if (gzip && COMPRESSIBLE.has(extname(file))) {
      headers.vary = 'accept-encoding';
      if (/\bgzip\b/.test(String(req.headers['accept-encoding'] ?? ''))) {
        const key = `${file}:${st.mtimeMs}`;
        let z = gzCache.get(key);
        if (!z) gzCache.set(key, (z = gzipSync(body, { level: 9 })));
        body = z;
        headers['content-encoding'] = 'gzip';
      }
    }
    headers['content-length'] = body.length;
    res.writeHead(200, headers);
    res.end(body);
  } catch {
    res.writeHead(404, { 'content-type': 'text/plain' });
    res.end('not found');
  }
});
server.listen(port, '127.0.0.1', () =>
  console.log(`serving ${dir}${gzip ? ' (gzip)' : ''} at http://127.0.0.1:${port}/app/`),
);
for (const sig of ['SIGINT', 'SIGTERM']) process.on(sig, () => server.close(() => process.exit(0)));
