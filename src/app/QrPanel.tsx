import { useEffect, useRef, useState, type ReactNode } from 'react';
import { qrPath } from '../ui/qr';

/**
 * The QR code panel of ./QrButton: the link drawn as a QR code (large in classroom mode), with its
 * caption, the share bar's extra controls and Close. Its own chunk, loaded on the first press.
 */
export default function QrPanel({
  link,
  present,
  classroomLink,
  children,
  onClose,
}: {
  link: string;
  present: boolean;
  classroomLink: boolean;
  children?: ReactNode;
  onClose: () => void;
}) {
  const [state, setState] = useState<{ text: string; path: string; size: number } | { error: string } | null>(
    null,
  );
  const close = useRef<HTMLButtonElement>(null);
  useEffect(() => {
    let alive = true;
    qrPath(link).then(
      (q) => alive && setState({ text: link, path: q.d, size: q.size }),
      (e: unknown) => alive && setState({ error: e instanceof Error ? e.message : String(e) }),
    );
    return () => {
      alive = false;
    };
  }, [link]);
  useEffect(() => close.current?.focus(), []);
  return (
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
      <button type="button" ref={close} onClick={onClose}>
        Close
      </button>
    </div>
  );
}
