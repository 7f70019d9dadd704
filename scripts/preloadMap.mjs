/**
 * The route preload map that index.html carries (written by scripts/routePreload.ts's inline
 * script: a list of files, and per route the indices of its scripts and stylesheets), read back
 * as route → { js, css } file names; null when the page has none.
 * @param {string} html
 * @returns {Record<string, { js: string[], css: string[] }> | null}
 */
export function readPreloadMap(html) {
  const g = /var f=(\[.*?\]),m=(\{.*?\}),b=/.exec(html);
  if (!g) return null;
  /** @type {string[]} */
  const files = JSON.parse(g[1]);
  /** @type {Record<string, [number[], number[]]>} */
  const compact = JSON.parse(g[2]);
  /** @type {Record<string, { js: string[], css: string[] }>} */
  const out = {};
  for (const [id, [js, css]] of Object.entries(compact))
    out[id] = { js: js.map((i) => files[i]), css: css.map((i) => files[i]) };
  return out;
}
