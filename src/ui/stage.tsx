/**
 * The stage: a scene's main figure, its key readouts and its transport in one container
 * (class `scene-stage`), with a fullscreen button. In classroom mode (`present=1`) SceneLayout
 * shows it first, sized to what is left of the first screen, with the controls in a drawer.
 *
 * Sizing the figure: in classroom mode the stage is a flex column exactly as tall as the rest of
 * the first screen; the element with the class `stage-figure` takes the height left over by the
 * readouts and the transport (`min-height: 0`, so an SVG with a viewBox and `height: 100%` shrinks
 * to fit). `--stage-h` on the stage holds that height for figures sized in script.
 */
import { useCallback, useEffect, useId, useLayoutEffect, useRef, useState, type ReactNode } from 'react';
import { Deferred } from './Deferred';
import { usePageKey } from './pageKeys';
import './stage.css';

function fullscreenAvailable(): boolean {
  return (
    typeof document !== 'undefined' &&
    document.fullscreenEnabled !== false &&
    typeof HTMLElement.prototype.requestFullscreen === 'function'
  );
}

/** The stage's fullscreen state and a toggle (Esc leaves fullscreen: the browser's own key). */
function useFullscreen(ref: { current: HTMLElement | null }) {
  const [full, setFull] = useState(false);
  useEffect(() => {
    const on = () => setFull(!!ref.current && document.fullscreenElement === ref.current);
    document.addEventListener('fullscreenchange', on);
    return () => document.removeEventListener('fullscreenchange', on);
  }, [ref]);
  const toggle = useCallback(() => {
    const el = ref.current;
    if (!el) return;
    // a refusal (no user gesture, a frame without allowfullscreen) leaves the page as it is
    if (document.fullscreenElement) void document.exitFullscreen().catch(() => undefined);
    else void Promise.resolve(el.requestFullscreen()).catch(() => undefined);
  }, [ref]);
  return { full, toggle };
}

/**
 * Keeps `--stage-top` on the element: its distance from the top of the page, so CSS can size it to
 * the rest of the first screen (recomputed when the page above it or the window changes).
 */
function useStageTop(ref: { current: HTMLElement | null }, active: boolean) {
  useLayoutEffect(() => {
    const el = ref.current;
    if (!active || !el) return;
    let last = '';
    const measure = () => {
      const top = `${Math.max(0, Math.round(el.getBoundingClientRect().top + window.scrollY))}px`;
      if (top !== last) el.style.setProperty('--stage-top', (last = top));
    };
    measure();
    window.addEventListener('resize', measure);
    const main = el.closest('main') ?? document.body;
    const ro = typeof ResizeObserver === 'function' ? new ResizeObserver(measure) : null;
    ro?.observe(main);
    return () => {
      window.removeEventListener('resize', measure);
      ro?.disconnect();
    };
  }, [ref, active]);
}

export interface StageProps {
  children: ReactNode;
  /** Classroom mode: the stage fills the first screen and holds the controls drawer. */
  staged: boolean;
  /** The scene's controls, in the drawer (staged only). */
  controls?: ReactNode;
}

/** The stage container; see the file's comment. */
export function Stage({ children, staged, controls }: StageProps) {
  const ref = useRef<HTMLDivElement>(null);
  const { full, toggle } = useFullscreen(ref);
  useStageTop(ref, staged);
  // known in the first render: a button that appeared after it pushed the whole figure down
  const [canFull] = useState(fullscreenAvailable);
  return (
    <div
      ref={ref}
      className={`scene-stage${staged ? ' is-staged' : ''}${full ? ' is-fullscreen' : ''}`}
      data-testid="scene-stage"
    >
      <div className="stage-bar">
        {staged ? <DrawerToggle>{controls}</DrawerToggle> : null}
        {canFull ? (
          <button
            type="button"
            className="stage-fullscreen"
            data-testid="fullscreen"
            aria-pressed={full}
            title={full ? 'Leave fullscreen (Esc)' : 'Show the figure fullscreen (Esc leaves)'}
            onClick={toggle}
          >
            {full ? 'Leave fullscreen' : 'Fullscreen'}
          </button>
        ) : null}
      </div>
      <div className="stage-body">{children}</div>
    </div>
  );
}

/**
 * The "Controls" button (key `c`) and the drawer it opens over the stage's left side: the scene's
 * controls column, kept mounted while closed (typed text and scroll survive). Opening moves focus
 * to the drawer, closing (the button, `c`, Esc, or Close) gives it back to the button.
 */
function DrawerToggle({ children }: { children: ReactNode }) {
  const id = useId();
  const [open, setOpenState] = useState(false);
  const openRef = useRef(open);
  openRef.current = open;
  const btn = useRef<HTMLButtonElement>(null);
  const drawer = useRef<HTMLDivElement>(null);
  // closing with focus inside the drawer gives it back to the button (read before the drawer hides,
  // which drops focus to the page)
  const restore = useRef(false);
  const setOpen = useCallback((next: boolean) => {
    if (!next && openRef.current) restore.current = !!drawer.current?.contains(document.activeElement);
    setOpenState(next);
  }, []);
  useEffect(() => {
    if (open) drawer.current?.focus({ preventScroll: true });
    else if (restore.current) btn.current?.focus({ preventScroll: true });
    restore.current = false;
  }, [open]);
  usePageKey('c', () => setOpen(!openRef.current), true, 'show or hide the controls');
  useEffect(() => {
    if (!open) return;
    const on = (e: KeyboardEvent) => {
      if (e.key === 'Escape' && !e.defaultPrevented && !document.fullscreenElement) {
        e.preventDefault();
        setOpen(false);
      }
    };
    // The drawer lies over the page: focus tabbed out of it would land under it, out of sight
    // (WCAG 2.4.11), so the drawer folds away when the keyboard takes focus elsewhere. A click
    // elsewhere keeps it open (the figure beside it stays usable with the pointer).
    const away = (e: FocusEvent) => {
      const t = e.target;
      if (!(t instanceof Element) || drawer.current?.contains(t) || btn.current === t) return;
      if (t.matches(':focus-visible')) setOpen(false);
    };
    window.addEventListener('keydown', on);
    document.addEventListener('focusin', away);
    return () => {
      window.removeEventListener('keydown', on);
      document.removeEventListener('focusin', away);
    };
  }, [open, setOpen]);
  return (
    <>
      <button
        type="button"
        ref={btn}
        className="stage-controls-toggle"
        data-testid="controls-drawer-toggle"
        aria-expanded={open}
        aria-controls={id}
        aria-keyshortcuts="c"
        title="Show or hide the controls (c)"
        onClick={() => setOpen(!open)}
      >
        Controls <kbd aria-hidden="true">c</kbd>
      </button>
      <div
        id={id}
        ref={drawer}
        className="scene-controls scene-drawer"
        data-testid="controls-drawer"
        role="region"
        aria-label="Controls"
        tabIndex={-1}
        hidden={!open}
      >
        <div className="drawer-head">
          <h2 className="panel-title">Controls</h2>
          <button type="button" onClick={() => setOpen(false)}>
            Close
          </button>
        </div>
        <Deferred estimate={600}>{children}</Deferred>
      </div>
    </>
  );
}
