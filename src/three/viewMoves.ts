/**
 * The camera moves of a 3D view, one table for its keys and its buttons: orbit left, right, up and
 * down about the target, zoom in and out, back to the home view. Pure (no DOM, no three.js): the
 * moves act on the engine's orbitBy / zoomBy / resetView.
 */
import type { Engine } from './engine';

/** Orbit step per press: 10° (2° with Shift). */
export const ORBIT_STEP = (10 * Math.PI) / 180;
export const FINE_STEP = (2 * Math.PI) / 180;
/** Zoom factor per press: the camera comes 1/1.15 of its distance closer (or goes 1.15× away). */
export const ZOOM_STEP = 1.15;

export type ViewMove = 'left' | 'right' | 'up' | 'down' | 'in' | 'out' | 'home';

export type MoveTarget = Pick<Engine, 'orbitBy' | 'zoomBy' | 'resetView'>;

/** Apply one move; `fine` takes the small orbit step. */
export function applyMove(engine: MoveTarget, move: ViewMove, fine = false): void {
  const step = fine ? FINE_STEP : ORBIT_STEP;
  switch (move) {
    case 'left':
      return engine.orbitBy(-step, 0);
    case 'right':
      return engine.orbitBy(step, 0);
    case 'up':
      return engine.orbitBy(0, step);
    case 'down':
      return engine.orbitBy(0, -step);
    case 'in':
      return engine.zoomBy(1 / ZOOM_STEP);
    case 'out':
      return engine.zoomBy(ZOOM_STEP);
    case 'home':
      return engine.resetView();
  }
}

/** The move of a key pressed on a focused 3D view, or null. */
export function moveOfKey(key: string): ViewMove | null {
  switch (key) {
    case 'ArrowLeft':
      return 'left';
    case 'ArrowRight':
      return 'right';
    case 'ArrowUp':
      return 'up';
    case 'ArrowDown':
      return 'down';
    case '+':
    case '=':
      return 'in';
    case '-':
    case '_':
      return 'out';
    case 'Home':
      return 'home';
    default:
      return null;
  }
}

/**
 * Keyboard orbit and zoom for a focused viewport: arrows orbit about the target (Shift: finer),
 * + / − zoom, Home resets the view. Returns true when the key was handled.
 */
export function viewportKey(engine: MoveTarget, e: Pick<KeyboardEvent, 'key' | 'shiftKey'>): boolean {
  const move = moveOfKey(e.key);
  if (!move) return false;
  applyMove(engine, move, e.shiftKey);
  return true;
}

/**
 * The buttons of the view's control cluster (the pointer's alternative to dragging): their move,
 * accessible name, visible glyph, the key that does the same, and their cell in the cluster's grid
 * (a cross of orbit arrows, the zoom pair beside it).
 */
export const MOVE_BUTTONS: readonly {
  move: Exclude<ViewMove, 'home'>;
  name: string;
  glyph: string;
  key: string;
  area: string;
}[] = [
  { move: 'up', name: 'Orbit up', glyph: '▲', key: '↑', area: 'up' },
  { move: 'left', name: 'Orbit left', glyph: '◀', key: '←', area: 'left' },
  { move: 'right', name: 'Orbit right', glyph: '▶', key: '→', area: 'right' },
  { move: 'down', name: 'Orbit down', glyph: '▼', key: '↓', area: 'down' },
  { move: 'in', name: 'Zoom in', glyph: '+', key: '+', area: 'in' },
  { move: 'out', name: 'Zoom out', glyph: '−', key: '−', area: 'out' },
];
