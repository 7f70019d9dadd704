import { SHELL_FLAG_NAMES, SHELL_PARAMS } from './params';
import { openFoldsValue, parseOpenFolds } from './folds';

/** Hash routing: `#/texture?u=0.4&v=0.24` → { path: '/texture', query: 'u=0.4&v=0.24' }. */
export interface Route {
  path: string;
  query: string;
}

export function parseHash(hash: string): Route {
  let h = hash.startsWith('#') ? hash.slice(1) : hash;
  if (h === '') h = '/';
  const q = h.indexOf('?');
  let path = q >= 0 ? h.slice(0, q) : h;
  const query = q >= 0 ? h.slice(q + 1) : '';
  if (!path.startsWith('/')) path = `/${path}`;
  if (path.length > 1 && path.endsWith('/')) path = path.slice(0, -1);
  return { path, query };
}

export interface ShellFlags {
  embed: boolean;
  present: boolean;
  /**
   * `ask=1`: ask, then reveal. The scene opens with its setup shown, its results hidden and its
   * animation held at the start, under a prediction prompt; Reveal (button or `v`) shows them.
   */
  ask: boolean;
  theme: 'light' | 'dark' | null;
  /** `a11y=1`: beside the scene, the text a screen reader receives (the teacher's A11y view). */
  a11y?: boolean;
  /**
   * `part=1c`: the exam sub-question to land on (the scene checks it is one of its parts). Kept in
   * links the scene writes, so a shared link lands on the same part.
   */
  part: string | null;
  /** `open=sweep,gpu`: the page's folded sections to open (./folds); kept in the links the page writes. */
  open: string[];
  /**
   * `origin=`: the only host-page origins the host API answers and height messages go to. null: no
   * `origin=` in the link (any parent). An empty list: `origin=` was given but names no usable
   * origin, so nobody is answered (a malformed restriction never widens who is).
   */
  origins: readonly string[] | null;
  /** Shell parameters the shell could not use, with a message each. */
  problems: { name: string; message: string }[];
}

/** Read the shell's own flags (embed, present, ask, theme, part, origin) from a query string. Never throws. */
export function parseShellFlags(query: string): ShellFlags {
  const flags: ShellFlags = {
    embed: false,
    present: false,
    ask: false,
    theme: null,
    part: null,
    open: [],
    origins: null,
    problems: [],
  };
  let sp: URLSearchParams;
  try {
    sp = new URLSearchParams(query);
  } catch {
    return flags;
  }
  const bool = (name: 'embed' | 'present' | 'ask' | 'a11y') => {
    const v = sp.get(name);
    if (v === null) return;
    if (v === '1' || v === 'true') flags[name] = true;
    else if (v === '0' || v === 'false') flags[name] = false;
    else flags.problems.push({ name, message: `${JSON.stringify(v.slice(0, 24))} is not 0 or 1; ignored` });
  };
  bool('embed');
  bool('present');
  bool('ask');
  bool('a11y');
  const t = sp.get('theme');
  if (t !== null) {
    if (t === 'light' || t === 'dark') flags.theme = t;
    else
      flags.problems.push({
        name: 'theme',
        message: `${JSON.stringify(t.slice(0, 24))} is not light or dark; using the system's`,
      });
  }
  const part = sp.get('part');
  if (part !== null) {
    if (/^[1-6][a-d]?$/.test(part)) flags.part = part;
    else
      flags.problems.push({
        name: 'part',
        message: `${JSON.stringify(part.slice(0, 24))} is not an exam part like 1c; showing the top of the page`,
      });
  }
  const open = parseOpenFolds(sp.get('open'));
  flags.open = open.names;
  if (open.problem) flags.problems.push({ name: 'open', message: open.problem });
  // a shell parameter given twice: the first is used, and the notice says so
  for (const name of SHELL_FLAG_NAMES) {
    const n = sp.getAll(name).length;
    if (n > 1) flags.problems.push({ name, message: `is given ${n} times; using the first` });
  }
  const o = parseOrigins(sp.get('origin'));
  flags.origins = o.origins;
  if (o.problem) flags.problems.push({ name: 'origin', message: o.problem });
  return flags;
}

/** The most origins `origin=` may name; the rest are dropped, with a notice. */
export const MAX_ORIGINS = 16;

/**
 * Parses the `origin=` parameter: a comma list of exact origins (`https://lms.example.edu`).
 * `origins` is null only when there is no `origin=` at all; an `origin=` with no usable entry
 * gives an empty list (answer nobody), never "any parent".
 */
