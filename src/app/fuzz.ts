/**
 * Fuzz mode, after PhET's `?fuzz`: `#/<scene>?fuzz=1&seed=7` makes the page drive
 * itself with seeded random clicks, drags, key presses and typing into its own controls (expression
 * fields included, with a corpus of hostile strings) and reports every error it sees in a small
 * panel and on `window.__rmlFuzz`. `fuzzn=300` stops after 300 actions (the browser test uses it);
 * without it the fuzzer runs until the panel's Stop button is pressed. Actions come in bursts of
 * 1–4 per tick (every 25 ms plus the time the page takes to render).
 *
 * Loaded lazily (only when `fuzz` is in the URL, and only in a development or test build: main.tsx),
 * so it costs the entry bundle nothing. It never leaves the page: links and buttons that navigate,
 * reload or download are skipped. It never touches the reader's saved data: before its first action
 * the page's localStorage and sessionStorage are replaced by empty in-memory stores for the rest of
 * the page's life, so a Reset or a Check it presses changes nothing that outlives the tab.
 */
/** mulberry32: a tiny seeded generator (the fuzzer's choices only, not the app's randomness). */
function mulberry(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Strings typed into text fields: valid input, hostile input, and everything in between. */
export const HOSTILE_STRINGS: readonly string[] = [
  '__proto__',
  'constructor',
  'toString',
  'valueOf',
  'hasOwnProperty',
  '',
  ' ',
  'NaN',
  'Infinity',
  '-Infinity',
  '1e400',
  '-1e-400',
  '1e308*x',
  '0',
  '-0',
  '1,2,3',
  '1,,2',
  '%E0%A4%A',
  '%',
  '\u202Ecos(theta)\u202C',
  '\u200F1\u200E',
  'θ',
  'φ',
  '😀',
  '#',
  'x = 2',
  'f(x) = x',
  '[1,2]',
  '{a: 1}',
  'x ? 1 : 0',
  'import("x")',
  '"a"',
  'sin(',
  'sin()',
  'max()',
  'atan2(1)',
  'log(1,2,3)',
  'cos(theta)+1',
  '(x+3)^2',
  'cos(theta)^10000',
  'tan(theta)',
  '1/cos(theta)',
  'theta^-2',
  '1/(theta-0.5)',
  'sqrt(cos(phi))',
  'exp(1000*theta)',
  'exp('.repeat(60) + 'x' + ')'.repeat(60),
  'exp('.repeat(60) + 'theta' + ')'.repeat(60),
  '('.repeat(70) + 'x' + ')'.repeat(70),
  Array(71).fill('1').join('+'),
  'x'.repeat(401),
  '<img src=x onerror=alert(1)>',
  "'; DROP TABLE x; --",
  '1 2 3',
  '0.4',
  '-3',
  '12345678901234567890',
];

/** Numbers typed into numeric fields. */
const NUMBERS: readonly string[] = [
  '0',
  '1',
  '-1',
  '0.5',
  '1e9',
  '-1e9',
  '1e-300',
  '1e400',
  'NaN',
  '',
  '3.14159',
  '42',
  '-0',
  '7',
];

const KEYS: readonly string[] = [
  'ArrowLeft',
  'ArrowRight',
  'ArrowUp',
  'ArrowDown',
  'Home',
  'End',
  'PageUp',
  'PageDown',
  'Enter',
  ' ',
  'Escape',
  'Tab',
  'a',
  'n',
  'r',
  '1',
  '?',
  'f',
];

export interface FuzzState {
  seed: number;
  actions: number;
  limit: number | null;
  running: boolean;
  errors: string[];
  /** The last few actions, for reproducing a failure by hand. */
  log: string[];
}

declare global {
  interface Window {
    __rmlFuzz?: FuzzState & { stop: () => void };
  }
}

const SELECTOR =
  'button, input, select, textarea, summary, [role="slider"], [role="tab"], canvas, [tabindex="0"]';

function visible(el: Element): boolean {
  const r = (el as HTMLElement).getBoundingClientRect();
  return (
    r.width > 0 && r.height > 0 && !(el as HTMLInputElement).disabled && !el.closest('[inert], .fuzz-panel')
  );
}

/** Elements that would leave or reload the page, or open or save something outside it. */
function unsafe(el: Element): boolean {
  if (el.closest('a[href]')) return true;
  const t = (el.textContent ?? '').toLowerCase();
  return el.tagName === 'BUTTON' && /reload|download/.test(t);
}

/** A Storage kept in memory only. */
export function memoryStorage(): Storage {
  const m = new Map<string, string>();
  return {
    get length() {
      return m.size;
    },
    clear: () => m.clear(),
    getItem: (k: string) => m.get(String(k)) ?? null,
    key: (i: number) => [...m.keys()][i] ?? null,
    removeItem: (k: string) => void m.delete(String(k)),
    setItem: (k: string, v: string) => void m.set(String(k), String(v)),
  };
}

/** Replace the page's storages by empty in-memory ones (the reader's data stays as it was). */
function sandboxStorage(): void {
  for (const name of ['localStorage', 'sessionStorage'] as const) {
    try {
      Object.defineProperty(window, name, { value: memoryStorage(), configurable: true });
    } catch {
      /* cannot be replaced: the storage is then unreachable anyway (sandboxed frame) */
    }
  }
}

function setNativeValue(el: HTMLInputElement | HTMLTextAreaElement | HTMLSelectElement, value: string): void {
  const proto =
    el instanceof HTMLSelectElement
      ? HTMLSelectElement.prototype
      : el instanceof HTMLTextAreaElement
        ? HTMLTextAreaElement.prototype
        : HTMLInputElement.prototype;
  const setter = Object.getOwnPropertyDescriptor(proto, 'value')?.set;
  if (setter) setter.call(el, value);
  else el.value = value;
}

function key(el: Element, k: string): void {
  const init = { key: k, bubbles: true, cancelable: true };
  el.dispatchEvent(new KeyboardEvent('keydown', init));
  el.dispatchEvent(new KeyboardEvent('keyup', init));
}

/** Start fuzzing this page. Returns a stop function. */
export function startFuzz(opts: { seed: number; limit: number | null; intervalMs?: number }): () => void {
  sandboxStorage();
  const rand = mulberry(opts.seed);
  const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)];
  const state: FuzzState = {
    seed: opts.seed,
    actions: 0,
    limit: opts.limit,
    running: true,
    errors: [],
    log: [],
  };

  const panel = document.createElement('div');
  panel.className = 'fuzz-panel';
  panel.setAttribute('role', 'status');
  panel.style.cssText =
    'position:fixed;right:8px;bottom:8px;z-index:9999;max-width:22rem;padding:6px 10px;font:12px/1.4 system-ui,sans-serif;background:#fff8d6;color:#222;border:1px solid #b59b00;border-radius:6px';
  const text = document.createElement('span');
  const stopBtn = document.createElement('button');
  stopBtn.type = 'button';
  stopBtn.textContent = 'Stop fuzzing';
  stopBtn.style.marginLeft = '8px';
  panel.append(text, stopBtn);
  document.body.append(panel);
  const render = () => {
    text.textContent = `Fuzz (seed ${state.seed}): ${state.actions}${state.limit ? `/${state.limit}` : ''} actions, ${state.errors.length} error${state.errors.length === 1 ? '' : 's'}${state.errors.length ? ` — last: ${state.errors[state.errors.length - 1].slice(0, 140)}` : ''}${state.running ? '' : ' (stopped)'}`;
  };

  const onError = (e: ErrorEvent) => state.errors.push(`error: ${e.message}`);
  const onRejection = (e: PromiseRejectionEvent) =>
    state.errors.push(
      `unhandled rejection: ${e.reason instanceof Error ? e.reason.message : String(e.reason)}`,
    );
  window.addEventListener('error', onError);
  window.addEventListener('unhandledrejection', onRejection);
  const origConsoleError = console.error;
  console.error = (...args: unknown[]) => {
    state.errors.push(`console.error: ${args.map(String).join(' ').slice(0, 300)}`);
    origConsoleError.apply(console, args);
  };
  // an error panel shown by the scene's error boundary counts as an error too
  const seenAlerts = new WeakSet<Element>();
  const checkBoundary = () => {
    for (const el of document.querySelectorAll('.notice-error[role="alert"]')) {
      if (seenAlerts.has(el)) continue;
      seenAlerts.add(el);
      if (/went wrong/.test(el.textContent ?? ''))
        state.errors.push(`error panel: ${(el.textContent ?? '').slice(0, 200)}`);
    }
  };

  const act = () => {
    const all = [...document.querySelectorAll(SELECTOR)].filter((el) => visible(el) && !unsafe(el));
    if (all.length === 0) return 'nothing to act on';
    const el = pick(all) as HTMLElement;
    const what =
      el.tagName.toLowerCase() +
      (el.getAttribute('data-testid') ? `[${el.getAttribute('data-testid')}]` : el.id ? `#${el.id}` : '');
    if (el instanceof HTMLInputElement) {
      const type = el.type;
      if (type === 'range') {
        const r = rand();
        if (r < 0.5) {
          const min = Number(el.min || 0);
          const max = Number(el.max || 100);
          const v = min + rand() * (max - min);
          setNativeValue(el, String(v));
          el.dispatchEvent(new Event('input', { bubbles: true }));
          el.dispatchEvent(new Event('change', { bubbles: true }));
          return `${what} = ${v}`;
        }
        el.focus();
        const k = pick(KEYS.slice(0, 8));
        key(el, k);
        return `${what} key ${k}`;
      }
      if (type === 'checkbox' || type === 'radio') {
        el.click();
        return `click ${what}`;
      }
      if (el.readOnly) {
        el.focus();
        return `focus ${what}`;
      }
      const v = type === 'number' ? pick(NUMBERS) : rand() < 0.8 ? pick(HOSTILE_STRINGS) : pick(NUMBERS);
      el.focus();
      setNativeValue(el, v);
      el.dispatchEvent(new Event('input', { bubbles: true }));
      if (rand() < 0.6) key(el, 'Enter');
      else el.blur();
      return `type ${JSON.stringify(v.slice(0, 40))} into ${what}`;
    }
    if (el instanceof HTMLSelectElement) {
      const opts = [...el.options].map((o) => o.value);
      const v = rand() < 0.9 && opts.length ? pick(opts) : pick(HOSTILE_STRINGS.slice(0, 5));
      setNativeValue(el, v);
      el.dispatchEvent(new Event('change', { bubbles: true }));
      return `select ${JSON.stringify(v)} in ${what}`;
    }
    if (el instanceof HTMLTextAreaElement) {
      const v = pick(HOSTILE_STRINGS);
      el.focus();
      setNativeValue(el, v);
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.blur();
      return `type into ${what}`;
    }
    if (el instanceof HTMLCanvasElement) {
      const r = el.getBoundingClientRect();
      let x = r.left + rand() * r.width;
      let y = r.top + rand() * r.height;
      const base = { bubbles: true, cancelable: true, pointerId: 1, isPrimary: true, pointerType: 'mouse' };
      el.dispatchEvent(
        new PointerEvent('pointerdown', { ...base, clientX: x, clientY: y, button: 0, buttons: 1 }),
      );
      for (let i = 0; i < 4; i++) {
        x += (rand() - 0.5) * 80;
        y += (rand() - 0.5) * 80;
        el.dispatchEvent(new PointerEvent('pointermove', { ...base, clientX: x, clientY: y, buttons: 1 }));
      }
      el.dispatchEvent(new PointerEvent('pointerup', { ...base, clientX: x, clientY: y, button: 0 }));
      if (rand() < 0.3)
        el.dispatchEvent(
          new WheelEvent('wheel', {
            bubbles: true,
            cancelable: true,
            deltaY: (rand() - 0.5) * 400,
            clientX: x,
            clientY: y,
          }),
        );
      return `drag on ${what}`;
    }
    if (rand() < 0.25) {
      el.focus?.();
      const k = pick(KEYS);
      key(el, k);
      return `key ${JSON.stringify(k)} on ${what}`;
    }
    if (typeof el.click === 'function') el.click();
    else el.dispatchEvent(new MouseEvent('click', { bubbles: true, cancelable: true }));
    return `click ${what}`;
  };

  let timer: ReturnType<typeof setTimeout> | null = null;
  const stop = () => {
    state.running = false;
    if (timer !== null) clearTimeout(timer);
    timer = null;
    window.removeEventListener('error', onError);
    window.removeEventListener('unhandledrejection', onRejection);
    console.error = origConsoleError;
    render();
  };
  const step = () => {
    if (!state.running) return;
    // a burst of 1–4 actions per tick: as fast as a hurried user, and React renders once per burst
    const burst = 1 + Math.floor(rand() * 4);
    for (let b = 0; b < burst && (state.limit === null || state.actions < state.limit); b++) {
      let done: string;
      try {
        done = act();
      } catch (e) {
        done = `action threw: ${e instanceof Error ? e.message : String(e)}`;
        state.errors.push(done);
      }
      state.actions++;
      state.log.push(done);
      if (state.log.length > 20) state.log.shift();
    }
    checkBoundary();
    render();
    if (state.limit !== null && state.actions >= state.limit) {
      stop();
      return;
    }
    timer = setTimeout(step, opts.intervalMs ?? 25);
  };
  stopBtn.addEventListener('click', stop);
  window.__rmlFuzz = Object.assign(state, { stop });
  render();
  timer = setTimeout(step, 100);
  return stop;
}
