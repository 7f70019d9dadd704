/**
 * The animated figures beside and under the grid: each renders at the paused position (useStillT)
 * and writes its moving nodes per frame without React (useAnimFrame); see ./anim.
 */
import { useMemo, useRef, type ComponentProps, type ReactNode } from 'react';
import { texel } from '../../../core/texture';
import { DescribedFigure, Notice, useAnimFrame, usePlaying, useStillT } from '../../../ui';
import { addressingNotes, type Lookup } from '../model';
import type { SphereModel } from '../sphere';
import type { Preset } from '../params';
import type { AnimContext } from './anim';
import { GridView } from './GridView';
import { StencilDetail } from './StencilDetail';
import { formatRounded } from '../../../core/format';
import { describeSphere, describeTexture, textureName } from './describe';
import './animated.css';

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
      x === 0 ? '' : ` at t = ${formatRounded(x)} on its path`,
      formatRounded(f.frame.u),
      formatRounded(f.frame.v),
      formatRounded(l.near.value),
      formatRounded(l.bil.value),
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
      <p className="tx-small tx-stencil-key">
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

/**
 * The main figure (the grid, the query on its path, the value along it and the stencil beside it),
 * named and described at the still position: the description follows every parameter and the
 * paused position (while playing it holds, and is announced again on pause).
 */
export function DescribedMain({
  ctx,
  preset,
  sphere,
  point,
  normalize,
  editing,
  ask,
  children,
}: {
  ctx: AnimContext;
  preset: Preset;
  sphere: SphereModel;
  point: { x: number; y: number; z: number };
  normalize: boolean;
  /** The node being edited (null when not editing or none chosen). */
  editing: { i: number; j: number } | null;
  /** Ask first: the setup only (see describeTexture). */
  ask: boolean;
  children: ReactNode;
}) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame } = ctx.frame(t);
  const { grid, opts, src, path } = ctx;
  const description = useMemo(
    () =>
      describeTexture({
        name: textureName(grid, preset, src.isExam),
        opts,
        frame,
        path,
        notes: addressingNotes(frame.u, frame.v, opts, frame.lookup),
        editing:
          editing && editing.i < grid.width && editing.j < grid.height
            ? { ...editing, value: texel(grid, editing.i, editing.j) }
            : null,
        sphere: describeSphere(sphere, point, normalize, ask),
        ask,
      }),
    [grid, preset, src.isExam, opts, frame, path, editing, sphere, point, normalize, ask],
  );
  return (
    <DescribedFigure
      label="Texel grid with the query point, its path, and the value along the path"
      description={description}
      playing={playing}
      testId="texture-figure"
    >
      {children}
    </DescribedFigure>
  );
}
