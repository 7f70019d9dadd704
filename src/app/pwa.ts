/**
 * Service-worker registration (loaded lazily from main.tsx after the page has loaded, so it adds
 * nothing to the entry but one dynamic import). The worker precaches the whole build; when a new
 * build is deployed, its worker waits and every open page shows an unobtrusive notice. Clicking
 * Reload activates the new worker and reloads that page once the new worker controls it; other
 * pages keep running their build until their reader reloads them (main.tsx, src/ui/staleBuild.ts).
 *
 * Plain service-worker API, not vite-plugin-pwa's registerSW: that helper reloads every page that
 * had shown the notice as soon as the new worker takes over (discarding another tab's typed work),
 * and never reloads a page that had no controller when it loaded (a first visit), so such a page
 * stayed on the old build after its reader clicked Reload.
 */
import { showUpdateNotice } from './updateNotice';

/**
 * The web app manifest's link (name, icons, standalone display) is added here, not in index.html:
 * browsers fetch the manifest and an icon as soon as they see it, which on a phone's first load
 * competed with the page's own scripts.
 */
function linkManifest(): void {
  if (document.querySelector('link[rel="manifest"]')) return;
  const link = document.createElement('link');
  link.rel = 'manifest';
  link.href = new URL('manifest.webmanifest', document.baseURI).href;
  document.head.append(link);
}

let reloading = false;
function reloadOnce(): void {
  if (reloading) return;
  reloading = true;
  window.location.reload();
}

/**
 * Activates the waiting worker and reloads this page as soon as it controls the page (whatever
 * controlled the page when it loaded: nothing, on a first visit, or the old worker). When there is
 * no waiting worker any more (another tab activated it), the new build is already in charge.
 */
export function activateAndReload(reg: ServiceWorkerRegistration): void {
  const waiting = reg.waiting;
  if (!waiting) {
    reloadOnce();
    return;
  }
  navigator.serviceWorker.addEventListener('controllerchange', reloadOnce, { once: true });
  waiting.addEventListener('statechange', () => {
    // activated: the controller changes with it (clientsClaim); redundant: another worker replaced
    // it, and a reload picks up whatever is active now
    if (waiting.state === 'activated' || waiting.state === 'redundant') reloadOnce();
  });
  waiting.postMessage({ type: 'SKIP_WAITING' });
}

/** A new build's worker is installed and waiting (this page runs an older build): say so. */
function watch(reg: ServiceWorkerRegistration | undefined): void {
  // (an automated browser that blocks service workers resolves the registration with nothing)
  if (!reg) return;
  const offer = () => {
    // no controller: this is the first install, which takes over by itself (nothing to reload)
    if (reg.waiting && navigator.serviceWorker.controller) showUpdateNotice(() => activateAndReload(reg));
  };
  offer();
  reg.addEventListener('updatefound', () => {
    const w = reg.installing;
    w?.addEventListener('statechange', () => {
      if (w.state === 'installed') offer();
    });
  });
  // look for a new build when the reader comes back to the tab, and every hour while it stays open
  const update = () => void reg.update().catch(() => undefined);
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'visible') update();
  });
  window.setInterval(update, 3_600_000);
}

/** Register the worker and watch for new builds; the promise settles once that is set up (never rejects). */
export function registerPwa(): Promise<void> {
  linkManifest();
  return navigator.serviceWorker
    .register(new URL('sw.js', document.baseURI).href, { scope: './' })
    .then(watch, () => {
      /* offline use is a bonus: the app works without it */
    });
}
