/**
 * The host-page API: a course page that embeds a scene in an iframe drives it over postMessage.
 *
 * Requests (host → scene), all plain data:
 *   { protocol: 'render-math-lab', version: 1, id?, type: 'get' }
 *   { protocol, version, id?, type: 'set', params: { u: 0.7, wrap: 'repeat', o: [0, 0, -5] } }
 *   { protocol, version, id?, type: 'subscribe' } / { …, type: 'unsubscribe' }
 *   { protocol, version, id?, type: 'play' } / { …, type: 'pause' } / { …, type: 'seek', t: 1.5 }
 * Replies (scene → host) echo the request's `id`:
 *   { protocol, version, id, type: 'reply', ok: true, state } or { …, ok: false, error, problems? }
 * Events (after `subscribe`), one per change:
 *   { protocol, version, type: 'event', event: 'change', cause: 'user' | 'host', state }
 *   { protocol, version, type: 'event', event: 'practice-verdict', verdict: { question, seed, name, verdict } }
 *
 * Rules: only messages whose `source` is this window's parent are read (and only when the app
 * runs in a frame); with `origin=` in the URL only those origins are (none when it names no
 * usable origin: a malformed `origin=` never widens who is answered); replies go to the origin
 * the request came from. Values are validated exactly like URL parameters (`parseParams`), a
 * `set` is all-or-nothing and its error names every value it could not use; nothing received is
 * evaluated or inserted as HTML. `play`, `pause` and `seek` are `set`s of the animation's `play`
 * (0/1) and `t` parameters, so they work on scenes whose schema has them and answer an error
 * naming the parameter elsewhere.
 */
import { startTransition } from 'react';
import {
  parseParams,
  serializeParams,
  SHELL_PARAMS,
  type ParamSchema,
  type ParamSpec,
  type ParamValues,
} from '../kit/params';
import type { SceneCheck } from '../kit/scene';
import { refusedValues } from './hostCheck';

export const PROTOCOL = 'render-math-lab';
export const PROTOCOL_VERSION = 1;

/** What the host receives as `state`: the scene and its URL parameters. */
export interface HostState {
  scene: string | null;
  route: string;
  /** Every parameter of the scene, typed (numbers, strings, booleans, number lists). */
  params: Record<string, unknown>;
  /** The query string of the scene's link (parameters that differ from their defaults). */
  query: string;
}

export interface HostScene {
  id: string;
  route: string;
  schema: ParamSchema;
  /** The scene's current values (after any setParams, even before React re-renders). */
  getValues: () => ParamValues<ParamSchema>;
  setParams: (patch: Record<string, unknown>) => void;
  /** The scene's model check (SceneModule.checkValues): values it would replace by a fallback. */
  checkValues?: SceneCheck;
}

type Problem = { name: string; message: string };

/** Turns one value from a host into the text the URL parser reads; null if it has no URL form. */
export function toUrlText(v: unknown): string | null {
  if (typeof v === 'string') return v;
  if (typeof v === 'number') return String(v);
  if (typeof v === 'boolean') return v ? '1' : '0';
  if (Array.isArray(v) && v.length <= 64 && v.every((x) => typeof x === 'number'))
    return v.map((x) => String(x)).join(',');
  return null;
}

const KIND_WORDS: Record<ParamSpec['kind'], string> = {
  number: 'a number',
  enum: 'one of its words (a string)',
  string: 'a string',
  bool: 'a boolean (or 0 / 1)',
  vec3: 'a list of three numbers',
  list: 'a list of numbers',
};

function typeName(v: unknown): string {
  if (Array.isArray(v)) return 'a list';
  if (v === null) return 'null';
  return typeof v === 'object' ? 'an object' : `a ${typeof v}`;
}

/**
 * Why a host's value does not have its parameter's type, or null if it does. No conversion is
 * silent: a boolean is not a number, a one-element list is not a number, a list is not a grid's
 * text. A string is read as URL text for every kind (the way a link carries it), but must not
 * carry spaces around it where the parameter is not free text, and a boolean's text is 0, 1,
 * true or false.
 */
export function typeProblem(spec: ParamSpec, v: unknown): string | null {
  const want = () => `is ${typeName(v)}; it takes ${KIND_WORDS[spec.kind]}`;
  if (typeof v === 'string') {
    if (spec.kind !== 'string' && v !== v.trim())
      return `${JSON.stringify(clip(v, 24))} has spaces around it; send the value alone`;
    if (spec.kind === 'bool' && !/^(0|1|true|false)$/.test(v))
      return `${JSON.stringify(clip(v, 24))} is not a boolean (true, false, 0 or 1)`;
    return null;
  }
  switch (spec.kind) {
    case 'number':
      return typeof v === 'number' ? null : want();
    case 'bool':
      return typeof v === 'boolean' || v === 0 || v === 1 ? null : want();
    case 'vec3':
    case 'list':
      return Array.isArray(v) ? null : want();
    default:
      return want();
  }
}

function clip(s: string, n = 40): string {
  return s.length > n ? `${s.slice(0, n)}…` : s;
}

