/**
 * Vite build plugin: a Content-Security-Policy `<meta http-equiv>` at the top of the built
 * index.html's `<head>` (after its charset, before anything that loads), so that anything injected into the page (an inline script, an event-handler
 * attribute, a script from another site) does not run. Scripts run only from the app's own origin
 * or, for the inline ones the build itself writes (the scene preloader of the static build, the
 * whole app in the single file), by the SHA-256 hash of their text, computed here once the HTML is
 * final. Workers are same-origin files (static build) or Blob URLs (single file). Styles may be
 * inline: KaTeX's markup sets style attributes. `connect-src` is the app's own origin;
 * the cmi5 package widens it to the learning record store (src/lms/packages.ts).
 *
 * Build only: the dev server injects inline scripts of its own (hot reload).
 */
import { createHash } from 'node:crypto';
import type { Plugin } from 'vite';

/** The policy's directives, but the script hashes (a meta CSP ignores frame-ancestors and reports). */
export const CSP_DIRECTIVES: Readonly<Record<string, string>> = {
  'default-src': "'self'",
  'script-src': "'self'",
  'style-src': "'self' 'unsafe-inline'",
  'img-src': "'self' data: blob:",
  'font-src': "'self' data:",
  'connect-src': "'self'",
  'worker-src': "'self' blob:",
  'manifest-src': "'self'",
  'object-src': "'none'",
  'base-uri': "'self'",
  'form-action': "'self'",
};

/** Every inline script's text in an HTML document (a `<script>` without `src`). */
export function inlineScripts(html: string): string[] {
  const out: string[] = [];
  for (const m of html.matchAll(/<script\b([^>]*)>([\s\S]*?)<\/script>/gi))
    if (!/\bsrc\s*=/i.test(m[1])) out.push(m[2]);
  return out;
}

/** The policy for a document whose inline scripts are `scripts`. */
export function cspFor(scripts: readonly string[]): string {
  const hashes = [
    ...new Set(scripts.map((s) => `'sha256-${createHash('sha256').update(s).digest('base64')}'`)),
  ];
  return Object.entries(CSP_DIRECTIVES)
    .map(([k, v]) => `${k} ${k === 'script-src' && hashes.length ? `${v} ${hashes.join(' ')}` : v}`)
    .join('; ');
}

/**
 * The document with its policy at the top of `<head>` (one the document already has,
 * before its first script, is replaced; text inside scripts is never touched: the single file's
 * code itself contains the words).
 */
export function withCsp(html: string): string {
  const firstScript = html.search(/<script\b/i);
  const headText = firstScript < 0 ? html : html.slice(0, firstScript);
  const bare =
    headText.replace(/\s*<meta http-equiv="Content-Security-Policy"[^>]*>/i, '') +
    html.slice(headText.length);
  const meta = `<meta http-equiv="Content-Security-Policy" content="${cspFor(inlineScripts(bare))}" />`;
  // after the charset (which must come within the first 1024 bytes), before anything that loads
  const anchor = /<meta charset[^>]*>/i.exec(bare) ?? /<head[^>]*>/i.exec(bare);
  const limit = firstScript < 0 ? bare.length : bare.search(/<script\b/i);
  if (!anchor || anchor.index > limit) throw new Error('csp: index.html has no <head>');
  const at = anchor.index + anchor[0].length;
  return `${bare.slice(0, at)}\n    ${meta}${bare.slice(at)}`;
}

export function contentSecurityPolicy(): Plugin {
  return {
    name: 'rml:csp',
    apply: 'build',
    enforce: 'post',
    // after every other plugin has written index.html (the single-file plugin inlines the scripts
    // in its own post generateBundle; list this plugin after it)
    generateBundle: {
      order: 'post',
      handler(_options, bundle) {
        const html = bundle['index.html'];
        if (!html || html.type !== 'asset') return;
        const text = typeof html.source === 'string' ? html.source : new TextDecoder().decode(html.source);
        html.source = withCsp(text);
      },
    },
  };
}
