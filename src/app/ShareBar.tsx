/**
 * The links a scene page hands out, built in this one place: the share bar (copy link, QR code,
 * copy embed code, keep classroom mode), the values a link may carry (typed expressions only once
 * they compile), and the embedded page's link to the full app. Which shell flags a shared link
 * keeps is kit/shareLink's `sharedFlags`.
 */
import { sharedFlags, shareUrl } from '../kit/shareLink';
import { openFoldsValue } from '../kit/folds';
import { useState } from 'react';
import type { PageInfo } from '../kit/catalogue';
import type { SceneModule } from '../kit/scene';
import { serializeParams, type ParamSchema, type ParamValues } from '../kit/params';
import type { ShellFlags } from '../kit/shell';
import { useOpenFolds } from '../ui/openFolds';
import { embedSnippet } from './embedCode';
import { QrButton } from './QrButton';
import { AddToDeck } from '../deck/AddToDeck';
import './sceneHost.css';

/** The embedded page's "open the full app" link: the same scene and values, without embed=1. */
export function fullAppHref(info: PageInfo, query: string): string {
  const sp = new URLSearchParams(query);
  sp.delete('embed');
  const q = sp.toString();
  return `${window.location.pathname}#${info.path}${q ? `?${q}` : ''}`;
}

/** Last expression per parameter that compiled, so a failing one falls back to it in the link. */
const goodExpressions = new Map<string, string>();

/**
 * The values with every typed expression (string params with `expression`) replaced by its last
 * successfully compiled text (or the default) unless it compiles now. The compiler (core/expr and
 * its parser chunk) loads only when an expression differs from its default.
 */
export async function linkSafeValues(
  schema: ParamSchema,
  values: ParamValues<ParamSchema>,
): Promise<ParamValues<ParamSchema>> {
  const out = { ...values } as Record<string, unknown>;
  for (const [name, spec] of Object.entries(schema)) {
    if (spec.kind !== 'string' || spec.expression === undefined) continue;
    const v = out[name];
    if (typeof v !== 'string' || v === spec.default) continue;
    let ok = false;
    try {
      const { compileExpression } = await import('../core/expr');
      ok = (await compileExpression(v, spec.expression)).ok;
    } catch {
      ok = false;
    }
    const key = `${spec.expression.join(',')}\u0000${name}`;
    if (ok) goodExpressions.set(key, v);
    else out[name] = goodExpressions.get(key) ?? spec.default;
  }
  return out as ParamValues<ParamSchema>;
}

export function ShareBar({
  info,
  schema,
  values,
  flags,
  asking,
}: {
  info: PageInfo;
  schema: SceneModule['schema'];
  values: ParamValues<ParamSchema>;
  flags: ShellFlags;
  /** `ask=1` and not yet revealed. */
  asking: boolean;
}) {
  const [copied, setCopied] = useState<'link' | 'embed' | null>(null);
  // the folds open now (opening one rewrites the address, not these props)
  const open = useOpenFolds();
  const [shown, setShown] = useState<string | null>(null);
  // In classroom mode (present=1) the copied link and the QR code are the room as it stands:
  // classroom mode, and the held-back results (ask=1) while they are held back. Outside it, a page
  // that holds its results back hands out the students' view unless the lecturer keeps ask=1.
  const [keep, setKeep] = useState(false);
  const offerKeep = !flags.present && asking;
  const keeps = flags.present || (keep && asking);
  // (not location.origin + pathname: a copy opened from file:// has the origin "null"); the page's
  // own query string (an LMS's learner id, a cmi5 launch's credential) is not the app's to share
  const href = window.location.href;
  const qs = serializeParams(
    schema,
    values,
    sharedFlags({ present: flags.present, asking, keep, part: flags.part, theme: flags.theme, open }),
  );
  const link = shareUrl(href, info.path, qs);
  const embedQs = serializeParams(schema, values, {
    part: flags.part ?? undefined,
    open: openFoldsValue(open),
    embed: '1',
    theme: flags.theme ?? undefined,
  });
  const embedSrc = shareUrl(href, info.path, embedQs);
  // a deck slide keeps ask=1 while the results are held back, never classroom mode or the theme
  const deckFlags = sharedFlags({ present: false, asking, keep: true, part: flags.part, theme: null, open });
  const embedCode = embedSnippet(embedSrc, `${info.title} — Render Math Lab`, info.id);
  const copy = async (what: 'link' | 'embed') => {
    const text = what === 'link' ? link : embedCode;
    setShown(text);
    try {
      await navigator.clipboard.writeText(text);
      setCopied(what);
    } catch {
      setCopied(null);
    }
  };
  return (
    <div className="share-bar">
      <button type="button" data-testid="copy-link" onClick={() => copy('link')}>
        Copy link
      </button>
      <QrButton link={link} present={flags.present} classroomLink={keeps}>
        {offerKeep ? <KeepClassroom keep={keep} onKeep={setKeep} testId="qr-keep-classroom" /> : null}
      </QrButton>
      {/* embedding is preparation, not the lecture: classroom mode keeps its one header row */}
      {flags.present ? null : (
        <button type="button" data-testid="copy-embed" onClick={() => copy('embed')}>
          Copy embed code
        </button>
      )}
      {offerKeep ? <KeepClassroom keep={keep} onKeep={setKeep} testId="keep-classroom" /> : null}
      {/* a slide for the lecturer's deck: this view as the class would open it, asking while it asks */}
      {flags.present || flags.embed ? null : (
        <AddToDeck link={`${info.path}?${serializeParams(schema, values, deckFlags)}`} />
      )}
      <span role="status" className="share-status">
        {copied === 'link'
          ? 'Link copied.'
          : copied === 'embed'
            ? 'Embed code copied.'
            : shown
              ? 'Copy it from the box:'
              : ''}
      </span>
      {shown ? (
        <input
          className="share-text"
          data-testid="share-text"
          aria-label="Text to copy"
          readOnly
          value={shown}
          onFocus={(e) => e.currentTarget.select()}
        />
      ) : null}
    </div>
  );
}

/** The lecturer's choice outside classroom mode: the copied link and the QR code keep ask=1. */
function KeepClassroom({
  keep,
  onKeep,
  testId,
}: {
  keep: boolean;
  onKeep: (keep: boolean) => void;
  testId: string;
}) {
  return (
    <label className="share-keep">
      <input type="checkbox" data-testid={testId} checked={keep} onChange={(e) => onKeep(e.target.checked)} />{' '}
      Keep classroom mode
    </label>
  );
}
