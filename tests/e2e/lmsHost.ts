/**
 * Helpers for the LMS browser tests: build a package in-process from the single-file build, unzip
 * it, and serve it (with a host page and scorm-again) from a loopback server on the test's port.
 */
import { createServer, type IncomingMessage, type Server, type ServerResponse } from 'node:http';
import { existsSync, readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { unzipSync } from 'fflate';
import { buildPackages, type PackageOutputs } from '../../src/lms/packages';
import type { QuestionId } from '../../src/practice/model';

export const SINGLE = 'dist-single/index.html';

export function haveSingle(): boolean {
  return existsSync(SINGLE);
}

/** The static build's files (LMS_TEST_APP=dist runs the package tests on it instead). */
function staticApp(dir: string): Record<string, Uint8Array> {
  const out: Record<string, Uint8Array> = {};
  const walk = (d: string) => {
    for (const n of readdirSync(d)) {
      const p = join(d, n);
      if (statSync(p).isDirectory()) walk(p);
      else if (!/^(sw\.js|workbox-.*\.js)$/.test(n))
        out[relative(dir, p).split('\\').join('/')] = new Uint8Array(readFileSync(p));
    }
  };
  walk(dir);
  return out;
}

/** Build the packages for `questions` (one variant each in the banks) from dist-single. */
export function packages(questions: QuestionId[], seed: number, mastery = 0.8): PackageOutputs {
  const dir = process.env.LMS_TEST_APP;
  const app = dir ? staticApp(dir) : { 'index.html': new Uint8Array(readFileSync(SINGLE)) };
  return buildPackages({ questions, variants: 1, seed, mastery, version: 'test' }, app);
}

export function unzip(bytes: Uint8Array): Record<string, Uint8Array> {
  return unzipSync(bytes);
}

const TYPES: Record<string, string> = {
  html: 'text/html; charset=utf-8',
  js: 'text/javascript; charset=utf-8',
  xml: 'application/xml',
  json: 'application/json',
};

export type Handler = (req: IncomingMessage, res: ServerResponse, body: string) => boolean;

/**
 * A 127.0.0.1 server on a free port (each test worker gets its own): files by path, then the
 * handler, else 404. Returns the server and its origin.
 */
export async function serve(
  files: Map<string, Uint8Array | string>,
  handler?: Handler,
): Promise<{ server: Server; origin: string }> {
  const server = createServer((req, res) => {
    const chunks: Buffer[] = [];
    req.on('data', (c: Buffer) => chunks.push(c));
    req.on('end', () => {
      const body = Buffer.concat(chunks).toString('utf8');
      const path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
      const f = files.get(path);
      if (f !== undefined && req.method === 'GET') {
        res.writeHead(200, {
          'content-type': TYPES[path.split('.').pop() ?? ''] ?? 'application/octet-stream',
        });
        res.end(f);
        return;
      }
      if (handler && handler(req, res, body)) return;
      res.writeHead(404);
      res.end();
    });
  });
  await new Promise<void>((ok) => server.listen(0, '127.0.0.1', ok));
  const addr = server.address();
  const port = typeof addr === 'object' && addr ? addr.port : 0;
  return { server, origin: `http://127.0.0.1:${port}` };
}
