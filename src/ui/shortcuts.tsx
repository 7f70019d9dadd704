import { createContext, useContext, useEffect, useRef, type ReactNode } from 'react';

/** Handlers a scene offers to the classroom keyboard shortcuts (space, r, s). */
export interface ShortcutHandlers {
  playPause?: () => void;
  reset?: () => void;
  step?: () => void;
}

interface Registry {
  register: (h: { current: ShortcutHandlers }) => () => void;
}

const ShortcutContext = createContext<Registry | null>(null);

/**
 * Register a scene's handlers for the classroom shortcuts. The latest handlers are always used
 * (held in a ref), so callers need not memoise them.
 */
export function useShortcuts(handlers: ShortcutHandlers): void {
  const reg = useContext(ShortcutContext);
  const ref = useRef(handlers);
  ref.current = handlers;
  useEffect(() => (reg ? reg.register(ref) : undefined), [reg]);
}

export const SHORTCUTS: readonly { key: string; label: string; action: keyof ShortcutHandlers | 'help' }[] = [
  { key: 'Space', label: 'play / pause', action: 'playPause' },
  { key: 'r', label: 'reset', action: 'reset' },
  { key: 's', label: 'step', action: 'step' },
  { key: '?', label: 'show this list', action: 'help' },
];

function isTyping(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  const tag = target.tagName;
  if (tag === 'TEXTAREA' || tag === 'SELECT' || target.isContentEditable) return true;
  if (tag === 'INPUT') {
    const type = (target as HTMLInputElement).type;
    return type !== 'checkbox' && type !== 'radio' && type !== 'button' && type !== 'range';
  }
  return false;
}

/**
 * Provides the shortcut registry and, when `active`, listens for the keys. `onHelp` toggles the
 * list of shortcuts.
 */
export function ShortcutProvider({ active, onHelp, children }: { active: boolean; onHelp: () => void; children: ReactNode }) {
  const handlersRef = useRef(new Set<{ current: ShortcutHandlers }>());
  const registry = useRef<Registry>({
    register: (h) => {
      handlersRef.current.add(h);
      return () => handlersRef.current.delete(h);
    },
  });
  const helpRef = useRef(onHelp);
  helpRef.current = onHelp;
  useEffect(() => {
    if (!active) return;
    const on = (e: KeyboardEvent) => {
      if (e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
      let action: keyof ShortcutHandlers | 'help' | null = null;
      if (e.key === ' ' || e.code === 'Space') action = 'playPause';
      else if (e.key === 'r' || e.key === 'R') action = 'reset';
      else if (e.key === 's' || e.key === 'S') action = 'step';
      else if (e.key === '?') action = 'help';
      if (!action) return;
      if (action === 'help') {
        e.preventDefault();
        helpRef.current();
        return;
      }
      let handled = false;
      for (const h of handlersRef.current) {
        const fn = h.current[action];
        if (fn) {
          fn();
          handled = true;
        }
      }
      if (handled) e.preventDefault();
    };
    window.addEventListener('keydown', on);
    return () => window.removeEventListener('keydown', on);
  }, [active]);
  return <ShortcutContext.Provider value={registry.current}>{children}</ShortcutContext.Provider>;
}
