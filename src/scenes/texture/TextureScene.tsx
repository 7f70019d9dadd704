/**
 * Texture lookup (exam Q3), exam first: the question as the exam states it with the figure that
 * teaches it (the grid, the query travelling its path, the value along the path), then (a) nearest,
 * (b) bilinear and (c) the spherical mapping, each with the key's steps in live numbers and the
 * live answer, then "explore further" (the whole texture reconstructed, its creases, the seam and
 * the poles). All figures come from ./model (pure, over the core); what is on screen at animation
 * position t is model.frameAt(grid, conventions, path, t).
 */
import {
  memo,
  startTransition,
  useCallback,
  useDeferredValue,
  useEffect,
  useMemo,
  useRef,
  useState,
  type ComponentProps,
} from 'react';
import type { SceneProps } from '../../kit/scene';
import { EXAM_GRID_TEXT, examGrid, gridRange, gridToRows, parseGrid, texel } from '../../core/texture';
import {
  AnimationDriver,
  createAnimationStore,
  Derivation,
  ExamPart,
  ExamQuestion,
  ExploreFurther,
  KeyNote,
  LiveAnswer,
  LiveReadout,
  Notice,
  NumberField,
  Panel,
  nextTask,
  Readout,
  SceneLayout,
  Select,
  Slider,
  Toggle,
  useAnimFrame,
  usePlaying,
  useStillT,
  writeReadout,
} from '../../ui';
import {
  KEY_PRINTED,
  addressingNotes,
  agreesWithKey,
  creases,
  gridTextIfFits,
  isExamQuery,
  isExamSphere,
  lookupAt,
  lookupOptions,
  pathOf,
  pathProfile,
  queryReadouts,
  resolveGrid,
  sphereReadouts,
  sphereModel,
  withCell,
  type Lookup,
  type QueryPath,
} from './model';
import { DURATION, RENDER_HZ, STEP, animContext, formatT, type AnimContext } from './anim';
import { GRID_TEXT_MAX, type PathKind, type Preset, type TextureSchema } from './params';
import { GridView, StencilDetail, fmtShort, type Grab } from './view/GridView';
import { BilinearWorked, NearestWorked, WideMath, bilinearTex, sphereTex } from './view/WorkedSteps';
import { PathPlot } from './view/PathPlot';
import { Reconstruction } from './view/Reconstruction';
import { SphereView } from './view/SphereView';
import { colorCss } from './colormap';
import './texture.css';

type PresetChoice = 'exam' | 'custom' | Exclude<Preset, 'grid'>;

const r4 = (x: number) => Math.round(x * 10000) / 10000 + 0;