/**
 * Validates a host's `set` against a schema exactly as the URL would be read. Returns the patch
 * to apply, or the problems (each naming the parameter) when any value cannot be used as given.
 */
export function validateSet(
  schema: ParamSchema,
  params: unknown,
): { ok: true; patch: Record<string, unknown> } | { ok: false; problems: Problem[] } {
  if (typeof params !== 'object' || params === null || Array.isArray(params)) {
    return {
      ok: false,
      problems: [{ name: 'params', message: 'must be an object of parameter names and values' }],
    };
  }
  const problems: Problem[] = [];
  const sp = new URLSearchParams();
  const names: string[] = [];
  const keys = Object.keys(params);
  if (keys.length > 64)
    return { ok: false, problems: [{ name: 'params', message: `has ${keys.length} entries; at most 64` }] };
  for (const name of keys) {
    const raw = (params as Record<string, unknown>)[name];
    if ((SHELL_PARAMS as readonly string[]).includes(name) || name === 'origin') {
      problems.push({ name: clip(name), message: 'is set by the page’s URL, not by the host API' });
      continue;
    }
    const text = toUrlText(raw);
    if (text === null) {
      problems.push({ name: clip(name), message: 'is not a string, number, boolean or list of numbers' });
      continue;
    }
    const spec = Object.hasOwn(schema, name) ? schema[name] : undefined;
    const wrong = spec ? typeProblem(spec, raw) : null;
    if (wrong) {
      problems.push({ name, message: wrong });
      continue;
    }
    sp.append(name, text);
    names.push(name);
  }
  const parsed = parseParams(schema, sp);
  for (const p of parsed.problems)
    problems.push({ name: p.name, message: p.message.replace(/; (using|ignored).*$/, '') });
  if (problems.length) return { ok: false, problems };
  const patch: Record<string, unknown> = {};
  const values = parsed.values as Record<string, unknown>;
  for (const n of names) if (Object.hasOwn(schema, n)) patch[n] = values[n];
  return { ok: true, patch };
}

// ---- one bridge per page ---------------------------------------------------------------

interface Subscriber {
  origin: string;
}

let scene: HostScene | null = null;
// who is answered (null: any parent); nobody until the app has read its link's `origin=`
let allowed: readonly string[] | null = [];
const subscribers: Subscriber[] = [];
/** `scene?query` of the last change event, so that each change is told once. */
let lastEmitted: string | null = null;

function framed(): boolean {
  try {
    return window.parent !== window;
  } catch {
    return true;
  }
}

function targetOf(origin: string): string {
  // a parent on file:// or in a sandbox has the opaque origin "null", which postMessage cannot name
  return origin === 'null' ? '*' : origin;
}

function post(msg: Record<string, unknown>, origin: string): void {
  try {
    window.parent.postMessage({ protocol: PROTOCOL, version: PROTOCOL_VERSION, ...msg }, targetOf(origin));
  } catch {
    /* the parent went away */
  }
}

