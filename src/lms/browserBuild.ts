/**
 * The LMS packages built in the browser (the practice sheet page): the app's own files are fetched
 * from this site (the static build lists them in app-files.json; the single-file build is one
 * page) and packed with fflate, exactly as scripts/build-lms.mjs packs them. Loaded lazily, only
 * when an instructor asks for a package.
 */
import type { PackageChoice, PackageOutputs } from './packages';

async function bytes(url: URL): Promise<Uint8Array> {
  const r = await fetch(url, { cache: 'no-cache' });
  if (!r.ok) throw new Error(`${url.pathname} answered ${r.status}`);
  return new Uint8Array(await r.arrayBuffer());
}

/** This site's copy of the app, as the packages' launch page and its files. */
export async function siteFiles(
  onProgress?: (done: number, total: number) => void,
): Promise<Record<string, Uint8Array>> {
  const page = new URL(window.location.href);
  page.hash = '';
  page.search = '';
  const base = new URL('.', page);
  if (import.meta.env.MODE === 'single') {
    const index = await bytes(page);
    return { 'index.html': index };
  }
  const list = (await (
    await fetch(new URL('app-files.json', base), { cache: 'no-cache' })
  ).json()) as unknown;
  if (
    !Array.isArray(list) ||
    !list.every((f) => typeof f === 'string' && !f.includes('..') && !/^[a-z]+:/i.test(f))
  )
    throw new Error('app-files.json is not a list of files');
  const files: Record<string, Uint8Array> = {};
  let done = 0;
  const queue = [...(list as string[])];
  const worker = async () => {
    for (let f = queue.shift(); f !== undefined; f = queue.shift()) {
      files[f] = await bytes(new URL(f, base));
      onProgress?.(++done, list.length);
    }
  };
  await Promise.all(Array.from({ length: 6 }, worker));
  if (!files['index.html']) throw new Error('the app list has no index.html');
  return files;
}

let cachedApp: Promise<Record<string, Uint8Array>> | null = null;

export async function buildInBrowser(
  choice: PackageChoice,
  onProgress?: (text: string) => void,
): Promise<PackageOutputs> {
  if (!cachedApp) {
    cachedApp = siteFiles((d, t) => onProgress?.(`Fetching the app: ${d} of ${t} files…`));
    cachedApp.catch(() => (cachedApp = null));
  }
  const [app, { buildPackages }, { katexMathml }, katex] = await Promise.all([
    cachedApp,
    import('./packages'),
    import('./mathml'),
    import('katex'),
  ]);
  onProgress?.('Packing…');
  return buildPackages(choice, app, katexMathml(katex.default));
}
