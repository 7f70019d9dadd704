/**
 * Service-worker registration (loaded lazily from main.tsx after the page has loaded, so it adds
 * nothing to the entry but one dynamic import). The worker precaches the whole build; when a new
 * build is deployed, its worker waits and this shows an unobtrusive notice: reloading activates it
 * and reloads the page, so a page never mixes chunks of two builds.
 */
import { registerSW } from 'virtual:pwa-register';

let shown = false;

function showUpdateNotice(update: () => void): void {
  if (shown) return;
  shown = true;
  // built with DOM calls and textContent only (no HTML strings)
  const box = document.createElement('div');
  box.className = 'update-notice';
  box.setAttribute('role', 'status');
  box.dataset.testid = 'update-notice';
  const p = document.createElement('p');
  p.textContent = 'Render Math Lab was updated.';
  const reload = document.createElement('button');
  reload.type = 'button';
  reload.textContent = 'Reload';
  reload.addEventListener('click', () => {
    reload.disabled = true;
    update();
  });
  const later = document.createElement('button');
  later.type = 'button';
  later.className = 'link-button';
  later.textContent = 'Later';
  later.setAttribute('aria-label', 'Dismiss the update notice');
  later.addEventListener('click', () => box.remove());
  box.append(p, reload, later);
  document.body.append(box);
}

/**
 * The web app manifest's link (name, icons, standalone display) is added here, not in index.html:
 * browsers fetch the manifest and an icon as soon as they see it, which on a phone's first load
 * competed with the page's own scripts (issue 15).
 */
function linkManifest(): void {
  if (document.querySelector('link[rel="manifest"]')) return;
  const link = document.createElement('link');
  link.rel = 'manifest';
  link.href = new URL('manifest.webmanifest', document.baseURI).href;
  document.head.append(link);
}

export function registerPwa(): void {
  linkManifest();
  // (Pages still running the old build in other tabs reload when the new build takes over:
  // main.tsx's controllerchange listener does it from the start, before this registration, and
  // registerSW's own 'controlling' handler too; tests/e2e/offline.spec.ts checks it.)
  const updateSW = registerSW({
    immediate: true,
    onNeedRefresh() {
      showUpdateNotice(() => void updateSW(true));
    },
    onRegisterError() {
      /* offline use is a bonus: the app works without it */
    },
  });
}
