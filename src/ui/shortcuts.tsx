import { createContext, useCallback, useContext, useEffect, useRef, useState, type ReactNode } from 'react';

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
  { key: 'r', label: 'back to this scene’s opening state', action: 'reset' },
  { key: 's', label: 'step', action: 'step' },
  { key: '?', label: 'show this list', action: 'help' },
];

/** Whether a key event's target takes text (page-wide single-letter keys must then stay out). */
export function isTyping(target: EventTarget | null): boolean {
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
export function ShortcutProvider({ active, children }: { active: boolean; children: ReactNode }) {
  const handlersRef = useRef(new Set<{ current: ShortcutHandlers }>());
  const registry = useRef<Registry>({
    register: (h) => {
      handlersRef.current.add(h);
      return () => handlersRef.current.delete(h);
    },
  });
  const [helpOpen, setHelpOpen] = useState(false);
  const helpOpenRef = useRef(helpOpen);
  helpOpenRef.current = helpOpen;
  const toggleHelp = useCallback(() => setHelpOpen((o) => !o), []);
  // Esc closes the list wherever focus is (also outside classroom mode, e.g. inside the dialog)
  useEffect(() => {
    if (!helpOpen) return;
    const on = (e: KeyboardEvent) => {
      if (e.key === 'Escape') {
        e.preventDefault();
        setHelpOpen(false);
      }
    };
    window.addEventListener('keydown', on);
    return () => window.removeEventListener('keydown', on);
  }, [helpOpen]);
  useEffect(() => {
    if (!active) return;
    const on = (e: KeyboardEvent) => {
      // defaultPrevented: a focused control (e.g. the timeline transport) already handled the key
      if (e.defaultPrevented || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
      if (e.key === 'Escape') {
        if (helpOpenRef.current) {
          e.preventDefault();
          setHelpOpen(false);
        }
        return;
      }
      let action: keyof ShortcutHandlers | 'help' | null = null;
      if (e.key === ' ' || e.code === 'Space') action = 'playPause';
      else if (e.key === 'r' || e.key === 'R') action = 'reset';
      else if (e.key === 's' || e.key === 'S') action = 'step';
      else if (e.key === '?') action = 'help';
      if (!action) return;
      if (action === 'help') {
        e.preventDefault();
        toggleHelp();
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
  }, [active, toggleHelp]);
  // the list shows only the keys that do something on this page
  const available = helpOpen
    ? SHORTCUTS.filter(
        (s) =>
          s.action === 'help' ||
          [...handlersRef.current].some((h) => !!h.current[s.action as keyof ShortcutHandlers]),
      )
    : [];
  return (
    <ShortcutContext.Provider value={registry.current}>
      {children}
      {helpOpen ? (
        <div
          className="shortcut-help"
          role="dialog"
          aria-modal="false"
          aria-label="Keyboard shortcuts"
          data-testid="shortcut-help"
        >
          <h2>Keyboard shortcuts</h2>
          <dl>
            {available.map((s) => (
              <div key={s.key}>
                <dt>
                  <kbd>{s.key}</kbd>
                </dt>
                <dd>{s.label}</dd>
              </div>
            ))}
            <div>
              <dt>
                <kbd>Esc</kbd>
              </dt>
              <dd>close this list</dd>
            </div>
          </dl>
          <button type="button" onClick={() => setHelpOpen(false)} autoFocus>
            Close
          </button>
        </div>
      ) : null}
    </ShortcutContext.Provider>
  );
}
