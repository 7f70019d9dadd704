import { lazy, Suspense, useEffect, useRef, useState, type ReactNode } from 'react';

// the panel and the QR encoder load on the first press, not with every scene page
const QrPanel = lazy(() => import('./QrPanel'));

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
  const btn = useRef<HTMLButtonElement>(null);

  useEffect(() => {
    if (!open) return;
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
        <Suspense fallback={<p role="status">Making the QR code…</p>}>
          <QrPanel
            link={link}
            present={present}
            classroomLink={classroomLink}
            onClose={() => {
              setOpen(false);
              btn.current?.focus();
            }}
          >
            {children}
          </QrPanel>
        </Suspense>
      ) : null}
    </>
  );
}
