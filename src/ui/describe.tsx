/**
 * A figure with an accessible name and a live description: what a screen reader hears of a
 * picture. The description is a plain sentence the scene builds from its model; it is the figure's
 * aria-describedby text (always current), and it is announced through the page's live region once
 * it has stayed the same for a moment, never while an animation plays (on pause it is), and on
 * request with the key `d` while focus is inside the figure.
 */
import { useEffect, useId, useRef, type KeyboardEvent, type ReactNode } from 'react';
import { announce } from './announce';
import './a11y.css';
import { isTyping, useKeyHelp, type KeyHelp } from './shortcuts';

/** How long a description must stay unchanged before it is announced, in ms. */
export const DESCRIBE_SETTLE_MS = 700;

export interface DescribedFigureProps {
  /** The figure's accessible name: what it is ("Cross-section through the ray and the sphere"). */
  label: string;
  /** What it shows now, with the numbers a sighted reader reads from it. */
  description: string;
  /** An animation is playing: changes are not announced until it pauses. */
  playing?: boolean;
  testId?: string;
  /** Do not announce changes (a secondary figure whose change the main one already says); `d` still does. */
  quiet?: boolean;
  className?: string;
  children: ReactNode;
}

/** The figure's key, for the `?` list. */
const DESCRIBE_KEY: readonly KeyHelp[] = [
  { keys: 'd', label: 'say what the figure shows now', where: 'Inside a described figure' },
];

export function DescribedFigure({
  label,
  description,
  playing = false,
  testId,
  quiet = false,
  className,
  children,
}: DescribedFigureProps) {
  useKeyHelp(DESCRIBE_KEY);
  const id = useId();
  const descId = `${id}-description`;
  // what was last said (or shown at mount): the same text is not announced again on its own
  const spoken = useRef(description);
  const wasPlaying = useRef(playing);
  const latest = useRef(description);
  latest.current = description;

  useEffect(() => {
    const paused = wasPlaying.current && !playing;
    wasPlaying.current = playing;
    if (quiet || playing) return;
    if (paused) {
      spoken.current = description;
      announce(description);
      return;
    }
    if (description === spoken.current) return;
    const timer = setTimeout(() => {
      spoken.current = latest.current;
      announce(latest.current);
    }, DESCRIBE_SETTLE_MS);
    return () => clearTimeout(timer);
  }, [description, playing, quiet]);

  const onKeyDown = (e: KeyboardEvent<HTMLElement>) => {
    if (e.key !== 'd' || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
    e.preventDefault();
    spoken.current = latest.current;
    announce(latest.current, { now: true });
  };

  return (
    <figure
      role="group"
      aria-label={label}
      aria-describedby={descId}
      className={className ? `described-figure ${className}` : 'described-figure'}
      data-testid={testId}
      data-described=""
      onKeyDown={onKeyDown}
    >
      {children}
      <p id={descId} className="sr-only" data-testid={testId ? `${testId}-description` : undefined}>
        {description}
      </p>
    </figure>
  );
}
