/**
 * A folded part of the page: a disclosure whose content is not mounted, and whose lazy chunks are
 * not loaded, until the reader opens it. Its `name` is its entry in the link's `open=` list
 * (./openFolds): a link can open it, and opening or closing it rewrites the link. Once opened it
 * stays mounted, so closing and reopening does not rebuild what it made (a WebGL context, a
 * computed image); a closed fold's content is not rendered by the browser (animation loops that
 * watch their visibility stop).
 *
 * Heavy work belongs inside the content's own components, not in the props the page computes for
 * it: only then does a closed fold cost nothing.
 */
import { Suspense, useState, type ReactNode } from 'react';
import { useFoldOpen } from './openFolds';
import './fold.css';

export function Fold({
  name,
  summary,
  children,
  testId,
  className,
}: {
  /** Unique on the page; lower-case letters, digits and dashes (../kit/folds FOLD_NAME). */
  name: string;
  summary: ReactNode;
  children: ReactNode;
  testId?: string;
  className?: string;
}) {
  const [open, setOpen] = useFoldOpen(name);
  const [opened, setOpened] = useState(open);
  if (open && !opened) setOpened(true);
  return (
    <details
      className={`fold${className ? ` ${className}` : ''}`}
      open={open}
      data-fold={name}
      data-testid={testId ?? `fold-${name}`}
      onToggle={(e) => {
        const now = (e.currentTarget as HTMLDetailsElement).open;
        if (now !== open) setOpen(now);
      }}
    >
      <summary className="fold-summary">{summary}</summary>
      {opened ? (
        <div className="fold-body">
          <Suspense
            fallback={
              <p className="fold-loading" aria-busy="true">
                Loading…
              </p>
            }
          >
            {children}
          </Suspense>
        </div>
      ) : null}
    </details>
  );
}
