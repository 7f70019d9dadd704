/**
 * Picking the stratum the figure follows: the 64 cells of the unit square as a radio group laid
 * over the square (click or tap a cell; arrow keys move the choice, Home/End go to the row's ends,
 * Escape stops following), and beside it two number fields and a button for the same choice, with
 * the sentence of what the cell becomes on the hemisphere.
 */
import { useEffect, useRef, useState, type KeyboardEvent } from 'react';
import { NumberField } from '../../../ui';
import { nextTask } from '../../../ui/chunked';
import type { SequenceKind } from '../../../core/random';
import { CELLS, cellBounds, countInCell, stepCell, type Cell } from '../stratum';

/** Called with the new cell, or null to stop following. */
export type PickCell = (c: Cell | null) => void;

const ROWS_TOP_DOWN = Array.from({ length: CELLS }, (_, r) => CELLS - 1 - r); // ξ₂ grows upwards
const COLS = Array.from({ length: CELLS }, (_, i) => i);

function cellName(c: Cell): string {
  const { xi1, xi2 } = cellBounds(c);
  return `cell (${c.i}, ${c.j}): ξ₁ from ${xi1[0]} to ${xi1[1]}, ξ₂ from ${xi2[0]} to ${xi2[1]}`;
}

/**
 * The cells as radio buttons over the square's plot area (`inset`: the plot's margin as a fraction
 * of the figure's side). Arrow keys move the choice and the focus with it.
 */
export function StratumCells({
  cell,
  onPick,
  inset,
}: {
  cell: Cell | null;
  onPick: PickCell;
  inset: number;
}) {
  const box = useRef<HTMLDivElement>(null);
  const focusWanted = useRef(false);
  const tabStop = cell ?? { i: 0, j: 0 };
  useEffect(() => {
    if (!focusWanted.current || !cell) return;
    focusWanted.current = false;
    box.current?.querySelector<HTMLElement>(`[data-cell="${cell.i},${cell.j}"]`)?.focus();
  }, [cell]);
  const onKey = (e: KeyboardEvent<HTMLDivElement>) => {
    const from = cell ?? tabStop;
    const moves: Record<string, [number, number]> = {
      ArrowRight: [1, 0],
      ArrowLeft: [-1, 0],
      ArrowUp: [0, 1],
      ArrowDown: [0, -1],
      Home: [-CELLS, 0],
      End: [CELLS, 0],
    };
    const m = Object.hasOwn(moves, e.key) ? moves[e.key] : null;
    if (m) {
      focusWanted.current = true;
      onPick(stepCell(from, m[0], m[1]));
    } else if (e.key === 'Escape' && cell) onPick(null);
    else return;
    e.preventDefault(); // no page scroll, and the classroom shortcuts skip the key
    e.stopPropagation();
  };
  const pct = `${inset * 100}%`;
  return (
    <div
      ref={box}
      className="hemi-cells"
      role="radiogroup"
      aria-label="Stratum to follow: a cell of the (ξ₁, ξ₂) square (arrow keys move, Escape stops following)"
      style={{ left: pct, top: pct, right: pct, bottom: pct }}
      onKeyDown={onKey}
      data-testid="stratum-cells"
    >
      {ROWS_TOP_DOWN.map((j) => (
        <div key={j} className="hemi-cells-row">
          {COLS.map((i) => {
            const checked = !!cell && cell.i === i && cell.j === j;
            const stop = tabStop.i === i && tabStop.j === j;
            return (
              <button
                key={i}
                type="button"
                role="radio"
                aria-checked={checked}
                aria-label={cellName({ i, j })}
                tabIndex={stop ? 0 : -1}
                data-cell={`${i},${j}`}
                className={checked ? 'on' : undefined}
                onClick={() => onPick(checked ? null : { i, j })}
              />
            );
          })}
        </div>
      ))}
    </div>
  );
}

/**
 * How many of the n points lie in the cell: counted in slices of 2¹⁵ points, one task each, so a
 * million points never make one long task; null while counting.
 */
export function useCellCount(kind: SequenceKind, seed: number, n: number, cell: Cell | null): number | null {
  const [state, setState] = useState<{ key: string; count: number } | null>(null);
  // the cell by its indices (a new object for the same cell must not restart the count)
  const ci = cell ? cell.i : -1;
  const cj = cell ? cell.j : -1;
  const key = `${kind}|${seed}|${n}|${ci},${cj}`;
  useEffect(() => {
    if (ci < 0) return;
    const c = { i: ci, j: cj };
    let alive = true;
    const slice = 1 << 15;
    const scratch = new Float64Array(2 * 4096);
    let done = 0;
    let count = 0;
    const step = () => {
      if (!alive) return;
      const to = Math.min(n, done + slice);
      count += countInCell(kind, seed, n, c, done, to, scratch);
      done = to;
      if (done < n) nextTask(step);
      else setState({ key: `${kind}|${seed}|${n}|${ci},${cj}`, count });
    };
    nextTask(step);
    return () => {
      alive = false;
    };
  }, [kind, seed, n, ci, cj]);
  return ci >= 0 && state && state.key === key ? state.count : null;
}

/** The two number fields: the cell's column (along ξ₁) and row (along ξ₂). */
const AXES = [
  { key: 'i', name: 'column i', xi: 'ξ₁' },
  { key: 'j', name: 'row j', xi: 'ξ₂' },
] as const;

/** The same choice by number fields and buttons, and what the cell becomes (`text`). */
export function StratumControls({
  cell,
  onPick,
  text,
  firstCell,
}: {
  cell: Cell | null;
  onPick: PickCell;
  text: string;
  /** The cell to start from (the first sample's). */
  firstCell: Cell;
}) {
  return (
    <fieldset className="hemi-stratum" data-testid="stratum">
      <legend>Follow a stratum: cell (i, j)</legend>
      {cell ? (
        <div className="hemi-stratum-fields">
          {AXES.map(({ key, name, xi }) => (
            <NumberField
              key={key}
              label={
                <>
                  {name} <span className="sr-only">of {xi}</span>
                </>
              }
              value={cell[key]}
              min={0}
              max={CELLS - 1}
              step={1}
              onChange={(v) => onPick({ ...cell, [key]: Math.round(v) })}
              testId={`stratum-${key}`}
            />
          ))}
          <button type="button" onClick={() => onPick(null)} data-testid="stratum-clear">
            Stop following
          </button>
        </div>
      ) : (
        <p className="small">
          Click or tap a cell of the square, or{' '}
          <button type="button" onClick={() => onPick(firstCell)} data-testid="stratum-start">
            follow the first sample&apos;s cell
          </button>
          .
        </p>
      )}
      {cell && text ? (
        <p className="small" data-testid="stratum-text">
          {text}
        </p>
      ) : null}
    </fieldset>
  );
}
