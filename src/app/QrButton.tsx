import { useEffect, useRef, useState, type ReactNode } from 'react';
import { qrPath } from '../ui/qr';

/**
 * "QR code" beside Copy link: shows the current link as a QR code (large in classroom mode), so
 * students in the room open the lecturer's exact configuration on their phones.
 */
export function QrButton({
  link,
  present,
  classroomLink = false,
  children,
}: {
  link: string;
  /** Classroom mode is on here: the code is drawn large. */
  present: boolean;
  /** The link keeps classroom mode (present=1, or ask=1 kept by the lecturer); else the students' view. */
  classroomLink?: boolean;
  /** Shown in the panel under the caption (the share bar's choice of link, usable while it is open). */
  children?: ReactNode;
}) {
  const [open, setOpen] = useState(false);
  const [state, setState] = useState<{ text: string; path: string; size: number } | { error: string } | null>(
    null,
  );
  const btn = useRef<HTMLButtonElement>(null);
  const close = useRef<HTMLButtonElement>(null);

  useEffect(() => {
    if (!open) return;
    let alive = true;
    qrPath(link).then(
      (q) => alive && setState({ text: link, path: q.d, size: q.size }),
      (e: unknown) => alive && setState({ error: e instanceof Error ? e.message : String(e) }),
    );
    return () => {
      alive = false;
    };
  }, [open, link]);

  useEffect(() => {
    if (!open) return;
    close.current?.focus();
    const onKey = (e: KeyboardEvent) => {
      if (e.key === 'Escape') {
        e.stopPropagation();
        setOpen(false);
        btn.current?.focus();
      }
    };
    window.addEventListener('keydown', onKey, true);
    return () => window.removeEventListener('keydown', onKey, true);
  }, [open]);

  return (
    <>
      <button
        type="button"
        ref={btn}
        data-testid="show-qr"
        aria-expanded={open}
        onClick={() => setOpen((o) => !o)}
      >
        QR code
      </button>
      {open ? (
        <div
          className={present ? 'qr-panel qr-large' : 'qr-panel'}
          role="dialog"
          aria-modal="false"
          aria-label="QR code of this link"
          data-testid="qr-panel"
        >
          {state && 'path' in state ? (
            <svg
              className="qr-code"
              data-testid="qr-code"
              data-text={state.text}
              viewBox={`0 0 ${state.size} ${state.size}`}
              role="img"
              aria-label="QR code of the link to this scene in its current configuration"
              shapeRendering="crispEdges"
            >
              <rect width={state.size} height={state.size} fill="#fff" />
              <path d={state.path} fill="#000" />
            </svg>
          ) : state && 'error' in state ? (
            <p role="alert" className="notice notice-error">
              The QR code could not be made ({state.error}).
            </p>
          ) : (
            <p role="status">Making the QR code…</p>
          )}
          <p className="qr-caption">
            Scan to open this scene as configured here
            {classroomLink ? ', in classroom mode' : ' (larger in classroom mode, present=1)'}.
          </p>
          {children}
          <button
            type="button"
            ref={close}
            onClick={() => {
              setOpen(false);
              btn.current?.focus();
            }}
          >
            Close
          </button>
        </div>
      ) : null}
    </>
  );
}
