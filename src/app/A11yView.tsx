/**
 * The A11y view (`a11y=1`), for teachers: beside the scene, the text a screen reader receives of it,
 * live: every described figure's accessible name and description (read from the page itself, as
 * the browser exposes them: aria-label / aria-labelledby and aria-describedby), and what the live
 * region has announced, newest first. Loaded only when the flag is set.
 */
import { useEffect, useState } from 'react';
import { onAnnounce, recentAnnouncements, type Announcement } from '../ui/announce';
import './a11y-view.css';

interface FigureText {
  key: string;
  kind: string;
  name: string;
  description: string;
}

/** What counts as a figure: anything named with a role a screen reader announces as a picture or group. */
const FIGURE_SELECTOR =
  'figure[aria-label], figure[aria-labelledby], [role="img"][aria-label], [role="img"][aria-labelledby], [role="group"][data-described], canvas[aria-label]';

function idsText(ids: string | null): string {
  if (!ids) return '';
  return ids
    .split(/\s+/)
    .map((id) => document.getElementById(id)?.textContent?.replace(/\s+/g, ' ').trim() ?? '')
    .filter(Boolean)
    .join(' ');
}

/** The figures' texts under `root`, in document order (the A11y view's own panel left out). */
export function readFigures(root: ParentNode): FigureText[] {
  const out: FigureText[] = [];
  const els = root.querySelectorAll<HTMLElement | SVGElement>(FIGURE_SELECTOR);
  els.forEach((el, i) => {
    if (el.closest('.a11y-view') || el.closest('[aria-hidden="true"]')) return;
    const name = el.getAttribute('aria-label') ?? idsText(el.getAttribute('aria-labelledby'));
    let description = idsText(el.getAttribute('aria-describedby'));
    if (!description && el instanceof SVGElement) {
      description = el.querySelector(':scope > desc')?.textContent?.trim() ?? '';
    }
    const role = el.getAttribute('role') ?? (el.tagName.toLowerCase() === 'figure' ? 'figure' : 'image');
    out.push({ key: `${i}`, kind: role === 'img' ? 'image' : role, name, description });
  });
  return out;
}

function sameFigures(a: FigureText[], b: FigureText[]): boolean {
  return (
    a.length === b.length && a.every((f, i) => f.name === b[i]!.name && f.description === b[i]!.description)
  );
}

export default function A11yView({ rootId = 'main' }: { rootId?: string }) {
  const [figures, setFigures] = useState<FigureText[]>([]);
  const [said, setSaid] = useState<readonly Announcement[]>(() => [...recentAnnouncements()]);

  useEffect(() => {
    const root = document.getElementById(rootId) ?? document.body;
    let timer: ReturnType<typeof setTimeout> | null = null;
    const read = () => {
      timer = null;
      const next = readFigures(root);
      setFigures((prev) => (sameFigures(prev, next) ? prev : next));
    };
    read();
    // at most a few reads a second, however fast the scene changes
    const mo = new MutationObserver(() => {
      timer ??= setTimeout(read, 250);
    });
    mo.observe(root, {
      subtree: true,
      childList: true,
      characterData: true,
      attributes: true,
      attributeFilter: ['aria-label', 'aria-describedby', 'aria-labelledby', 'aria-hidden'],
    });
    return () => {
      mo.disconnect();
      if (timer !== null) clearTimeout(timer);
    };
  }, [rootId]);

  useEffect(() => onAnnounce(() => setSaid([...recentAnnouncements()])), []);

  useEffect(() => {
    const cl = document.documentElement.classList;
    cl.add('with-a11y-view');
    return () => cl.remove('with-a11y-view');
  }, []);

  return (
    <section className="a11y-view" aria-label="A11y view" data-testid="a11y-view">
      <h2>A11y view</h2>
      <p className="small">What a screen reader receives of this scene, live.</p>
      <h3>Figures</h3>
      {figures.length === 0 ? (
        <p className="small">No described figure on the page yet.</p>
      ) : (
        <ol className="a11y-figures" data-testid="a11y-figures">
          {figures.map((f) => (
            <li key={f.key}>
              <strong>{f.name || '(no name)'}</strong> <span className="a11y-kind">{f.kind}</span>
              <div className={f.description ? 'a11y-desc' : 'a11y-desc a11y-missing'}>
                {f.description || 'No description.'}
              </div>
            </li>
          ))}
        </ol>
      )}
      <h3>Announced</h3>
      {said.length === 0 ? (
        <p className="small">Nothing announced yet: change a parameter, or press d on a figure.</p>
      ) : (
        <ol className="a11y-said" reversed data-testid="a11y-announcements">
          {[...said].reverse().map((a) => (
            <li key={a.seq}>{a.text}</li>
          ))}
        </ol>
      )}
    </section>
  );
}
