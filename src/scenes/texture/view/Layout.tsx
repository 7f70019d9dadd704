/**
 * Where the pieces of the scene's figure go: on the page (the exam's data, the grid with its
 * transport and the folded path, the stencil and the folded cell editor beside it), or in
 * classroom mode on the stage (the grid beside its key readouts and the transport, filling the
 * first screen) with the rest in the panel below it.
 */
import type { ReactNode, RefObject } from 'react';
import './Layout.css';

export interface FigurePieces {
  /** The exam's data (its text and its grid). */
  gives: ReactNode;
  /** The grid figure with its colour scale. */
  grid: ReactNode;
  /** The timeline's transport. */
  transport: ReactNode;
  /** The path's shape and end and the value along it (folded). */
  path: ReactNode;
  /** The query now and its stencil (the key readouts). */
  side: ReactNode;
  /** The cell editor (folded) and the texture's values as a table. */
  editor: ReactNode;
}

/** The figure on the page; `figRef` is what the timeline watches to pause off screen. */
export function PageFigure({ p, figRef }: { p: FigurePieces; figRef: RefObject<HTMLDivElement | null> }) {
  return (
    <div className="tx-figure-cols" ref={figRef}>
      {p.gives}
      <div className="tx-figure-main">
        {p.grid}
        {p.transport}
        {p.path}
      </div>
      <div className="tx-figure-side">
        {p.side}
        {p.editor}
      </div>
    </div>
  );
}

/** The stage's figure: the grid sized to the first screen, beside the key readouts and the transport. */
export function StageFigure({ p, figRef }: { p: FigurePieces; figRef: RefObject<HTMLDivElement | null> }) {
  return (
    <div className="tx-stage" ref={figRef}>
      <div className="tx-stage-grid">{p.grid}</div>
      <div className="tx-stage-side">
        {p.transport}
        {p.side}
      </div>
    </div>
  );
}

/** What the stage leaves for the page below it in classroom mode. */
export function StageRest({ p }: { p: FigurePieces }) {
  return (
    <div className="tx-figure-cols">
      {p.gives}
      <div className="tx-figure-main">{p.path}</div>
      <div className="tx-figure-side">{p.editor}</div>
    </div>
  );
}