export default function TextureScene({ params, setParams, mode }: SceneProps<TextureSchema>) {
  const [drag, setDrag] = useState<{ grab: 'a' | 'b'; u: number; v: number } | null>(null);
  const [editing, setEditing] = useState(false);
  const [selected, setSelected] = useState<{ i: number; j: number } | null>(null);
  const [editError, setEditError] = useState<string | null>(null);
  const figRef = useRef<HTMLDivElement>(null);
  // Enter on the grid while editing: focus the value field once it is rendered
  const [focusCell, setFocusCell] = useState(0);
  useEffect(() => {
    if (focusCell) document.querySelector<HTMLInputElement>('[data-testid=cell-field]')?.focus();
  }, [focusCell]);

  const au = drag?.grab === 'a' ? drag.u : params.u;
  const av = drag?.grab === 'a' ? drag.v : params.v;
  const bu = drag?.grab === 'b' ? drag.u : params.u2;
  const bv = drag?.grab === 'b' ? drag.v : params.v2;
  const kind = params.path as PathKind;
  const path = useMemo<QueryPath>(
    () => pathOf({ u: au, v: av, u2: bu, v2: bv, path: kind }),
    [au, av, bu, bv, kind],
  );
  const committedPath = useMemo<QueryPath>(
    () => pathOf({ u: params.u, v: params.v, u2: params.u2, v2: params.v2, path: kind }),
    [params.u, params.v, params.u2, params.v2, kind],
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

  // The timeline lives in <AnimationDriver>, which publishes its position to this store; only the
  // components that draw the moving query subscribe to it (see ./anim), so a frame does not
  // re-render the scene.
  const [store] = useState(() => createAnimationStore(Number(params.t)));
  const ctx = useMemo(
    () => animContext(store, grid, opts, src, path, committedPath),
    [store, grid, opts, src, path, committedPath],
  );
  const sphere = useMemo(
    () => sphereModel(grid, { x: params.x, y: params.y, z: params.z, normalize: params.normalize }, opts),
    [grid, params.x, params.y, params.z, params.normalize, opts],
  );
  const ro = useMemo(() => sphereReadouts(sphere), [sphere]);
  const examS = isExamSphere(src, opts, sphere);

  const dir = useMemo<[number, number, number] | null>(() => {
    if (!sphere.ok) return null;
    return [params.x / sphere.r, params.y / sphere.r, params.z / sphere.r];
  }, [sphere, params.x, params.y, params.z]);

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
  const onPick = useCallback(
    (p: [number, number, number]) => {
      setParams({ x: r4(p[0]), y: r4(p[1]), z: r4(p[2]) });
    },
    [setParams],
  );

  const presetChoice: PresetChoice =
    params.preset === 'grid' ? (src.isExam ? 'exam' : 'custom') : (params.preset as PresetChoice);
  const presetOptions: { value: PresetChoice; label: string }[] = [
    { value: 'exam', label: 'The exam’s 5 × 5 grid' },
    { value: 'checker', label: 'Checkerboard' },
    { value: 'gradient', label: 'Gradient' },
    { value: 'random', label: 'Random (seeded)' },
  ];
  if (presetChoice === 'custom') presetOptions.push({ value: 'custom', label: 'Custom (grid text)' });

  const setCell = (x: number) => {
    if (!selected) return;
    const next = withCell(grid, selected.i, selected.j, x);
    const text = gridTextIfFits(next);
    if (text === null) {
      setEditError(
        `This grid is too large to store in a link (over ${GRID_TEXT_MAX} characters), so its cells cannot be edited; pick a smaller size.`,
      );
      return;
    }
    setEditError(null);
    setParams({ preset: 'grid', grid: text });
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

  // where the sphere point is, as angles (a keyboard path to "picking" a point on the sphere)
  const phiDeg = sphere.ok ? (sphere.phi * 180) / Math.PI : 0;
  const thetaDeg = sphere.ok ? (sphere.theta * 180) / Math.PI : 0;
  const setAngles = (phDeg: number, thDeg: number) => {
    const r = sphere.ok ? sphere.r : 1;
    const ph = (phDeg * Math.PI) / 180;
    const th = (thDeg * Math.PI) / 180;
    setParams({
      x: r4(r * Math.cos(ph) * Math.sin(th)),
      y: r4(r * Math.sin(ph) * Math.sin(th)),
      z: r4(r * Math.cos(th)),
    });
  };

  // Parts that do not depend on the animation position are memoized, so a frame only re-renders
  // the figure's moving parts and the readouts.
  const controls = useMemo(
    () => (
      <>
        <Panel title="Query point and path" className="tx-panel-query">
          <Slider
            label="u (the query at t = 0)"
            value={params.u}
            min={-2}
            max={3}
            step={0.001}
            onChange={(x) => setParams({ u: x })}
            testId="u-slider"
          />
          <Slider
            label="v (the query at t = 0)"
            value={params.v}
            min={-2}
            max={3}
            step={0.001}
            onChange={(x) => setParams({ v: x })}
            testId="v-slider"
          />
          <p className="tx-small">
            Or click / drag on the grid; with the grid focused, arrow keys move the query (Shift: by 0.1).
          </p>
        </Panel>
        <Panel title="Conventions" className="tx-panel-conventions">
          <Select
            label="Where the values sit"
            value={opts.align}
            options={[
              { value: 'corner', label: 'Corner nodes (exam)' },
              { value: 'center', label: 'Texel centres (GPU)' },
            ]}
            onChange={(x) => setParams({ align: x })}
            testId="align-select"
          />
          <Toggle
            label="Flip v: v′ = 1 − v (the key accepts it)"
            checked={params.vflip}
            onChange={(x) => setParams({ vflip: x })}
            testId="vflip-toggle"
          />
          <Select
            label="Addressing outside [0, 1]"
            value={params.wrap as 'clamp' | 'repeat' | 'mirror'}
            options={[
              { value: 'clamp', label: 'Clamp to edge' },
              { value: 'repeat', label: 'Repeat' },
              { value: 'mirror', label: 'Mirrored repeat' },
            ]}
            onChange={(x) => setParams({ wrap: x })}
            testId="wrap-select"
          />
        </Panel>
        <Panel title="Texture" className="tx-panel-texture">
          <Select
            label="Values"
            value={presetChoice}
            options={presetOptions}
            onChange={(x) => {
              setSelected(null);
              setEditError(null);
              if (x === 'exam') setParams({ preset: 'grid', grid: EXAM_GRID_TEXT });
              else if (x !== 'custom') setParams({ preset: x });
            }}
            testId="preset-select"
          />
          {params.preset !== 'grid' ? (
            <>
              <NumberField
                label="Size N (N × N, 2 to 64)"
                value={params.size}
                min={2}
                max={64}
                step={1}
                onChange={(x) => setParams({ size: Math.round(x) })}
                testId="size-field"
              />
              {params.preset === 'random' ? (
                <button type="button" onClick={() => setParams({ seed: (params.seed + 1) % 4294967296 })}>
                  New random values (seed {params.seed + 1})
                </button>
              ) : null}
            </>
          ) : null}
          <GridText
            key={params.grid + params.preset}
            text={params.preset === 'grid' ? params.grid : (gridTextIfFits(grid) ?? '')}
            onApply={(t) => setParams({ preset: 'grid', grid: t })}
          />
        </Panel>
      </>
    ),
    // presetOptions follows presetChoice
    [params, setParams, opts.align, presetChoice, grid],
  );

  const figure = (
    <Panel className="tx-figure">
      {src.error ? (
        <Notice kind="warn" testId="grid-error">
          <strong>grid</strong>: {src.error} Using the exam’s 5 × 5 grid instead.
        </Notice>
      ) : null}
      <div className="tx-figure-cols" ref={figRef}>
        <div className="exam-asks tx-gives">
          <span className="exam-asks-label">The exam gives</span>
          <p>
            A 5 × 5 texture with values at the nodes (u, v) = (i/4, j/4), v upward. (a), (b): look it up at
            (u, v) = (0.4, 0.24); (c): at a point on a sphere.
          </p>
          <ExamGridTable />
        </div>
        <div className="tx-figure-main">
          <AnimGrid
            ctx={ctx}
            grid={grid}
            opts={opts}
            range={range}
            onMove={onMove}
            editing={editing}
            selected={selected}
            onSelect={(i, j) => setSelected({ i, j })}
            onEditEnter={() => setFocusCell((k) => k + 1)}
            present={mode.present}
          />
          <Legend range={range} />
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
          >
            <label className="tx-path-kind">
              <span>Path</span>
              <select
                value={kind}
                onChange={(e) => setParams({ path: e.target.value === 'circle' ? 'circle' : 'line' })}
                data-testid="path-select"
              >
                <option value="line">line to (u₂, v₂)</option>
                <option value="circle">circle through both</option>
              </select>
            </label>
          </AnimationDriver>
          <div className="tx-path-end">
            <span>Path end</span>
            <NumberField
              label="u₂"
              value={params.u2}
              min={-4}
              max={4}
              step={0.01}
              onChange={(x) => setParams({ u2: x })}
              testId="u2-field"
            />
            <NumberField
              label="v₂"
              value={params.v2}
              min={-4}
              max={4}
              step={0.01}
              onChange={(x) => setParams({ v2: x })}
              testId="v2-field"
            />
          </div>
          <AnimPathPlot ctx={ctx} present={mode.present} />
        </div>
        <div className="tx-figure-side">
          <AnimSide ctx={ctx} />
          <div className="tx-edit">
            <Toggle
              label="Edit cells (click a node, or arrow keys on the grid, then Enter)"
              checked={editing}
              onChange={(x) => {
                setEditing(x);
                if (!x) setSelected(null);
              }}
              testId="edit-toggle"
            />
            {editing && selected && selected.i < grid.width && selected.j < grid.height ? (
              <NumberField
                label={`Value at column ${selected.i}, row ${selected.j} (from the bottom)`}
                value={texel(grid, selected.i, selected.j)}
                onChange={setCell}
                step={1}
                testId="cell-field"
              />
            ) : editing ? (
              <p className="tx-small">
                Click a node, or focus the grid and use the arrow keys, to choose the value to edit.
              </p>
            ) : null}
            {editError ? <Notice kind="warn">{editError}</Notice> : null}
          </div>
        </div>
      </div>
    </Panel>
  );

  const part3c = useMemo(
    () => (
      <ExamPart
        id="3c"
        title="The spherical mapping"
        asks={
          <>
            A point on a sphere, x = r cos u sin v, y = r sin u sin v, z = r cos v, has y/x = 1 and z/r =
            √2/2. Find its texture coordinates (u, v) and the bilinear value there.
          </>
        }
      >
        <div className="tx-sphere-cols">
          <div className="tx-sphere-inputs">
            <NumberField
              label="x"
              value={params.x}
              min={-1000}
              max={1000}
              onChange={(x) => setParams({ x })}
              testId="x-field"
            />
            <NumberField
              label="y"
              value={params.y}
              min={-1000}
              max={1000}
              onChange={(y) => setParams({ y })}
              testId="y-field"
            />
            <NumberField
              label="z"
              value={params.z}
              min={-1000}
              max={1000}
              onChange={(z) => setParams({ z })}
              testId="z-field"
            />
            <Slider
              label="Azimuth φ (moves the point)"
              unit="°"
              value={r4(phiDeg)}
              min={0}
              max={359.9}
              step={0.1}
              onChange={(x) => setAngles(x, thetaDeg)}
              testId="phi-slider"
            />
            <Slider
              label="Polar angle θ (moves the point)"
              unit="°"
              value={r4(thetaDeg)}
              min={0}
              max={180}
              step={0.1}
              onChange={(x) => setAngles(phiDeg, x)}
              testId="theta-slider"
            />
            <Toggle
              label="Normalize by (2π, π)"
              checked={params.normalize}
              onChange={(x) => setParams({ normalize: x })}
              testId="normalize-toggle"
            />
            <button
              type="button"
              onClick={() => setParams({ x: 1, y: 1, z: Math.SQRT2 })}
              data-testid="exam-point"
            >
              The exam’s point (y/x = 1, z/r = √2/2)
            </button>
          </div>
          <div className="tx-sphere-fig">
            <SphereView
              grid={grid}
              opts={opts}
              range={range}
              normalize={params.normalize}
              dir={dir}
              onPick={onPick}
              height={mode.present ? 420 : 320}
            />
            <p className="tx-small">
              Click the sphere to pick a point, or use the angle sliders or the x, y, z fields.
            </p>
          </div>
        </div>
        {!sphere.ok ? (
          <Notice kind="warn" testId="sphere-error">
            <strong>x, y, z</strong>: {sphere.message} The sphere readouts show “none” until you pick another
            point.
          </Notice>
        ) : null}
        {sphere.ok ? (
          <Derivation testId="derivation-3c">
            <p className="tx-small">
              Divide y by x to eliminate r and v, and z by r to isolate v. The key writes u = arctan(y/x);
              atan2(y, x) is the same for x &gt; 0 and also finds the right quadrant when x ≤ 0 (negative
              angles get + 2π, so u ∈ [0, 2π)). Then normalize by the ranges (2π, π) of the two angles to land
              in [0, 1]:
            </p>
            <WideMath
              label="Spherical coordinates, step by step"
              tex={`\\begin{aligned}${sphereTex({ x: params.x, y: params.y, z: params.z, r: sphere.r, phi: sphere.phi, theta: sphere.theta, pole: sphere.pole, u: sphere.normalized.u, v: sphere.normalized.v })}\\end{aligned}`}
            />
            <p className="tx-small">
              Bilinear at the normalized (u, v), in the key’s form (each step divided by the cell size):
            </p>
            <WideMath
              label="Bilinear steps at the sphere point"
              tex={`\\begin{aligned}${bilinearTex(sphere.normalized, opts)}\\end{aligned}`}
            />
            {sphere.normalized.bil.fv === 0 || sphere.normalized.bil.fu === 0 ? (
              <p className="tx-small">
                The point lies on a node line ({sphere.normalized.bil.fv === 0 ? 'v = v₀' : 'u = u₀'}), so one
                of the two rows gets weight 0: that is the key’s one-line form.
              </p>
            ) : null}
          </Derivation>
        ) : null}
        <LiveAnswer testId="answer-3c">
          <div className="readouts">
            <Readout
              id="sphere-u"
              label={params.normalize ? 'u = φ / 2π' : 'u = φ (radians)'}
              value={ro.sphereU}
            />
            <Readout
              id="sphere-v"
              label={params.normalize ? 'v = θ / π' : 'v = θ (radians)'}
              value={ro.sphereV}
            />
            <Readout
              id="sphere-bilinear"
              label={params.normalize ? 'Bilinear at (u, v)' : 'Bilinear at (φ, θ), not normalized'}
              value={ro.sphereBilinear}
              note={
                examS && ro.sphereBilinear !== null
                  ? keyNote(ro.sphereBilinear, params.normalize ? KEY_PRINTED.sphere : KEY_PRINTED.sphereRaw)
                  : undefined
              }
            />
          </div>
          {sphere.ok ? (
            <div
              className="tx-table-wrap"
              tabIndex={0}
              role="group"
              aria-label="The sphere point, normalized and not (the table scrolls sideways on narrow screens)"
            >
              <table className="worked tx-compare" data-testid="sphere-compare">
                <thead>
                  <tr>
                    <th />
                    <th>normalized</th>
                    <th>forgot to normalize</th>
                  </tr>
                </thead>
                <tbody>
                  <tr>
                    <th>u</th>
                    <td>{texPlain(sphere.normalized.u)}</td>
                    <td>{texPlain(sphere.raw.u)}</td>
                  </tr>
                  <tr>
                    <th>v</th>
                    <td>{texPlain(sphere.normalized.v)}</td>
                    <td>{texPlain(sphere.raw.v)}</td>
                  </tr>
                  <tr>
                    <th>(u, v) as used</th>
                    <td>
                      ({fmtShort(sphere.normalized.bil.u)}, {fmtShort(sphere.normalized.bil.v)})
                    </td>
                    <td>
                      ({fmtShort(sphere.raw.bil.u)}, {fmtShort(sphere.raw.bil.v)})
                    </td>
                  </tr>
                  <tr>
                    <th>bilinear</th>
                    <td data-testid="sphere-normalized-value">{texPlain(sphere.normalized.bil.value)}</td>
                    <td data-testid="sphere-raw-value">{texPlain(sphere.raw.bil.value)}</td>
                  </tr>
                </tbody>
              </table>
            </div>
          ) : null}
        </LiveAnswer>
        {sphere.ok ? (
          <KeyNote testId="key-note">
            the key cuts 2.5 marks when the normalization is missing, but gives full marks for a lookup at the
            un-normalized (π/4, π/4) done right, and prints {KEY_PRINTED.sphereRaw.value} for it.{' '}
            {examS ? (
              <ExamSphereNote normalized={sphere.normalized.bil.value} raw={sphere.raw.bil.value} />
            ) : (
              `Here the un-normalized lookup gives ${texPlain(sphere.raw.bil.value)}.`
            )}
          </KeyNote>
        ) : null}
      </ExamPart>
    ),
    // setAngles reads only sphere and setParams
    [params, setParams, sphere, examS, ro, grid, opts, range, dir, onPick, mode.present],
  );

  const main = (
    <>
      <ExamQuestion n={3} title="Texture lookup" intro={figure}>
        <ExamPart
          id="3a"
          title="Nearest neighbour"
          asks={<>What value does nearest-neighbour lookup return at (u, v) = (0.4, 0.24)?</>}
        >
          <NotExam ctx={ctx} toExam={toExam} />
          <Derivation testId="derivation-3a">
            <WorkedNearest ctx={ctx} />
          </Derivation>
          <LiveAnswer testId="answer-3a">
            <Readouts3a ctx={ctx} />
          </LiveAnswer>
          <KeyNote testId="keynote-3a">
            <KeyNote3a ctx={ctx} />
          </KeyNote>
        </ExamPart>
        <ExamPart
          id="3b"
          title="Bilinear"
          asks={<>What value does bilinear interpolation give at (u, v) = (0.4, 0.24)?</>}
        >
          <NotExam ctx={ctx} toExam={toExam} />
          <Derivation testId="derivation-3b">
            <WorkedBilinear ctx={ctx} />
          </Derivation>
          <LiveAnswer testId="answer-3b">
            <Readouts3b ctx={ctx} />
          </LiveAnswer>
          <KeyNote testId="keynote-3b">
            <KeyNote3b ctx={ctx} />
          </KeyNote>
        </ExamPart>
        {part3c}
      </ExamQuestion>
      <ExploreFurther intro="Beyond the exam: the whole texture under both filters, where bilinear creases, and what the spherical mapping does at its seam and poles.">
        <ReconstructionPanel
          ctx={ctx}
          range={range}
          isExam={src.isExam}
          showChecker={params.preset !== 'checker' ? showChecker : null}
        />
        <Panel title="The sphere’s seam and poles">
          <p className="tx-small">
            <strong>Seam.</strong> atan2 returns angles in (−π, π]; adding 2π to the negative ones puts φ in
            [0, 2π), so u runs from 0 at +x all the way round to just below 1. The meridian φ = 0 (red) is
            where u jumps from 1 back to 0: u = 1 is never produced, so the seam belongs to u = 0. Unless the
            texture’s left and right columns match (or the lookup repeats with texel centres), the picture
            jumps there.
          </p>
          <p className="tx-small">
            <strong>Poles.</strong> On the z axis (x = y = 0) every φ names the same point, so u is undefined;
            we define u = 0. θ is computed as atan2(√(x² + y²), z), which equals arccos(z/r) but keeps full
            precision near the poles.
          </p>
          {sphere.ok ? (
            <details className="tx-details">
              <summary>
                Bilinear steps for the sphere point ({params.normalize ? 'normalized' : 'not normalized'})
              </summary>
              <WideMath
                label="Bilinear steps at the sphere point"
                tex={`\\begin{aligned}${bilinearTex(sphere.chosen, opts)}\\end{aligned}`}
              />
            </details>
          ) : null}
        </Panel>
      </ExploreFurther>
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}

/** Explore further: the whole texture under both filters, with the bilinear creases (computed when this part mounts). */
function ReconstructionPanel({
  ctx,
  range,
  isExam,
  showChecker,
}: {
  ctx: AnimContext;
  range: { min: number; max: number };
  isExam: boolean;
  /** Offered when the grid has no crease (null: the checkerboard is already shown). */
  showChecker: (() => void) | null;
}) {
  const { grid, opts } = ctx;
  const crease = useMemo(() => creases(grid, opts), [grid, opts]);
  return (
    <Panel title="The whole texture, reconstructed">
      <AnimReconstruction ctx={ctx} range={range} creases={crease.list} />
      <p className="tx-small" data-testid="crease-caption">
        Both images show [0, 1]² {opts.vflip ? '(in the flipped frame v′) ' : ''}magnified; the cross is the
        query. Nearest copies the closest value, so it is blocky. Bilinear is continuous, and linear along u
        and along v inside each cell, so its slope can change only across node lines — and only where the
        values do not continue linearly across the line (a non-zero second difference).{' '}
        {creaseSentence(crease.creased, crease.lines, isExam)}
        {crease.creased === 0 && showChecker ? (
          <>
            {' '}
            <button type="button" onClick={showChecker} data-testid="show-checker">
              Show the checkerboard
            </button>
          </>
        ) : null}
      </p>
    </Panel>
  );
}

function creaseSentence(creased: number, lines: number, isExam: boolean): string {
  if (lines === 0) return 'This grid has no interior node lines.';
  if (creased === 0)
    return `On this grid none of the ${lines} interior node lines is a crease: the values change linearly across every one${isExam ? ' (the exam’s grid is the linear function 21 + 4u − 20v)' : ''}, so bilinear reproduces a smooth (here planar) surface.`;
  if (creased === lines)
    return `On this grid all ${lines} of the ${lines} interior node lines are creases (dashed on the bilinear image).`;
  return `On this grid ${creased} of the ${lines} interior node lines ${creased === 1 ? 'is a crease' : 'are creases'} (dashed on the bilinear image); across the others the values continue linearly and the surface is smooth.`;
}

/** The exam's grid as the exam prints it (v = 1 on top). */
const ExamGridTable = memo(function ExamGridTable() {
  const rows = gridToRows(examGrid());
  const n = rows.length;
  return (
    <table
      className="tx-exam-grid"
      data-testid="exam-grid"
      aria-label="The exam’s texture: rows from v = 1 (top) to v = 0, columns u = 0 to 1"
    >
      <tbody>
        {rows.map((row, k) => (
          <tr key={k}>
            <th scope="row">{(n - 1 - k) / (n - 1)}</th>
            {row.map((x, i) => (
              <td key={i}>{x}</td>
            ))}
          </tr>
        ))}
        <tr>
          <th scope="row">v↑ u→</th>
          {rows[0].map((_, i) => (
            <th key={i} scope="col">
              {i / (rows[0].length - 1)}
            </th>
          ))}
        </tr>
      </tbody>
    </table>
  );
});

function texPlain(x: number): string {
  return Number.isFinite(x) ? String(Number(x.toPrecision(6))) : '—';
}

function keyNote(computed: number, printed: { value: number; decimals: number }): string {
  return agreesWithKey(computed, printed)
    ? `agrees with the key’s printed ${printed.value}`
    : `the key prints ${printed.value}; the computed value rounds to ${computed.toFixed(printed.decimals)}`;
}

function ExamSphereNote({ normalized, raw }: { normalized: number; raw: number }) {
  const closed = 21 - 4 * Math.PI;
  return (
    <span className="tx-note-text">
      On the exam’s grid the texture is the linear function 21 + 4u − 20v, which bilinear filtering reproduces
      exactly. Normalized, (1/8, 1/4) gives {texPlain(normalized)} (
      {agreesWithKey(normalized, KEY_PRINTED.sphere)
        ? 'as the key prints'
        : `the key prints ${KEY_PRINTED.sphere.value}`}
      ). Not normalized, (π/4, π/4) ≈ (0.785, 0.785) is still inside [0, 1], so no addressing is involved, and
      the value is 21 − 4π = {texPlain(closed)}; this lookup gives {texPlain(raw)}.{' '}
      {agreesWithKey(raw, KEY_PRINTED.sphereRaw)
        ? `The key’s ${KEY_PRINTED.sphereRaw.value} agrees.`
        : `The key prints ${KEY_PRINTED.sphereRaw.value}, which differs in the second decimal (the exact value rounds to ${raw.toFixed(2)}).`}
    </span>
  );
}

const Legend = memo(function Legend({ range }: { range: { min: number; max: number } }) {
  const stops = Array.from({ length: 11 }, (_, k) => colorCss(k / 10)).join(', ');
  return (
    <div className="tx-legend" aria-hidden="true">
      <span>{fmtShort(range.min)}</span>
      <span className="tx-legend-bar" style={{ background: `linear-gradient(to right, ${stops})` }} />
      <span>{fmtShort(range.max)}</span>
    </div>
  );
});

/** The grid as text (rows top to bottom); applies only text that parses, else says why. */
function GridText({ text, onApply }: { text: string; onApply: (t: string) => void }) {
  const [draft, setDraft] = useState(text);
  const [error, setError] = useState<string | null>(null);
  const apply = () => {
    const t = draft.trim();
    const r = parseGrid(t);
    if (!r.ok) {
      setError(r.message);
      return;
    }
    if (t.length > GRID_TEXT_MAX) {
      setError(`The text is longer than ${GRID_TEXT_MAX} characters, too long for a link.`);
      return;
    }
    setError(null);
    onApply(t);
  };
  return (
    <div className="field">
      <label className="field-label" htmlFor="tx-grid-text">
        Grid as text (rows top to bottom, “;” between rows, “,” between values)
      </label>
      <textarea
        id="tx-grid-text"
        className="tx-grid-text"
        data-testid="grid-text"
        rows={4}
        spellCheck={false}
        value={draft}
        aria-invalid={error ? true : undefined}
        onChange={(e) => setDraft(e.target.value)}
      />
      <button type="button" onClick={apply} data-testid="grid-apply">
        Use this grid
      </button>
      {error ? (
        <span className="field-error" role="alert" data-testid="grid-text-error">
          {error}
        </span>
      ) : null}
    </div>
  );
}

// ---- The animated parts (./anim): the figures render at the paused position and their moving
// nodes are written per frame without React; the text parts follow the timeline's coarse position.

/** The grid figure with the query at position t (the grid's layers are memoized inside). */
function AnimGrid({
  ctx,
  ...rest
}: { ctx: AnimContext } & Omit<ComponentProps<typeof GridView>, 'q' | 'path' | 'drawRef'>) {
  const t = useStillT(ctx.store);
  const draw = useRef<((q: ReturnType<AnimContext['frame']>['dq']) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => draw.current?.(ctx.frame(x).dq));
  return <GridView {...rest} q={ctx.frame(t).dq} path={ctx.path} drawRef={draw} />;
}

/**
 * True from one task after the component mounted: work that can wait for it (a figure below the
 * first screen of a phone) is not part of the page's first render (issue 15: no long task on load).
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
function AnimPathPlot({ ctx, present }: { ctx: AnimContext; present: boolean }) {
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
function AnimSide({ ctx }: { ctx: AnimContext }) {
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

/** Q3(a)'s live answer at position t (written per frame; the key note only while paused). */
function Readouts3a({ ctx }: { ctx: AnimContext }) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame } = ctx.frame(t);
  const ro = queryReadouts(frame.lookup);
  const examQ = !playing && isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);
  const near = useRef<HTMLOutputElement>(null);
  const uv = useRef<HTMLOutputElement>(null);
  useAnimFrame(ctx.store, (x, text) => {
    if (!text) return;
    const q = ctx.frame(x).frame.lookup;
    writeReadout(near.current, queryReadouts(q).nearest);
    writeReadout(uv.current, `(${fmtShort(q.bil.u)}, ${fmtShort(q.bil.v)})`);
  });
  return (
    <div className="readouts">
      <LiveReadout
        id="nearest"
        label="Nearest (Q3a)"
        outRef={near}
        note={examQ ? keyNote(ro.nearest, KEY_PRINTED.nearest) : undefined}
      />
      <LiveReadout id="query-uv" label="(u, v) as used" outRef={uv} />
    </div>
  );
}

