/**
 * The animated figures beside and under the grid: each renders at the paused position (useStillT)
 * and writes its moving nodes per frame without React (useAnimFrame); see ./anim.
 */
import { startTransition, useEffect, useMemo, useRef, useState, type ComponentProps } from 'react';
import { Notice, nextTask, useAnimFrame, usePlaying, useStillT } from '../../../ui';
import { addressingNotes, pathProfile, type Lookup } from '../model';
import type { AnimContext } from './anim';
import { GridView, StencilDetail, fmtShort } from './GridView';
import { PathPlot } from './PathPlot';

/** The grid figure with the query at position t (the grid's layers are memoized inside). */
export function AnimGrid({
  ctx,
  ...rest
}: { ctx: AnimContext } & Omit<ComponentProps<typeof GridView>, 'q' | 'path' | 'drawRef'>) {
  const t = useStillT(ctx.store);
  const draw = useRef<((q: Lookup) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => draw.current?.(ctx.frame(x).dq));
  return <GridView {...rest} q={ctx.frame(t).dq} path={ctx.path} drawRef={draw} />;
}

/**
 * True from one task after the component mounted: work that can wait for it (a figure below the
 * first screen of a phone) stays out of the page's first render, so loading has no long task.
 */
function useAfterMount(): boolean {
  const [on, setOn] = useState(false);
  useEffect(() => {
    let live = true;
    nextTask(() => {
      if (live) startTransition(() => setOn(true));
    });
    return () => {
      live = false;
    };
  }, []);
  return on;
}

/** The value along the path with the marker at t (its curves are memoized inside). */
export function AnimPathPlot({ ctx, present }: { ctx: AnimContext; present: boolean }) {
  const ready = useAfterMount();
  const profile = useMemo(
    () => (ready ? pathProfile(ctx.grid, ctx.opts, ctx.path) : null),
    [ready, ctx.grid, ctx.opts, ctx.path],
  );
  const t = useStillT(ctx.store);
  const q = ctx.frame(t).frame.lookup;
  const draw = useRef<((t: number, near: number, bil: number) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => {
    const l = ctx.frame(x).frame.lookup;
    draw.current?.(x, l.near.value, l.bil.value);
  });
  return (
    <PathPlot
      profile={profile}
      t={t}
      near={q.near.value}
      bil={q.bil.value}
      present={present}
      drawRef={draw}
    />
  );
}

/**
 * The query now, its stencil and the addressing notes, beside the grid. The numbers are written per
 * frame without React (text at most TEXT_HZ times a second while playing); the addressing notes
 * render while paused only (exact at the paused position).
 */
export function AnimSide({ ctx }: { ctx: AnimContext }) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame, dq } = ctx.frame(t);
  const q = frame.lookup;
  const notes = useMemo(
    () => (playing ? [] : addressingNotes(frame.u, frame.v, ctx.opts, q)),
    [playing, frame, ctx.opts, q],
  );
  const nowRef = useRef<HTMLParagraphElement>(null);
  const stencil = useRef<((q: Lookup, text: boolean) => void) | null>(null);
  useAnimFrame(ctx.store, (x, text) => {
    const f = ctx.frame(x);
    stencil.current?.(f.dq, text);
    const p = nowRef.current;
    if (!p || !text) return;
    const l = f.frame.lookup;
    const parts = [
      x === 0 ? '' : ` at t = ${fmtShort(x)} on its path`,
      fmtShort(f.frame.u),
      fmtShort(f.frame.v),
      fmtShort(l.near.value),
      fmtShort(l.bil.value),
    ];
    for (let k = 0; k < parts.length; k++) {
      const el = p.children[k];
      if (el && el.textContent !== parts[k]) el.textContent = parts[k];
    }
  });
  return (
    <>
      <p className="tx-now" data-testid="query-now" ref={nowRef}>
        Query
        <span />: (u, v) = (<span />, <span />) → nearest <strong />, bilinear <strong />
      </p>
      <StencilDetail q={dq} drawRef={stencil} />
      <p className="tx-small">
        <span className="tx-key nearest" /> nearest node · <span className="tx-key cell" /> the bilinear cell:
        each of its four nodes is weighted by the area of the sub-rectangle opposite to it (same colour).
      </p>
      {notes.length ? (
        <Notice kind="info" testId="addressing-note">
          {notes.map((n) => (
            <span key={n} className="tx-note-line">
              {n}
            </span>
          ))}
        </Notice>
      ) : null}
    </>
  );
}
