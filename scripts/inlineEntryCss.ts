/**
 * Vite build plugin: index.html carries the shell's stylesheet (the design tokens, base styles and
 * site chrome that the entry imports) inline, in a `<style>`, instead of linking it.
 *
 * A linked stylesheet blocks the first paint until it has downloaded, and on a phone's few
 * connections it is one more request beside the entry's and the route's own files. The `<link>`
 * stays, marked `disabled` (a disabled stylesheet link is not fetched), because Vite's loader for
 * lazy chunks looks for a stylesheet link with that address before it adds one: with the link
 * gone, every lazy page would download the stylesheet again. A relative `url()` (KaTeX's font
 * faces, say) is rewritten to the same file's address from the page (the stylesheet's folder in
 * front of it); a stylesheet with an `@import`, or a `url()` that climbs out of its folder, stays
 * linked.
 */
import type { Plugin } from 'vite';

type BundleLike = Record<string, { type: string; fileName: string; source?: string | Uint8Array }>;

/**
 * `css`'s relative url()s addressed from the page instead of from the stylesheet, whose folder (as
 * the page addresses it, e.g. `./assets/`) is `dir`; null if one cannot be (it climbs with `..`).
 * Absolute addresses, data: URLs and fragments are kept.
 */
export function rebaseUrls(css: string, dir: string): string | null {
  let ok = true;
  const out = css.replace(/url\(\s*(['"]?)([^'")]*)\1\s*\)/g, (whole, quote: string, target: string) => {
    if (/^([a-z][a-z0-9+.-]*:|\/|#)/i.test(target)) return whole;
    if (/(^|\/)\.\.(\/|$)/.test(target)) {
      ok = false;
      return whole;
    }
    return `url(${quote}${dir}${target.replace(/^\.\//, '')}${quote})`;
  });
  return ok ? out : null;
}

/** index.html with its stylesheet links (files of `bundle`, addressed as `base` + file) inlined. */
export function inlineStylesheets(html: string, bundle: BundleLike, base: string): string {
  return html.replace(/<link\b[^>]*\brel="stylesheet"[^>]*>/g, (tag) => {
    const href = /\bhref="([^"]+)"/.exec(tag)?.[1];
    if (!href || !href.startsWith(base) || /\bdisabled\b/.test(tag)) return tag;
    const asset = bundle[href.slice(base.length)];
    if (!asset || asset.type !== 'asset' || asset.source === undefined) return tag;
    const text = typeof asset.source === 'string' ? asset.source : new TextDecoder().decode(asset.source);
    if (/@import|<\/style/i.test(text)) return tag;
    const css = rebaseUrls(text, href.slice(0, href.lastIndexOf('/') + 1));
    if (css === null) return tag;
    return `<style>${css}</style>${tag.replace(/>$/, ' disabled>')}`;
  });
}

export function inlineEntryCss(): Plugin {
  let base = './';
  return {
    name: 'rml:inline-entry-css',
    apply: 'build',
    enforce: 'post',
    configResolved(config) {
      base = config.base === '' ? './' : config.base;
    },
    transformIndexHtml: {
      order: 'post',
      handler(html, ctx) {
        return ctx.bundle ? inlineStylesheets(html, ctx.bundle as unknown as BundleLike, base) : html;
      },
    },
  };
}