/** Q3(b)'s live answer at position t (written per frame; the key note only while paused). */
function Readouts3b({ ctx }: { ctx: AnimContext }) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame } = ctx.frame(t);
  const ro = queryReadouts(frame.lookup);
  const examQ = !playing && isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);
  const bil = useRef<HTMLOutputElement>(null);
  useAnimFrame(ctx.store, (x, text) => {
    if (text) writeReadout(bil.current, queryReadouts(ctx.frame(x).frame.lookup).bilinear);
  });
  return (
    <div className="readouts">
      <LiveReadout
        id="bilinear"
        label="Bilinear (Q3b)"
        outRef={bil}
        note={examQ ? keyNote(ro.bilinear, KEY_PRINTED.bilinear) : undefined}
      />
    </div>
  );
}

/** The reconstructions with the query's cross at position t (the images are memoized inside). */
function AnimReconstruction({
  ctx,
  range,
  creases,
}: {
  ctx: AnimContext;
  range: { min: number; max: number };
  creases: ComponentProps<typeof Reconstruction>['creases'];
}) {
  const t = useStillT(ctx.store);
  const { dq } = ctx.frame(t);
  const draw = useRef<((qu: number, qv: number) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => {
    const d = ctx.frame(x).dq;
    draw.current?.(d.bil.u, d.bil.v);
  });
  return (
    <Reconstruction
      grid={ctx.grid}
      opts={ctx.opts}
      range={range}
      qu={dq.bil.u}
      qv={dq.bil.v}
      creases={creases}
      drawRef={draw}
    />
  );
}

