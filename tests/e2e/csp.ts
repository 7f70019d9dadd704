/**
 * Browser-test helpers for the build's Content-Security-Policy (scripts/csp.ts): record every
 * violation a page reports, and try injecting script the way an attacker would.
 */
import type { BrowserContext, Page } from '@playwright/test';

/** Record every CSP violation of the context's pages, from their first script on, in `window.__csp`. */
export async function recordCspViolations(context: BrowserContext): Promise<void> {
  await context.addInitScript(() => {
    const w = window as unknown as { __csp: string[] };
    w.__csp = [];
    document.addEventListener('securitypolicyviolation', (e) =>
      w.__csp.push(`${e.violatedDirective} ${e.blockedURI}`),
    );
  });
}

export async function cspViolations(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { __csp?: string[] }).__csp ?? ['(not recording)']);
}

/**
 * Inject an inline script and an inline event handler into the page; resolves with what ran of
 * them (nothing, under the policy) once the browser has reported both as violations.
 */
export async function injectScript(page: Page): Promise<{ ran: string[]; reported: string[] }> {
  return page.evaluate(async () => {
    const w = window as unknown as { __csp: string[]; __ran?: string[] };
    w.__ran = [];
    const before = w.__csp.length;
    const s = document.createElement('script');
    s.textContent = 'window.__ran.push("inline script")';
    document.body.append(s);
    const box = document.createElement('div');
    box.innerHTML = '<img alt="" src="data:," onerror="window.__ran.push(\'event handler\')">';
    document.body.append(box);
    for (let i = 0; i < 100 && w.__csp.length < before + 2; i++) await new Promise((r) => setTimeout(r, 50));
    box.remove();
    s.remove();
    return { ran: w.__ran, reported: w.__csp.slice(before) };
  });
}

/** The console errors the browser logs for the injection (expected; a test removes them from its list). */
export const INJECTION_REFUSED =
  /(Refused to execute|Executing) inline (script|event handler).*Content Security Policy/;