function currentRoute(): string {
  const h = window.location.hash.replace(/^#/, '');
  const q = h.indexOf('?');
  return (q >= 0 ? h.slice(0, q) : h) || '/';
}

/** The state a host sees: the scene id and its parameters (never the page's URL). */
export function hostState(s: HostScene | null): HostState {
  if (!s) return { scene: null, route: currentRoute(), params: {}, query: '' };
  const values = s.getValues();
  const params: Record<string, unknown> = {};
  for (const name of Object.keys(s.schema)) {
    const v = (values as Record<string, unknown>)[name];
    params[name] = Array.isArray(v) ? [...v] : v;
  }
  return { scene: s.id, route: s.route, params, query: serializeParams(s.schema, values) };
}

function reply(id: unknown, origin: string, body: Record<string, unknown>): void {
  const safeId =
    typeof id === 'string' ? id.slice(0, 200) : typeof id === 'number' && Number.isFinite(id) ? id : null;
  post({ type: 'reply', id: safeId, ...body }, origin);
}

/** `set`s run one after another (each waits for its checks), so replies keep the requests' order. */
let setQueue: Promise<void> = Promise.resolve();

function applySet(id: unknown, origin: string, params: unknown): void {
  setQueue = setQueue.then(() => applySetNow(id, origin, params)).catch(() => undefined);
}

function refuse(id: unknown, origin: string, problems: Problem[]): void {
  reply(id, origin, {
    ok: false,
    error: `Not applied: ${problems.map((p) => `${p.name} ${p.message}`).join('; ')}.`,
    problems,
  });
}

async function applySetNow(id: unknown, origin: string, params: unknown): Promise<void> {
  const s = scene;
  if (!s) {
    reply(id, origin, { ok: false, error: 'There is no scene on this page to set parameters of.' });
    return;
  }
  const r = validateSet(s.schema, params);
  if (!r.ok) {
    refuse(id, origin, r.problems);
    return;
  }
  // values the parser accepts but the page would replace (an expression that does not compile, a
  // fallback the scene's model would take): the whole set fails, as the README promises
  const refused = await refusedValues(s.schema, s.getValues(), r.patch, s.checkValues);
  if (refused.length) {
    refuse(id, origin, refused);
    return;
  }
  const now = scene;
  if (!now || now.id !== s.id) {
    reply(id, origin, { ok: false, error: 'Not applied: the page changed to another scene meanwhile.' });
    return;
  }
  // the scene re-renders as a transition: in slices that yield, however fast a host sets
  if (Object.keys(r.patch).length) startTransition(() => now.setParams(r.patch));
  // the state after the change (the shell updates the values synchronously in setParams)
  const state = hostState(now);
  reply(id, origin, { ok: true, state });
  maybeEmitChange(state, 'host');
}

/** The reply to a request whose `version` is not this protocol's (a number). */
export function versionError(v: unknown): string {
  const V = PROTOCOL_VERSION;
  if (typeof v === 'string')
    return `Protocol version ${JSON.stringify(clip(v, 12))} is a string; send version: ${V} (the number ${V}).`;
  if (v === undefined) return `The request has no version; send version: ${V}.`;
  const shown = typeof v === 'number' ? String(v) : typeName(v);
  return `Protocol version ${shown} is not supported; this app speaks version ${V}.`;
}

function onMessage(e: MessageEvent): void {
  if (!framed() || e.source !== window.parent) return;
  // no `origin=`: any parent; `origin=` (even one naming nothing usable): only its origins
  if (allowed !== null && !allowed.includes(e.origin)) return;
  const d: unknown = e.data;
  if (typeof d !== 'object' || d === null) return;
  const m = d as Record<string, unknown>;
  if (m.protocol !== PROTOCOL) return;
  if (m.version !== PROTOCOL_VERSION) {
    reply(m.id, e.origin, {
      ok: false,
      error: versionError(m.version),
    });
    return;
  }
  switch (m.type) {
    case 'get':
      reply(m.id, e.origin, { ok: true, state: hostState(scene) });
      return;
    case 'set':
      applySet(m.id, e.origin, m.params);
      return;
    case 'play':
    case 'pause':
      applySet(m.id, e.origin, { play: m.type === 'play' ? 1 : 0 });
      return;
    case 'seek':
      if (typeof m.t !== 'number') {
        reply(m.id, e.origin, { ok: false, error: 'seek needs a number t (the animation time).' });
        return;
      }
      applySet(m.id, e.origin, { t: m.t });
      return;
    case 'subscribe':
      if (!subscribers.some((s) => s.origin === e.origin)) subscribers.push({ origin: e.origin });
      if (scene) lastEmitted = key(hostState(scene));
      reply(m.id, e.origin, { ok: true, state: hostState(scene) });
      return;
    case 'unsubscribe': {
      const i = subscribers.findIndex((s) => s.origin === e.origin);
      if (i >= 0) subscribers.splice(i, 1);
      reply(m.id, e.origin, { ok: true });
      return;
    }
    default:
      reply(m.id, e.origin, {
        ok: false,
        error: `Unknown request type ${JSON.stringify(String(m.type).slice(0, 24))}; use get, set, subscribe, unsubscribe, play, pause or seek.`,
      });
  }
}

function key(st: HostState): string {
  return `${st.scene ?? ''}?${st.query}`;
}

function maybeEmitChange(st: HostState, cause: 'user' | 'host'): void {
  if (!subscribers.length) return;
  const k = key(st);
  if (k === lastEmitted) return;
  lastEmitted = k;
  emit({ event: 'change', cause, state: st });
}

function emit(msg: Record<string, unknown>): void {
  for (const s of subscribers) post({ type: 'event', ...msg }, s.origin);
}

function onVerdict(e: Event): void {
  const detail = (e as CustomEvent<unknown>).detail;
  if (typeof detail !== 'object' || detail === null) return;
  const d = detail as Record<string, unknown>;
  const plain = (v: unknown) =>
    typeof v === 'string' ? v.slice(0, 200) : typeof v === 'number' || typeof v === 'boolean' ? v : null;
  emit({
    event: 'practice-verdict',
    route: currentRoute(),
    verdict: {
      question: plain(d.question),
      seed: plain(d.seed),
      name: plain(d.name),
      verdict: plain(d.verdict),
    },
  });
}

/**
 * What the page's bridge (./hostBridge.ts, in the entry) calls once this module has loaded: the
 * handlers for requests and practice verdicts, and the allowed origins and the scene on screen.
 */
export const host = {
  onMessage,
  onVerdict,
  setAllowed(origins: readonly string[] | null): void {
    allowed = origins;
  },
  /** The scene on screen (null when it leaves); tells subscribers about the change it makes. */
  setScene(s: HostScene | null): void {
    scene = s;
    if (s) maybeEmitChange(hostState(s), 'user');
  },
  /** The scene's values changed (by the reader or by a `set`). */
  changed(s: HostScene): void {
    if (scene !== s) scene = s;
    maybeEmitChange(hostState(s), 'user');
  },
  /** The scene is leaving: forget it unless another has taken its place. */
  leave(s: HostScene): void {
    if (scene === s) scene = null;
  },
};