export function parseOrigins(raw: string | null): { origins: string[] | null; problem: string | null } {
  if (raw === null) return { origins: null, problem: null };
  const origins: string[] = [];
  const bad: string[] = [];
  for (const part of raw.split(',')) {
    const s = part.trim();
    if (!s) continue;
    let ok = false;
    try {
      const u = new URL(s);
      ok = (u.protocol === 'https:' || u.protocol === 'http:') && u.origin === s.replace(/\/$/, '');
      if (ok && !origins.includes(u.origin)) origins.push(u.origin);
    } catch {
      ok = false;
    }
    if (!ok) bad.push(clip(s, 24));
  }
  const problems: string[] = [];
  if (bad.length)
    problems.push(
      `${bad
        .slice(0, 4)
        .map((b) => JSON.stringify(b))
        .join(
          ', ',
        )}${bad.length > 4 ? ` and ${bad.length - 4} more` : ''} ${bad.length > 1 ? 'are not origins' : 'is not an origin'} like https://lms.example.edu; ignored`,
    );
  if (origins.length > MAX_ORIGINS)
    problems.push(
      `names ${origins.length} origins; only the first ${MAX_ORIGINS} are answered (${origins.length - MAX_ORIGINS} dropped, from ${JSON.stringify(clip(origins[MAX_ORIGINS], 40))})`,
    );
  if (origins.length === 0)
    problems.push('names no usable origin, so no host page is answered and no height message is sent');
  return { origins: origins.slice(0, MAX_ORIGINS), problem: problems.length ? problems.join('; ') : null };
}

function clip(s: string, n: number): string {
  return s.length > n ? `${s.slice(0, n)}…` : s;
}

/** The shell flags as query entries, for links that must keep the mode. */
export function shellExtras(
  flags: Pick<ShellFlags, 'embed' | 'present' | 'theme' | 'a11y'> & {
    ask?: boolean;
    part?: string | null;
    /** The page's open folds (./folds); left out of links to other pages. */
    open?: readonly string[];
    origins?: readonly string[] | null;
  },
): Record<string, string | undefined> {
  return {
    part: flags.part ?? undefined,
    open: openFoldsValue(flags.open ?? []),
    embed: flags.embed ? '1' : undefined,
    present: flags.present ? '1' : undefined,
    ask: flags.ask ? '1' : undefined,
    theme: flags.theme ?? undefined,
    a11y: flags.a11y ? '1' : undefined,
    // an empty list stays `origin=` (nobody), so a rewritten link never drops the restriction
    origin: flags.origins ? flags.origins.join(',') : undefined,
  };
}

/**
 * What a scene's address says besides the entries the page rewrites by itself: the folds it opens
 * (`open=`) and the end of asking (`ask=`). Two addresses with the same key differ only by the
 * page's own rewrites; a different key means a link was followed (typed, pasted, back or forward).
 */
export function addressKey(hash: string): string {
  const { path, query } = parseHash(hash);
  return `${path}?${dropQueryParam(dropQueryParam(query, 'open'), 'ask')}`;
}

/**
 * `query` without the entries named `name` (e.g. `ask` once revealed); every other entry stays
 * exactly as written (its order and its encoding).
 */
export function dropQueryParam(query: string, name: string): string {
  const q = query.startsWith('?') ? query.slice(1) : query;
  if (q === '') return '';
  return q
    .split('&')
    .filter((entry) => {
      const k = entry.split('=', 1)[0];
      let key = k;
      try {
        key = decodeURIComponent(k.replace(/\+/g, ' '));
      } catch {
        /* a malformed escape: compare it as written */
      }
      return key !== name;
    })
    .join('&');
}

/**
 * What a page without a parameter schema (home, guide, practice) could not use in its query: names
 * it does not take (beyond the shell's), and names given more than once (the first is used).
 */
export function queryProblems(query: string, known: readonly string[]): { name: string; message: string }[] {
  let sp: URLSearchParams;
  try {
    sp = new URLSearchParams(query);
  } catch {
    return [{ name: '(query)', message: 'could not be read' }];
  }
  const shell: readonly string[] = SHELL_PARAMS;
  const out: { name: string; message: string }[] = [];
  const seen = new Set<string>();
  let unknown = 0;
  for (const name of sp.keys()) {
    if (seen.has(name)) continue;
    seen.add(name);
    const shown = clip(name, 24);
    if (shell.includes(name)) continue;
    if (!known.includes(name)) {
      if (++unknown <= 5) out.push({ name: shown, message: 'is not a parameter of this page; ignored' });
      continue;
    }
    const n = sp.getAll(name).length;
    if (n > 1) out.push({ name: shown, message: `is given ${n} times; using the first` });
  }
  return out;
}
