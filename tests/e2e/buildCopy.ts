/**
 * A static server of a private copy of the build at /app/ on an ephemeral port, for the tests that
 * change what is served (take the server down, "deploy" a new build, remove a file) without
 * touching the shared one. `setDown(true)` makes every request fail as if the host were gone (the
 * connection is dropped without an answer) until `setDown(false)`; `stop()` closes the server and
 * every connection; the copy's folder is `dir`.
 */
import { createServer, type Server } from 'node:http';
import { cpSync, mkdtempSync } from 'node:fs';
import { readFile, stat } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';

const dist = process.env.E2E_DIST ?? 'dist';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.woff2': 'font/woff2',
  '.woff': 'font/woff',
  '.ttf': 'font/ttf',
};

export interface BuildCopy {
  dir: string;
  base: string;
  setDown: (down: boolean) => void;
  stop: () => Promise<void>;
}

export async function serveBuildCopy(): Promise<BuildCopy> {
  const dir = mkdtempSync(join(tmpdir(), 'rml-build-'));
  cpSync(dist, dir, { recursive: true });
  let down = false;
  const server: Server = createServer(async (req, res) => {
    if (down) {
      req.socket.destroy();
      return;
    }
    try {
      let path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
      if (!path.startsWith('/app/')) throw new Error('outside');
      path = path.slice(4);
      if (path.endsWith('/')) path += 'index.html';
      const file = normalize(join(dir, path));
      if (!file.startsWith(dir) || !(await stat(file)).isFile()) throw new Error('missing');
      res.writeHead(200, {
        'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
        'cache-control': 'no-store',
      });
      res.end(await readFile(file));
    } catch {
      res.writeHead(404);
      res.end();
    }
  });
  await new Promise<void>((ok) => server.listen(0, '127.0.0.1', ok));
  return {
    dir,
    base: `http://127.0.0.1:${(server.address() as { port: number }).port}/app/`,
    setDown: (d) => {
      down = d;
    },
    stop: () =>
      new Promise<void>((ok) => {
        server.closeAllConnections();
        server.close(() => ok());
      }),
  };
}
