/**
 * The build's Content-Security-Policy (scripts/csp.ts): the meta is the first element of <head>,
 * every inline script the build writes is allowed by its hash and nothing else inline is; the LMS
 * launch pages keep it, the cmi5 one admitting its learning record store.
 */
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { cspFor, inlineScripts, withCsp } from '../../scripts/csp';
import type { LmsConfig } from '../../src/lms/config';
import { launchHtml } from '../../src/lms/packages';

const hash = (s: string) => `'sha256-${createHash('sha256').update(s).digest('base64')}'`;
const policyOf = (html: string) =>
  /<meta http-equiv="Content-Security-Policy" content="([^"]*)"/.exec(html)?.[1] ?? '';
const directive = (policy: string, name: string) =>
  policy
    .split(';')
    .map((d) => d.trim())
    .find((d) => d.startsWith(`${name} `)) ?? '';

const PAGE =
  '<!doctype html><html><head><meta charset="UTF-8" /><script>var a = 1;</script></head>' +
  '<body><script type="module" src="./assets/index.js"></script><script type="module">import "x";</script></body></html>';

describe('the build’s CSP meta', () => {
  it('comes right after the charset, before any script, and allows exactly the inline scripts by hash', () => {
    const out = withCsp(PAGE);
    const at = out.indexOf('<meta http-equiv="Content-Security-Policy"');
    expect(at).toBeGreaterThan(out.indexOf('<meta charset'));
    expect(at).toBeLessThan(out.indexOf('<script'));
    expect(inlineScripts(PAGE)).toEqual(['var a = 1;', 'import "x";']);
    const script = directive(policyOf(out), 'script-src');
    expect(script).toBe(`script-src 'self' ${hash('var a = 1;')} ${hash('import "x";')}`);
    expect(script).not.toMatch(/unsafe-inline|unsafe-eval|\*/);
    expect(directive(policyOf(out), 'object-src')).toBe("object-src 'none'");
    expect(directive(policyOf(out), 'worker-src')).toBe("worker-src 'self' blob:");
    // built twice, one policy; the words inside a script (the single file's own code) stay as they are
    expect(withCsp(out).match(/Content-Security-Policy/g)).toHaveLength(1);
    const code = '<script>var re = /<meta http-equiv="Content-Security-Policy" content="x">/;</script>';
    const single = withCsp(`<html><head>${code}</head></html>`);
    expect(single).toContain(code);
    expect(single.match(/Content-Security-Policy/g)).toHaveLength(2);
    expect(cspFor([])).toContain("script-src 'self';");
  });
  it('an LMS launch page keeps it; only cmi5 admits other origins, for its record store', () => {
    const app = withCsp(PAGE);
    const cfg: LmsConfig = { kind: 'scorm12', questions: ['q1'], seed: 1, mastery: 0.8, version: 't' };
    const scorm = launchHtml(app, cfg);
    expect(policyOf(scorm)).toBe(policyOf(app));
    expect(scorm).not.toMatch(/<script>window/);
    const cmi5 = launchHtml(app, { ...cfg, kind: 'cmi5' });
    expect(directive(policyOf(cmi5), 'connect-src')).toBe("connect-src 'self' https: http:");
    expect(directive(policyOf(cmi5), 'script-src')).toBe(directive(policyOf(app), 'script-src'));
  });
});
