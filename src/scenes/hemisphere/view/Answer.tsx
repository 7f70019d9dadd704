/** An exam part's live answer that waits, under ask=1, until the class has made its prediction. */
import type { ReactNode } from 'react';
import { LiveAnswer } from '../../../ui/exam';
import { Revealed } from '../../../ui/ask';

export function Answer({
  testId,
  ask,
  what,
  title,
  children,
}: {
  testId: string;
  /** Results hidden until revealed. */
  ask: boolean;
  /** What is hidden ("Hidden until you reveal: …"). */
  what: string;
  title?: string;
  children: ReactNode;
}) {
  return (
    <LiveAnswer testId={testId} title={title}>
      <Revealed ask={ask} what={what}>
        {children}
      </Revealed>
    </LiveAnswer>
  );
}