/**
 * The worked steps follow the committed path; while playing they hold the position where it
 * started (exact again as soon as it pauses, steps or seeks), so no frame carries a KaTeX typeset.
 */
function useWorked(ctx: AnimContext) {
  const tWorked = useStillT(ctx.store);
  return { tWorked, frame: ctx.worked(tWorked) };
}

function NotExam({ ctx, toExam }: { ctx: AnimContext; toExam: () => void }) {
  const { tWorked, frame } = useWorked(ctx);
  const { src, opts } = ctx;
  if (isExamQuery(src, opts, frame.u, frame.v)) return null;
  return (
    <p className="tx-small tx-not-exam" data-testid="not-exam-query">
      The steps use the current query (u, v) = ({fmtShort(frame.u)}, {fmtShort(frame.v)})
      {tWorked !== 0 ? `, at t = ${fmtShort(tWorked)} on its path` : ''}
      {src.isExam ? '' : ', on a grid that is not the exam’s'}
      {opts.align !== 'corner' ? ', with texel centres' : ''}
      {opts.vflip ? ', with v flipped' : ''}.{' '}
      <button type="button" onClick={toExam} data-testid="to-exam">
        Back to the exam’s question
      </button>
    </p>
  );
}

function WorkedNearest({ ctx }: { ctx: AnimContext }) {
  const q = useDeferredValue(useWorked(ctx).frame.lookup);
  return <NearestWorked grid={ctx.grid} opts={ctx.opts} q={q} />;
}

