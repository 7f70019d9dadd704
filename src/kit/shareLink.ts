import { openFoldsValue } from './folds';
/**
 * The document part of a link the app hands out (Copy link, the QR code, the embed code, the
 * worksheet's links): the page's address without its query string and fragment. The page may have
 * been opened with parameters that are not the app's: an LMS or a course page adds the learner's
 * id, name and e-mail, a cmi5 launch adds its one-time credential (`fetch`), the learner (`actor`),
 * `registration` and `endpoint`; a server may put a session in the path (`;jsessionid=…`) or a
 * login in the address (`user:password@`). A shared link carries the app's own route and
 * parameters only, which live after the `#`, so nothing before it but the document's path is kept.
 */
export function shareBase(href: string): string {
  const doc = href.split('#')[0];
  const q = doc.indexOf('?');
  const bare = q < 0 ? doc : doc.slice(0, q);
  let u: URL;
  try {
    u = new URL(bare);
  } catch {
    return bare;
  }
  if (!/^(https?|file):$/.test(u.protocol)) return bare;
  // path parameters (`;name=value` in a segment) are a server's, never the app's
  return `${u.protocol}//${u.host}${u.pathname.replace(/;[^/]*/g, '')}`;
}

/** The link to the app's `route` with its own `query` (no `?` when empty), on `href`'s document. */
export function shareUrl(href: string, route: string, query: string): string {
  return `${shareBase(href)}#${route}${query ? `?${query}` : ''}`;
}

/** What decides the shell flags of the link Copy link and the QR code hand out. */
export interface ShareMode {
  /** The page is in classroom mode (`present=1`). */
  present: boolean;
  /** The page holds its results back (`ask=1`, not yet revealed). */
  asking: boolean;
  /** Outside classroom mode: the lecturer ticked "Keep classroom mode" (keep `ask=1`). */
  keep: boolean;
  /** The exam part the page landed on (`part=`), kept. */
  part: string | null;
  /** A theme chosen by the link (`theme=`), kept. */
  theme: string | null;
  /** The page's open folds (`open=`, ./folds), kept. */
  open?: readonly string[];
}

/**
 * The shell flags the shared link carries (entries for serializeParams; undefined: left out). In
 * classroom mode the link is the lecturer's room as it stands: `present=1`, and `ask=1` while the
 * results are still held back, so students who scan the QR code predict before they see them.
 * Outside classroom mode the link is the students' view: `present` never, `ask=1` only when the
 * lecturer asks to keep it. The part, the open folds and the theme always travel; nothing else of
 * the page does.
 */
export function sharedFlags(m: ShareMode): Record<string, string | undefined> {
  return {
    part: m.part ?? undefined,
    open: openFoldsValue(m.open ?? []),
    present: m.present ? '1' : undefined,
    ask: m.asking && (m.present || m.keep) ? '1' : undefined,
    theme: m.theme ?? undefined,
  };
}
