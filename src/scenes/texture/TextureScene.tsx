/**
 * Texture lookup (exam Q3), exam first: the question as the exam states it with the figure that
 * teaches it (the grid, the query travelling its path, its stencil), then (a) nearest, (b) bilinear
 * and (c) the spherical mapping, each with the key's steps in live numbers and the live answer.
 * What goes beyond the exam is folded (./view/folds; closed on load, loaded when opened): the
 * settings, the path's shape and the value along it, the cell editor, the angle sliders, and
 * "explore further" (the whole texture reconstructed with its creases, the seam and the poles).
 * All figures come from ./model (pure, over the core); what is on screen at animation
 * position t is model.frameAt(grid, conventions, path, t). This file holds the scene's state and
 * its layout; the exam parts are in ./exam, the figures in ./view.
 */
import { useCallback, useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import type { SceneProps } from '../../kit/scene';
import { EXAM_GRID_TEXT, gridRange } from '../../core/texture';
import {
  AnimationDriver,
  createAnimationStore,
  ExamQuestion,
  ExploreFurther,
  Notice,
  Panel,
  Revealed,
  SceneLayout,
} from '../../ui';
import { gridTextIfFits, lookupOptions, resolveGrid, withCell } from './model';
import { pathOf, type QueryPath } from './path';
import { sphereModel } from './sphere';
import { GRID_TEXT_MAX, type TextureSchema } from './params';
import { useFoldOpen } from '../../ui/openFolds';
import { DURATION, RENDER_HZ, STEP, animContext, formatT } from './view/anim';
import { AnimGrid, AnimSide, DescribedMain } from './view/animated';
import { Controls } from './view/Controls';
import { ExamGives, GridValues, Legend } from './view/FigureParts';
import { EDIT_FOLD, EditFold, PathFold, SeamFold, WholeTextureFold } from './view/folds';
import { PageFigure, StageFigure, StageRest, type FigurePieces } from './view/Layout';
import type { Grab } from './view/GridView';
import { Q3a } from './exam/Q3a';
import { Q3b } from './exam/Q3b';
import { Q3c } from './exam/Q3c';
import './texture.css';

const TOO_LARGE_TO_EDIT =
  `This grid is too large to store in a link (over ${GRID_TEXT_MAX} characters), ` +
  'so its cells cannot be edited; pick a smaller size.';

export default function TextureScene({ params, setParams, mode }: SceneProps<TextureSchema>) {
  const [drag, setDrag] = useState<{ grab: 'a' | 'b'; u: number; v: number } | null>(null);
  const [editSwitch, setEditing] = useState(false);
  // the grid edits cells only while the editor's fold is open and its switch is on
  const [editOpen] = useFoldOpen(EDIT_FOLD);
  const editing = editSwitch && editOpen;
  const [selected, setSelected] = useState<{ i: number; j: number } | null>(null);
  const [editError, setEditError] = useState<string | null>(null);
  const figRef = useRef<HTMLDivElement>(null);
  // Enter on the grid while editing: focus the value field once it is rendered
  const [focusCell, setFocusCell] = useState(0);
  useEffect(() => {
    if (focusCell) document.querySelector<HTMLInputElement>('[data-testid=cell-field]')?.focus();
  }, [focusCell]);

  // the path as drawn (following a drag) and as committed to the URL
  const au = drag?.grab === 'a' ? drag.u : params.u;
  const av = drag?.grab === 'a' ? drag.v : params.v;
  const bu = drag?.grab === 'b' ? drag.u : params.u2;
  const bv = drag?.grab === 'b' ? drag.v : params.v2;
  const kind = params.path;
  const path = useMemo<QueryPath>(
    () => pathOf({ u: au, v: av, u2: bu, v2: bv, path: kind }),
    [au, av, bu, bv, kind],
  );

  const src = useMemo(
    () => resolveGrid({ grid: params.grid, preset: params.preset, size: params.size, seed: params.seed }),
    [params.grid, params.preset, params.size, params.seed],
  );
  const grid = src.grid;
  const opts = useMemo(
    () => lookupOptions({ align: params.align, vflip: params.vflip, wrap: params.wrap }),
    [params.align, params.vflip, params.wrap],
  );
  const range = useMemo(() => gridRange(grid), [grid]);
  const shown = { grid, opts, range };

  // The timeline lives in <AnimationDriver>, which publishes its position to this store; only the
  // components that draw the moving query subscribe to it (see ./view/anim), so a frame does not
  // re-render the scene.
  // (ask first: held at the start until revealed)
  const [store] = useState(() => createAnimationStore(mode.ask ? 0 : Number(params.t)));
  const dragging = drag !== null;
  const ctx = useMemo(
    () => animContext(store, grid, opts, src, path, dragging),
    [store, grid, opts, src, path, dragging],
  );
  const point = useMemo(() => ({ x: params.x, y: params.y, z: params.z }), [params.x, params.y, params.z]);
  const sphere = useMemo(
    () => sphereModel(grid, { ...point, normalize: params.normalize }, opts),
    [grid, point, params.normalize, opts],
  );

  const onMove = useCallback(
    (grab: Grab, ut: number, vt: number, final: boolean) => {
      const nv = opts.vflip ? Math.round((1 - vt) * 10000) / 10000 : vt;
      if (grab === 'query') {
        // the query goes where the pointer / keys put it: back to the start of the path (t = 0)
        const t = store.timeline();
        if (t && (t.t !== 0 || t.playing)) t.reset();
      }
      const which = grab === 'b' ? 'b' : 'a';
      if (final) {
        setDrag(null);
        setParams(which === 'b' ? { u2: ut, v2: nv } : { u: ut, v: nv });
      } else setDrag({ grab: which, u: ut, v: nv });
    },
    [opts.vflip, setParams, store],
  );
  // a new texture: the node being edited and its message no longer apply
  const onTexture = useCallback(() => {
    setSelected(null);
    setEditError(null);
  }, []);
  const onEditing = (on: boolean) => {
    setEditing(on);
    if (!on) setSelected(null);
  };
  const setCell = (x: number) => {
    if (!selected) return;
    const text = gridTextIfFits(withCell(grid, selected.i, selected.j, x));
    setEditError(text === null ? TOO_LARGE_TO_EDIT : null);
    if (text !== null) setParams({ preset: 'grid', grid: text });
  };
  const toExam = () => {
    setSelected(null);
    setParams({
      u: 0.4,
      v: 0.24,
      t: 0,
      play: false,
      preset: 'grid',
      grid: EXAM_GRID_TEXT,
      align: 'corner',
      vflip: false,
    });
  };
  const showChecker = () => setParams({ preset: 'checker', size: 8 });

  const controls = (
    <Controls params={params} setParams={setParams} grid={grid} isExam={src.isExam} onTexture={onTexture} />
  );

  const ask = mode.ask;
  const pieces: FigurePieces = {
    gives: <ExamGives />,
    grid: (
      <>
        <AnimGrid
          ctx={ctx}
          {...shown}
          onMove={onMove}
          editing={editing}
          selected={selected}
          onSelect={(i, j) => setSelected({ i, j })}
          onEditEnter={() => setFocusCell((k) => k + 1)}
          present={mode.present}
          ask={ask}
        />
        <Legend range={range} />
      </>
    ),
    // ask first: the query stays at the start of its path until the results are revealed
    transport: (
      <Revealed ask={ask} what="the query’s path (the animation)">
        <AnimationDriver
          store={store}
          t={Number(params.t)}
          play={params.play === true}
          setParams={setParams}
          visibleRef={figRef}
          max={1}
          duration={DURATION}
          stepSize={STEP}
          renderHz={RENDER_HZ}
          label="Query path"
          format={formatT}
        />
      </Revealed>
    ),
    path: <PathFold ctx={ctx} params={params} setParams={setParams} present={mode.present} ask={ask} />,
    side: (
      <Revealed ask={ask} what="the looked-up values and the weights">
        <AnimSide ctx={ctx} />
      </Revealed>
    ),
    editor: (
      <>
        <EditFold
          ctx={ctx}
          editing={editSwitch}
          onEditing={onEditing}
          selected={selected}
          onSelect={(i, j) => setSelected({ i, j })}
          onCell={setCell}
          error={editError}
        />
        <GridValues grid={grid} opts={opts} />
      </>
    ),
  };
  const described = (children: ReactNode) => (
    <DescribedMain
      ctx={ctx}
      preset={params.preset}
      sphere={sphere}
      point={point}
      normalize={params.normalize}
      editing={editing ? selected : null}
      ask={ask}
    >
      {children}
    </DescribedMain>
  );
  // classroom mode: the grid, its readouts and the transport on the stage, the rest below
  const stage = mode.present ? described(<StageFigure p={pieces} figRef={figRef} />) : undefined;
  const figure = (
    <Panel className="tx-figure">
      {src.problems.map((p) => (
        <Notice key={p.name} kind="warn" testId="grid-error">
          <strong>{p.name}</strong>: {p.message} Using the exam’s 5 × 5 grid instead.
        </Notice>
      ))}
      {mode.present ? <StageRest p={pieces} /> : described(<PageFigure p={pieces} figRef={figRef} />)}
    </Panel>
  );

  const main = (
    <>
      <ExamQuestion n={3} intro={figure}>
        <Q3a ctx={ctx} toExam={toExam} ask={ask} />
        <Q3b ctx={ctx} toExam={toExam} ask={ask} />
        <Q3c
          params={params}
          setParams={setParams}
          sphere={sphere}
          src={src}
          {...shown}
          present={mode.present}
          ask={ask}
        />
      </ExamQuestion>
      <ExploreFurther
        intro={
          'Beyond the exam: the whole texture under both filters, where bilinear creases, and what the ' +
          'spherical mapping does at its seam and poles.'
        }
      >
        <WholeTextureFold
          ctx={ctx}
          range={range}
          isExam={src.isExam}
          showChecker={params.preset !== 'checker' ? showChecker : null}
        />
        <SeamFold sphere={sphere} opts={opts} normalize={params.normalize} />
      </ExploreFurther>
    </>
  );

  return <SceneLayout controls={controls} main={main} stage={stage} />;
}