function WorkedBilinear({ ctx }: { ctx: AnimContext }) {
  const q = useDeferredValue(useWorked(ctx).frame.lookup);
  return <BilinearWorked opts={ctx.opts} q={q} />;
}

function KeyNote3a({ ctx }: { ctx: AnimContext }) {
  const { frame } = useWorked(ctx);
  const { grid, opts } = ctx;
  const flipped = useMemo(
    () => lookupAt(grid, frame.u, frame.v, { ...opts, vflip: !opts.vflip }),
    [grid, frame.u, frame.v, opts],
  );
  return (
    <>
      the key gives the node (0.5, 0.25) with the value 18 and also awards marks for a stated different
      convention, for example v′ = 1 − v (v measured downward). With the flip{' '}
      {opts.vflip ? 'undone' : 'applied'} here, nearest gives {fmtShort(flipped.near.value)} (the node at (
      {fmtShort(flipped.near.nodeU)}, {fmtShort(flipped.near.nodeV)}) of the flipped frame) and bilinear{' '}
      {fmtShort(flipped.bil.value)}.
    </>
  );
}

function KeyNote3b({ ctx }: { ctx: AnimContext }) {
  const { frame } = useWorked(ctx);
  const workedQ = useDeferredValue(frame.lookup);
  const workedExam = isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);
  return (
    <>
      the key deducts 2.5 marks when the division by the cell size 0.25 is missing. Without it each step is
      scaled by Δ: c_u would be {fmtShort(workedQ.steps.cu * workedQ.bil.du)}, c_l{' '}
      {fmtShort(workedQ.steps.cl * workedQ.bil.du)} and c{' '}
      {fmtShort(workedQ.steps.c * workedQ.bil.du * workedQ.bil.dv)}
      {workedExam
        ? `; with the divisions the computed c_u, c_l and c (${fmtShort(workedQ.steps.cu)}, ${fmtShort(workedQ.steps.cl)}, ${fmtShort(workedQ.steps.c)}) ${
            agreesWithKey(workedQ.steps.cu, KEY_PRINTED.cu) &&
            agreesWithKey(workedQ.steps.cl, KEY_PRINTED.cl) &&
            agreesWithKey(workedQ.steps.c, KEY_PRINTED.bilinear)
              ? `agree with the key’s printed ${KEY_PRINTED.cu.value}, ${KEY_PRINTED.cl.value} and ${KEY_PRINTED.bilinear.value}`
              : `differ from the key’s printed ${KEY_PRINTED.cu.value}, ${KEY_PRINTED.cl.value} and ${KEY_PRINTED.bilinear.value}`
          }`
        : ''}
      .
    </>
  );
}
