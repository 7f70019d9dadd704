/**
 * The "Render Math Lab was updated. Reload" notice. It lives in the entry (not in the lazy service
 * worker chunk) because a page of the old build must be able to show it after a new build has taken
 * over, when the old build's lazy chunks may no longer be served.
 */

let box: HTMLDivElement | null = null;

/**
 * Shows the notice once per page; `reload` runs when the reader clicks Reload (nothing reloads the
 * page without that click). A later call replaces what Reload does (e.g. once another tab has already
 * activated the new build, a plain reload is all that is left to do).
 */
export function showUpdateNotice(reload: () => void): void {
  if (box && box.isConnected) {
    const button = box.querySelector<HTMLButtonElement>('button[data-action="reload"]');
    if (button) button.onclick = () => clickReload(button, reload);
    return;
  }
  if (box) return; // dismissed with Later
  // built with DOM calls and textContent only (no HTML strings)
  box = document.createElement('div');
  box.className = 'update-notice';
  box.setAttribute('role', 'status');
  box.dataset.testid = 'update-notice';
  const p = document.createElement('p');
  p.textContent = 'Render Math Lab was updated.';
  const button = document.createElement('button');
  button.type = 'button';
  button.dataset.action = 'reload';
  button.textContent = 'Reload';
  button.onclick = () => clickReload(button, reload);
  const later = document.createElement('button');
  later.type = 'button';
  later.className = 'link-button';
  later.textContent = 'Later';
  later.setAttribute('aria-label', 'Dismiss the update notice');
  later.addEventListener('click', () => box?.remove());
  box.append(p, button, later);
  document.body.append(box);
}

function clickReload(button: HTMLButtonElement, reload: () => void): void {
  button.disabled = true;
  button.textContent = 'Reloading…';
  reload();
}
