import { applyMove, MOVE_BUTTONS, type MoveTarget } from './viewMoves';

/**
 * The 3D view's orbit and zoom buttons: a small cross of arrows and a zoom pair in a corner of the
 * view, for whoever cannot or would rather not drag (a mouse click, a tap, Enter or
 * Space each make one step, Shift+click a finer orbit step; the arrow keys keep working while a
 * button has focus, since the keys belong to the whole view).
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
  return (
    <div
      className={`viewport-tools vt-at-${at}`}
      role="group"
      aria-label="Orbit and zoom"
      data-testid={testId && `${testId}-tools`}
    >
      {MOVE_BUTTONS.map((b) => (
        <button
          key={b.move}
          type="button"
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
