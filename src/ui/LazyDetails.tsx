/**
 * A disclosure whose content is a lazy chunk: nothing of it loads until the reader opens it (or a
 * link opens it with `open`); once opened it stays mounted, so closing and reopening does not
 * rebuild what it made (a WebGL context, a computed image).
 */
import { Suspense, useState, type ReactNode } from 'react';

export function LazyDetails({
  summary,
  children,
  testId,
  open: initiallyOpen = false,
}: {
  summary: ReactNode;
  /** The content, rendered only once the disclosure has been opened (wrap lazy components here). */
  children: () => ReactNode;
  testId?: string;
  open?: boolean;
}) {
  const [opened, setOpened] = useState(initiallyOpen);
  return (
    <details
      open={initiallyOpen || undefined}
      data-testid={testId}
      onToggle={(e) => {
        if ((e.currentTarget as HTMLDetailsElement).open) setOpened(true);
      }}
    >
      <summary>{summary}</summary>
      {opened ? <Suspense fallback={<p aria-busy="true">Loading…</p>}>{children()}</Suspense> : null}
    </details>
  );
}
