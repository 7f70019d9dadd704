/**
 * A part of the page that is mounted late: when it comes near the screen, else in idle
 * time once the page's opening is over (./whenQuiet openingDone), one section per idle period in
 * page order (./viewQueue), and at once before printing. A
 * scene's exam page mounts its first screen first; the derivations, tables and plots below follow
 * in short tasks instead of one long commit (and one long layout) when the page opens on a phone.
 *
 * Sections mount one at a time: the next one starts only after the previous one has committed and
 * the browser has laid it out and painted it (a frame). Several sections that come near the
 * screen together would otherwise be rendered as one transition, committed in one task and laid
 * out in one long task; one at a time, each costs its own short commit and layout.
 *
 * Until it mounts, a placeholder keeps an estimated height (so the scroll bar is about right and
 * the page below does not jump when it arrives near the screen) and is marked
 * `data-deferred="pending"` (tests wait until none is left). Mounting is a transition: React
 * renders the subtree in slices that yield to input. Where IntersectionObserver is missing
 * everything mounts at once.
 */
import {
  createContext,
  startTransition,
  useContext,
  useEffect,
  useLayoutEffect,
  useRef,
  useState,
  type ReactNode,
} from 'react';
import { flushSync } from 'react-dom';
import { nextTask } from './chunked';
import { createViewQueue } from './viewQueue';
import { openingDone } from './whenQuiet';

/** How far below (or above) the screen a section starts mounting. */
export const DEFERRED_MARGIN = '800px 0px';

/** The longest a section holds the mounting slot (ms): one that never commits must not stop the others. */
const SLOT_TIMEOUT_MS = 1000;

/** Sections waiting for the mounting slot: those near the screen first, then in the order they asked. */
const slots: { owner: object; mount: () => void; near: boolean }[] = [];
/** The section mounting now (its commit has not been painted yet), or null. */
let holder: { owner: object; timer: ReturnType<typeof setTimeout> } | null = null;

/** Sections whose mounting has started (a transition) and not committed yet, with their mount. */
const mounting = new Map<object, () => void>();

/** Give the mounting slot to the next waiting section. */
function pump(): void {
  if (holder) return;
  const next = slots.shift();
  if (!next) return;
  holder = { owner: next.owner, timer: setTimeout(() => release(next.owner), SLOT_TIMEOUT_MS) };
  mounting.set(next.owner, next.mount);
  next.mount();
}

/** `owner` gives the slot back (now), e.g. when it unmounts before committing. */
function release(owner: object): void {
  if (holder?.owner !== owner) return;
  clearTimeout(holder.timer);
  holder = null;
  pump();
}

/** `owner` has committed: the next section mounts after this frame's layout and paint. */
function releaseAfterFrame(owner: object): void {
  if (holder?.owner !== owner) return;
  let done = false;
  const go = () => {
    if (done) return;
    done = true;
    release(owner);
  };
  // a task queued from an animation frame callback runs after that frame's layout and paint;
  // the timeout covers a hidden page (no frames)
  if (typeof requestAnimationFrame === 'function') requestAnimationFrame(() => nextTask(go));
  setTimeout(go, 100);
}

function askSlot(owner: object, mount: () => void, near: boolean): () => void {
  const entry = { owner, mount, near };
  const i = near ? slots.findIndex((s) => !s.near) : -1;
  if (i >= 0) slots.splice(i, 0, entry);
  else slots.push(entry);
  pump();
  return () => {
    const i = slots.indexOf(entry);
    if (i >= 0) slots.splice(i, 1);
    release(owner);
  };
}

const queue = createViewQueue({
  margin: DEFERRED_MARGIN,
  perIdle: 1,
  // a page that is never idle (a slow phone, a loaded machine) still gets a section every 0.5 s
  idleTimeoutMs: 500,
  idleAfter: openingDone,
  runNear: (job) => {
    runningNear = true;
    try {
      job();
    } finally {
      runningNear = false;
    }
    return () => {};
  },
});
/** True while the queue runs a job because its section is near the screen (not in idle time). */
let runningNear = false;

/**
 * The width (CSS px) of the placeholder a section replaced, as the visibility observer reported it
 * (no layout is read for it), or null. A figure that fills its section's width sizes its first
 * render with it instead of a guess, so it is not drawn twice (and nothing shifts) when its own
 * measurement (useWidth) arrives.
 */
const SectionWidth = createContext<number | null>(null);
export function useSectionWidth(): number | null {
  return useContext(SectionWidth);
}

let flushing = false;
/**
 * True while {@link flushDeferred} mounts the waiting sections for a print: a view that would
 * finish its drawing after its first painted frame must finish it at once (no frame comes before
 * the print).
 */
export function mountingForPrint(): boolean {
  return flushing;
}

/** Mount every section still waiting, synchronously (before printing). */
export function flushDeferred(): void {
  flushing = true;
  try {
    flushSync(() => {
      queue.flush();
      // and those waiting for the mounting slot, or mounting in a transition not committed yet
      for (const s of slots.splice(0)) s.mount();
      for (const m of [...mounting.values()]) m();
    });
  } finally {
    flushing = false;
  }
}

let printHooked = false;
function hookPrint(): void {
  if (printHooked || typeof window === 'undefined') return;
  printHooked = true;
  // capture: before MathTex's own beforeprint listener (on window, capture listeners run first),
  // so the formulas of the sections mounted here are sent to the typesetter by that flush too
  window.addEventListener('beforeprint', flushDeferred, { capture: true });
}

export function Deferred({
  children,
  estimate = 480,
}: {
  children: ReactNode;
  /** the placeholder's height (px) */ estimate?: number;
}) {
  // mounted at once where nothing can tell when it is near, and when first rendered by the print
  // flush (a section nested in one that the flush mounts)
  const [on, setOn] = useState(() => typeof IntersectionObserver !== 'function' || flushing);
  const [width, setWidth] = useState<number | null>(null);
  const ref = useRef<HTMLDivElement>(null);
  const owner = useRef({}).current;
  const committed = useRef(on);
  useEffect(() => {
    if (on) return;
    hookPrint();
    let cancelSlot = () => {};
    const cancel = queue.schedule(ref.current, (rect) => {
      const w = rect && rect.width > 0 ? Math.round(rect.width) : null;
      const mount = () => {
        setWidth(w);
        setOn(true);
      };
      // the print flush mounts synchronously (flushSync needs a plain update, not a transition)
      if (flushing) mount();
      else cancelSlot = askSlot(owner, () => (flushing ? mount() : startTransition(mount)), runningNear);
    });
    return () => {
      cancel();
      // unmounted (or flushed) before its commit: the slot goes to the next section now
      if (!committed.current) {
        mounting.delete(owner);
        cancelSlot();
      }
    };
  }, [on, owner]);
  // committed: the next section may start once this one is laid out and painted
  useLayoutEffect(() => {
    if (!on) return;
    committed.current = true;
    mounting.delete(owner);
    releaseAfterFrame(owner);
  }, [on, owner]);
  if (on) return <SectionWidth.Provider value={width}>{children}</SectionWidth.Provider>;
  return (
    <div ref={ref} className="deferred-pending" data-deferred="pending" style={{ minHeight: estimate }} />
  );
}
