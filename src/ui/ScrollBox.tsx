import type { ReactNode } from 'react';
import './layout.css';

/**
 * A box that scrolls sideways when its content (a wide table, a long formula) is wider than a
 * phone. Keyboard users can reach and scroll it: it is focusable and named, so a screen reader
 * says what scrolls (WCAG 2.1.1 and axe's scrollable-region-focusable).
 */
export function ScrollBox({
  label,
  children,
  className,
  testId,
}: {
  /** what the box holds, e.g. "All three strategies"; read when it takes focus */
  label: string;
  children: ReactNode;
  className?: string;
  testId?: string;
}) {
  return (
    <div
      className={className ? `scroll-box ${className}` : 'scroll-box'}
      tabIndex={0}
      role="region"
      aria-label={label}
      data-testid={testId}
    >
      {children}
    </div>
  );
}
