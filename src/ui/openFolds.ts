/**
 * Which folds of the page are open (../kit/folds): one list for the page, kept in the address's
 * `open=` entry. Opening or closing a fold rewrites that entry in place (replaceState: no history
 * entry, every other entry kept as written); a link followed on the page (hashchange) sets the
 * list again. The share bar and the scene host read it when they write a link.
 */
import { useCallback, useSyncExternalStore } from 'react';
import { openFoldsValue, toggledFolds } from '../kit/folds';
import { dropQueryParam, parseHash, parseShellFlags } from '../kit/shell';

const listeners = new Set<() => void>();
let names: readonly string[] | null = null;

/**
 * Takes the address's `open=` list, keeping the same array while the list is unchanged (React's
 * useSyncExternalStore compares snapshots by identity); true when it changed.
 */
function takeAddress(): boolean {
  const next =
    typeof window === 'undefined' ? [] : parseShellFlags(parseHash(window.location.hash).query).open;
  if (names && next.join(',') === names.join(',')) return false;
  names = next;
  return true;
}

function notify(): void {
  for (const l of listeners) l();
}

function onHashChange(): void {
  if (takeAddress()) notify();
}

/**
 * The open folds' names, in the order they were opened. While a fold or the share bar listens, the
 * list is kept here and follows the address's hashchanges; while nothing listens (between two
 * pages, say), no hashchange is heard, so the address itself is read.
 */
export function getOpenFolds(): readonly string[] {
  if (names === null || listeners.size === 0) takeAddress();
  return names as readonly string[];
}

function subscribe(l: () => void): () => void {
  if (listeners.size === 0) window.addEventListener('hashchange', onHashChange);
  listeners.add(l);
  return () => {
    listeners.delete(l);
    if (listeners.size === 0) window.removeEventListener('hashchange', onHashChange);
  };
}

/** Opens or closes the fold `name`, and writes the address's `open=` to match. */
function setFoldOpen(name: string, open: boolean): void {
  const current = getOpenFolds();
  if (current.includes(name) === open) return;
  names = toggledFolds(current, name, open);
  const { path, query } = parseHash(window.location.hash);
  const rest = dropQueryParam(query, 'open');
  const value = openFoldsValue(names);
  const qs = [rest, value ? `open=${value}` : ''].filter(Boolean).join('&');
  try {
    window.history.replaceState(window.history.state, '', `#${path}${qs ? `?${qs}` : ''}`);
  } catch {
    /* some sandboxed iframes forbid it; the state still lives in the page */
  }
  notify();
}

/** The page's open folds, re-rendering on change. */
export function useOpenFolds(): readonly string[] {
  return useSyncExternalStore(subscribe, getOpenFolds, () => []);
}

/** Whether fold `name` is open, and a setter that keeps the address in step. */
export function useFoldOpen(name: string): [boolean, (open: boolean) => void] {
  const open = useOpenFolds().includes(name);
  return [open, useCallback((o: boolean) => setFoldOpen(name, o), [name])];
}
