/**
 * Page-wide single-key commands and the classroom-mode flag, for the shared layout and the shell:
 * `c` (controls drawer), `v` (reveal), read whether classroom mode (`present=1`) is on.
 */
import { useEffect, useMemo, useRef, useSyncExternalStore } from 'react';
import { isTyping, useKeyHelp } from './shortcuts';

/** Classroom mode is on: the shell puts the class `present` on <html> (src/app/App.tsx). */
export function isPresent(): boolean {
  return typeof document !== 'undefined' && document.documentElement.classList.contains('present');
}

function subscribeRootClass(onChange: () => void): () => void {
  if (typeof MutationObserver !== 'function') return () => {};
  const mo = new MutationObserver(onChange);
  mo.observe(document.documentElement, { attributes: true, attributeFilter: ['class'] });
  return () => mo.disconnect();
}

/** {@link isPresent}, live (re-renders when classroom mode is switched on or off). */
export function usePresent(): boolean {
  return useSyncExternalStore(subscribeRootClass, isPresent, () => false);
}

/**
 * Calls `fn` when `key` (one character, either case) is pressed anywhere on the page while
 * `active`: not while typing in a field, not with a modifier, not when a focused control already
 * handled the key. With `help`, the key is listed under that label in the `?` list while active.
 */
export function usePageKey(key: string, fn: () => void, active = true, help?: string): void {
  const ref = useRef(fn);
  ref.current = fn;
  useKeyHelp(useMemo(() => (active && help ? [{ keys: key, label: help }] : null), [key, active, help]));
  useEffect(() => {
    if (!active) return;
    const k = key.toLowerCase();
    const on = (e: KeyboardEvent) => {
      if (e.defaultPrevented || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
      if (e.key.toLowerCase() !== k) return;
      e.preventDefault();
      ref.current();
    };
    window.addEventListener('keydown', on);
    return () => window.removeEventListener('keydown', on);
  }, [key, active]);
}
