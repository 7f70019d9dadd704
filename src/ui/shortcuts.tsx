import { createContext, useCallback, useContext, useEffect, useRef, useState, type ReactNode } from 'react';
import './shortcuts.css';

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

/** Whether the classroom keys (Space, r, s) work page-wide here (classroom mode). */
const ClassroomKeysContext = createContext(false);

/**
 * Whether the page-wide classroom keys are on (`present=1`). Then `r` is the page's: back to the
 * scene's opening state (the link's parameters at load), wherever focus is.
 */
export function useClassroomKeys(): boolean {
  return useContext(ClassroomKeysContext);
}

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

/** The classroom keys (`?`, the list itself, works on every page). */
export const SHORTCUTS: readonly { key: string; label: string; action: keyof ShortcutHandlers }[] = [
  { key: 'Space', label: 'play / pause', action: 'playPause' },
  { key: 'r', label: 'back to this scene’s opening state', action: 'reset' },
  { key: 's', label: 'step', action: 'step' },
];

/**
 * A key shown in the `?` list while its owner is mounted: page-wide, or while focus is in a part
 * of the page (`where`, e.g. "On a focused 3D view").
 */
export interface KeyHelp {
  keys: string;
  label: string;
  where?: string;
}

/** The lists registered by {@link useKeyHelp}, one entry per mounted owner. */
const keyHelp = new Set<{ entries: readonly KeyHelp[] }>();

/** List `entries` among the keyboard shortcuts while mounted and not null (keep the array stable). */
export function useKeyHelp(entries: readonly KeyHelp[] | null): void {
  useEffect(() => {
    if (!entries) return;
    const token = { entries };
    keyHelp.add(token);
    return () => {
      keyHelp.delete(token);
    };
  }, [entries]);
}

/** The registered keys, each once, grouped by where they work (page-wide first), in order of registration. */
function helpGroups(): [string, KeyHelp[]][] {
  const groups = new Map<string, KeyHelp[]>([['', []]]);
  const seen = new Set<string>();
  for (const { entries } of keyHelp)
    for (const e of entries) {
      const where = e.where ?? '';
      if (seen.has(`${where}|${e.keys}`)) continue;
      seen.add(`${where}|${e.keys}`);
      if (!groups.has(where)) groups.set(where, []);
      groups.get(where)!.push(e);
    }
  return [...groups];
}

/** Space on a focused button, link, summary or box presses it: it is not the page's play / pause. */
function pressable(target: EventTarget | null): boolean {
  return (
    target instanceof Element &&
    !!target.closest('button, a[href], summary, [role="button"], [role="checkbox"], [role="radio"], input')
  );
}

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
 * Provides the shortcut registry and listens for the keys: `?` (the list of shortcuts) on every
 * page, the classroom keys (space, r, s) when `active`. The list shows the keys that work on the
 * page: the classroom keys a scene offers, and those registered with {@link useKeyHelp} (the
 * controls drawer's `c`, Reveal's `v`, a 3D view's arrows …).
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
  const dialog = useRef<HTMLDivElement>(null);
  // Esc closes the list wherever focus is (also outside classroom mode, e.g. inside the dialog).
  // The list lies over the page's corner: focus tabbed out of it would land under it, out of sight
  // (WCAG 2.4.11), so it closes when the keyboard takes focus elsewhere.
  useEffect(() => {
    if (!helpOpen) return;
    const on = (e: KeyboardEvent) => {
      if (e.key === 'Escape') {
        e.preventDefault();
        setHelpOpen(false);
      }
    };
    const away = (e: FocusEvent) => {
      const t = e.target;
      if (t instanceof Element && !dialog.current?.contains(t) && t.matches(':focus-visible'))
        setHelpOpen(false);
    };
    window.addEventListener('keydown', on);
    document.addEventListener('focusin', away);
    return () => {
      window.removeEventListener('keydown', on);
      document.removeEventListener('focusin', away);
    };
  }, [helpOpen]);
  useEffect(() => {
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
      if (e.key === '?') action = 'help';
      else if (!active) return;
      else if (e.key === ' ' || e.code === 'Space') action = pressable(e.target) ? null : 'playPause';
      else if (e.key === 'r' || e.key === 'R') action = 'reset';
      else if (e.key === 's' || e.key === 'S') action = 'step';
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
  const offered = (s: (typeof SHORTCUTS)[number]) =>
    active && [...handlersRef.current].some((h) => !!h.current[s.action]);
  const groups = helpOpen ? helpGroups() : [];
  if (helpOpen) {
    const page = SHORTCUTS.filter(offered).map(({ key, label }) => ({
      keys: key,
      label,
    }));
    groups[0][1] = [
      ...page,
      ...groups[0][1],
      { keys: '?', label: 'show this list' },
      { keys: 'Esc', label: 'close this list' },
    ];
  }
  return (
    <ShortcutContext.Provider value={registry.current}>
      <ClassroomKeysContext.Provider value={active}>{children}</ClassroomKeysContext.Provider>
      {helpOpen ? (
        <div
          ref={dialog}
          className="shortcut-help"
          role="dialog"
          aria-modal="false"
          aria-label="Keyboard shortcuts"
          data-testid="shortcut-help"
        >
          <h2>Keyboard shortcuts</h2>
          <div className="shortcut-groups">
            {groups.map(([where, keys]) => (
              <div key={where}>
                {where ? <h3>{where}</h3> : null}
                <dl>
                  {keys.map((k) => (
                    <div key={k.keys}>
                      <dt>
                        <kbd>{k.keys}</kbd>
                      </dt>
                      <dd>{k.label}</dd>
                    </div>
                  ))}
                </dl>
              </div>
            ))}
          </div>
          <button type="button" onClick={() => setHelpOpen(false)} autoFocus>
            Close
          </button>
        </div>
      ) : null}
    </ShortcutContext.Provider>
  );
}
