import { describe, expect, it } from 'vitest';
import {
  applyMove,
  FINE_STEP,
  MOVE_BUTTONS,
  moveOfKey,
  ORBIT_STEP,
  viewportKey,
  ZOOM_STEP,
  type MoveTarget,
} from '../../src/three/viewMoves';

/** A camera reduced to what the moves change: azimuth, polar angle and distance. */
function fakeCamera() {
  const cam = { az: 0, pol: 1, dist: 4, resets: 0 };
  const engine: MoveTarget = {
    orbitBy: (a, p) => {
      cam.az += a;
      cam.pol -= p;
    },
    zoomBy: (f) => {
      cam.dist *= f;
    },
    resetView: () => {
      Object.assign(cam, { az: 0, pol: 1, dist: 4 });
      cam.resets++;
    },
  };
  return { cam, engine };
}

describe('the 3D view’s camera moves (keys and buttons share them)', () => {
  it('each button makes the move of its key', () => {
    for (const b of MOVE_BUTTONS) {
      const byButton = fakeCamera();
      const byKey = fakeCamera();
      applyMove(byButton.engine, b.move);
      const key = {
        '←': 'ArrowLeft',
        '→': 'ArrowRight',
        '↑': 'ArrowUp',
        '↓': 'ArrowDown',
        '+': '+',
        '−': '-',
      }[b.key]!;
      expect(moveOfKey(key)).toBe(b.move);
      expect(viewportKey(byKey.engine, { key, shiftKey: false })).toBe(true);
      expect(byButton.cam, b.name).toEqual(byKey.cam);
      expect(byButton.cam, `${b.name} moves the camera`).not.toEqual(fakeCamera().cam);
    }
  });

  it('steps: 10° an orbit (2° fine), ×1.15 a zoom; left undoes right, in undoes out', () => {
    const { cam, engine } = fakeCamera();
    applyMove(engine, 'left');
    expect(cam.az).toBeCloseTo(-ORBIT_STEP, 12);
    expect(ORBIT_STEP).toBeCloseTo((10 * Math.PI) / 180, 12);
    applyMove(engine, 'right', true);
    expect(cam.az).toBeCloseTo(-ORBIT_STEP + FINE_STEP, 12);
    applyMove(engine, 'up');
    applyMove(engine, 'down');
    expect(cam.pol).toBeCloseTo(1, 12);
    applyMove(engine, 'in');
    expect(cam.dist).toBeCloseTo(4 / ZOOM_STEP, 12);
    applyMove(engine, 'out');
    expect(cam.dist).toBeCloseTo(4, 12);
    applyMove(engine, 'home');
    expect(cam.resets).toBe(1);
  });

  it('the buttons have distinct names, moves and grid cells; other keys are not the view’s', () => {
    expect(new Set(MOVE_BUTTONS.map((b) => b.name)).size).toBe(MOVE_BUTTONS.length);
    expect(new Set(MOVE_BUTTONS.map((b) => b.move)).size).toBe(6);
    expect(new Set(MOVE_BUTTONS.map((b) => b.area)).size).toBe(6);
    for (const k of ['a', 'Enter', ' ', 'Escape', 'PageUp']) expect(moveOfKey(k)).toBeNull();
    const { cam, engine } = fakeCamera();
    expect(viewportKey(engine, { key: 'x', shiftKey: false })).toBe(false);
    expect(cam).toEqual(fakeCamera().cam);
  });
});
