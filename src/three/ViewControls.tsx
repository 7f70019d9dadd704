import { useRef, useState, type KeyboardEvent } from 'react';
import { applyMove, MOVE_BUTTONS, type MoveTarget } from './viewMoves';

/**
 * The 3D view's orbit and zoom buttons: a small cross of arrows and a zoom pair in a corner of the
 * view, for whoever cannot or would rather not drag (a mouse click, a tap, Enter or
 * Space each make one step, Shift+click a finer orbit step). They are one toolbar and one tab
 * stop: the arrow keys, Home and End move between its buttons (the view itself, focused, takes the
 * arrow keys to orbit).
 */
export function ViewControls({
  engine,
  testId,
  at = 'bottom',
}: {
  engine: MoveTarget;
  testId?: string;
  /** The bottom-right corner, or the top-right under "Reset view". */
  at?: 'bottom' | 'top';
}) {
  // one tab stop for the whole toolbar (roving tabindex, WAI-ARIA's toolbar pattern): Tab enters
  // it on the button used last, the arrow keys, Home and End move between its buttons
  const [current, setCurrent] = useState(0);
  const bar = useRef<HTMLDivElement>(null);
  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    const n = MOVE_BUTTONS.length;
    const step: Record<string, number> = { ArrowRight: 1, ArrowDown: 1, ArrowLeft: -1, ArrowUp: -1 };
    let next: number | null = null;
    if (e.key in step) next = (current + step[e.key] + n) % n;
    else if (e.key === 'Home') next = 0;
    else if (e.key === 'End') next = n - 1;
    if (next === null) return;
    e.preventDefault();
    e.stopPropagation();
    setCurrent(next);
    bar.current?.querySelectorAll('button')[next]?.focus();
  };
  return (
    <div
      ref={bar}
      className={`viewport-tools vt-at-${at}`}
      role="toolbar"
      aria-label="Orbit and zoom"
      data-testid={testId && `${testId}-tools`}
      onKeyDown={onKeyDown}
    >
      {MOVE_BUTTONS.map((b, k) => (
        <button
          key={b.move}
          type="button"
          tabIndex={k === current ? 0 : -1}
          onFocus={() => setCurrent(k)}
          className={`viewport-tool vt-${b.area}`}
          aria-label={b.name}
          title={`${b.name} (${b.key})`}
          data-testid={testId && `${testId}-${b.move}`}
          onClick={(e) => applyMove(engine, b.move, e.shiftKey)}
        >
          <span aria-hidden="true">{b.glyph}</span>
        </button>
      ))}
    </div>
  );
}
