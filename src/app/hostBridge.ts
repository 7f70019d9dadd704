/**
 * The host-page API's foothold in the entry chunk. The API itself (./hostApi.ts: validation,
 * replies, subscriptions) is needed only when the app runs in a frame, so it loads then, as its
 * own chunk; a page opened directly never loads it. Requests that arrive before it has loaded are
 * queued and handed over in order, so a host that asks at once is still answered.
 */
import { useEffect, useRef } from 'react';
import type { HostScene } from './hostApi';

type HostModule = typeof import('./hostApi');

let loaded: HostModule['host'] | null = null;
let loading: Promise<void> | null = null;
let allowed: readonly string[] | null = [];
let scene: HostScene | null = null;
const queued: { kind: 'message' | 'verdict'; e: Event }[] = [];

function framed(): boolean {
  try {
    return window.parent !== window;
  } catch {
    return true;
  }
}

function load(): void {
  loading ??= import('./hostApi').then(
    (m) => {
      loaded = m.host;
      loaded.setAllowed(allowed);
      if (scene) loaded.setScene(scene);
      for (const { kind, e } of queued.splice(0)) deliver(kind, e);
    },
    () => {
      // the chunk could not load (offline, a build replaced): requests go unanswered, as without a host API
      queued.length = 0;
    },
  );
}

function deliver(kind: 'message' | 'verdict', e: Event): void {
  if (!loaded) {
    if (queued.length < 100) queued.push({ kind, e });
    load();
  } else if (kind === 'message') loaded.onMessage(e as MessageEvent);
  else loaded.onVerdict(e);
}

const onMessage = (e: MessageEvent) => deliver('message', e);
const onVerdict = (e: Event) => deliver('verdict', e);

/** The page-wide bridge (call once, in the app): listens for requests and practice verdicts. */
export function useHostApi(origins: readonly string[] | null): void {
  useEffect(() => {
    allowed = origins;
    loaded?.setAllowed(origins);
  }, [origins]);
  useEffect(() => {
    if (!framed()) return;
    load();
    window.addEventListener('message', onMessage);
    window.addEventListener('rml:practice-verdict', onVerdict);
    return () => {
      window.removeEventListener('message', onMessage);
      window.removeEventListener('rml:practice-verdict', onVerdict);
    };
  }, []);
}

/** Registers the scene on screen with the bridge and tells subscribers about every change. */
export function useHostScene(s: HostScene, values: unknown): void {
  const ref = useRef(s);
  ref.current = s;
  useEffect(() => {
    if (!framed()) return;
    scene = ref.current;
    loaded?.setScene(scene);
    return () => {
      // the latest registration (a `set` or the reader may have replaced the first one)
      if (scene === ref.current) scene = null;
      loaded?.leave(ref.current);
    };
  }, []);
  useEffect(() => {
    if (!framed()) return;
    if (scene !== ref.current) scene = ref.current;
    loaded?.changed(ref.current);
  }, [values]);
}
