import { useEffect, useRef, useState, type RefObject } from 'react';

interface PromptProps {
  partId: string;
  /** The confirmation is open. */
  asking: boolean;
  onAsk: () => void;
  onCancel: () => void;
  onConfirm: () => void;
  openRef?: RefObject<HTMLButtonElement | null>;
  confirmRef?: RefObject<HTMLButtonElement | null>;
}

/** The button, or the confirmation it opens (pure: what is shown for `asking`). */
export function RevealPrompt({
  partId,
  asking,
  onAsk,
  onCancel,
  onConfirm,
  openRef,
  confirmRef,
}: PromptProps) {
  if (!asking)
    return (
      <button type="button" ref={openRef} onClick={onAsk} data-testid={`show-answer-${partId}`}>
        Show answer
      </button>
    );
  const textId = `confirm-text-${partId}`;
  return (
    <span
      className="confirm-reveal"
      role="group"
      aria-labelledby={textId}
      data-testid={`confirm-reveal-${partId}`}
      onKeyDown={(e) => {
        if (e.key === 'Escape') onCancel();
      }}
    >
      <span id={textId}>Show the answer to ({partId})? This part then earns no more marks.</span>{' '}
      <button
        type="button"
        ref={confirmRef}
        onClick={onConfirm}
        data-testid={`confirm-show-answer-${partId}`}
      >
        Show answer
      </button>{' '}
      <button type="button" onClick={onCancel} data-testid={`cancel-show-answer-${partId}`}>
        Keep trying
      </button>
    </span>
  );
}

/**
 * "Show answer" for one part, asking first: showing the answer ends the part's marks, so the
 * button opens a confirmation in the page (focus moves to it; "Keep trying" or Escape closes it
 * and gives focus back) and only its own "Show answer" reveals.
 */
export function ShowAnswer({ partId, onReveal }: { partId: string; onReveal: () => void }) {
  const [asking, setAsking] = useState(false);
  const confirmRef = useRef<HTMLButtonElement>(null);
  const openRef = useRef<HTMLButtonElement>(null);
  const wasAsking = useRef(false);
  useEffect(() => {
    if (asking) confirmRef.current?.focus();
    else if (wasAsking.current) openRef.current?.focus();
    wasAsking.current = asking;
  }, [asking]);
  return (
    <RevealPrompt
      partId={partId}
      asking={asking}
      onAsk={() => setAsking(true)}
      onCancel={() => setAsking(false)}
      onConfirm={() => {
        setAsking(false);
        onReveal();
      }}
      openRef={openRef}
      confirmRef={confirmRef}
    />
  );
}
