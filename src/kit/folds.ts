/**
 * Folded parts of a page and the `open=` link parameter that remembers them.
 *
 * A page shows the exam first; everything else (sweeps, tables, GPU and float32 panels, audio
 * traces, "beyond the exam") sits in a fold, closed until the reader opens it. Each fold has a
 * name, unique on its page (`sweep`, `gpu-warp`, …); `open=sweep,gpu-warp` in a link opens those
 * folds, and opening or closing one rewrites the link, so a shared link shows the same folds open.
 */

/** What a fold's name may be: lower-case letters, digits and dashes, starting with a letter. */
export const FOLD_NAME = /^[a-z][a-z0-9-]{0,31}$/;

/** The most folds one link may open; the rest are dropped, with a notice. */
export const MAX_OPEN_FOLDS = 24;

/**
 * Parses `open=`: a comma list of fold names. Never throws; names that cannot be folds are dropped
 * and said in `problem` (null when there is nothing to say). Duplicates are kept once.
 */
export function parseOpenFolds(raw: string | null): { names: string[]; problem: string | null } {
  if (raw === null) return { names: [], problem: null };
  const names: string[] = [];
  const bad: string[] = [];
  for (const entry of raw.split(',')) {
    const s = entry.trim();
    if (!s) continue;
    if (FOLD_NAME.test(s)) {
      if (!names.includes(s)) names.push(s);
    } else bad.push(s.length > 24 ? `${s.slice(0, 24)}…` : s);
  }
  const problems: string[] = [];
  if (bad.length)
    problems.push(
      `${bad
        .slice(0, 3)
        .map((b) => JSON.stringify(b))
        .join(', ')}${bad.length > 3 ? ` and ${bad.length - 3} more` : ''} ${
        bad.length > 1 ? 'are not names of folded sections' : 'is not the name of a folded section'
      } (like "sweep"); left closed`,
    );
  if (names.length > MAX_OPEN_FOLDS)
    problems.push(`names ${names.length} sections; only the first ${MAX_OPEN_FOLDS} are opened`);
  return { names: names.slice(0, MAX_OPEN_FOLDS), problem: problems.length ? problems.join('; ') : null };
}

/** The `open=` value for a set of fold names (undefined when none is open, so the link leaves it out). */
export function openFoldsValue(names: readonly string[]): string | undefined {
  return names.length ? names.join(',') : undefined;
}

/** `names` with `name` opened or closed, in the order the reader opened them. */
export function toggledFolds(names: readonly string[], name: string, open: boolean): string[] {
  const rest = names.filter((n) => n !== name);
  return open ? [...rest, name] : rest;
}
