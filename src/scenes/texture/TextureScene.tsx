/**
 * Texture lookup (exam Q3): nearest and bilinear lookup on a texel grid, the conventions that change
 * the answer, and the spherical (u, v) mapping. All figures come from ./model (pure, over the core).
 */
import { useCallback, useDeferredValue, useMemo, useState } from 'react';
import type { SceneProps } from '../../app/scene';
import { EXAM_GRID_TEXT, gridRange, parseGrid, texel } from '../../core/texture';
import { MathTex, NumberField, Notice, Panel, Readout, SceneLayout, Select, Slider, Toggle, useShortcuts } from '../../ui';
import {
  KEY_PRINTED,
  addressingNotes,
  drawnLookup,
  agreesWithKey,
  gridTextIfFits,
  isExamQuery,
  isExamSphere,
  lookupAt,
  lookupOptions,
  readouts,
  resolveGrid,
  sphereModel,
  withCell,
} from './model';
import { GRID_TEXT_MAX, type Preset, type TextureSchema } from './params';
import { GridView, fmtShort } from './view/GridView';
import { QueryWorked, bilinearTex, texNum } from './view/WorkedSteps';
import { Reconstruction } from './view/Reconstruction';
import { SphereView } from './view/SphereView';
import { colorCss } from './colormap';
import './texture.css';

type PresetChoice = 'exam' | 'custom' | Exclude<Preset, 'grid'>;

export default function TextureScene({ params, setParams, mode }: SceneProps<TextureSchema>) {
  const [drag, setDrag] = useState<{ u: number; v: number } | null>(null);
  const [editing, setEditing] = useState(false);
  const [selected, setSelected] = useState<{ i: number; j: number } | null>(null);
  const [editError, setEditError] = useState<string | null>(null);

  const u = drag ? drag.u : params.u;
  const v = drag ? drag.v : params.v;

  const src = useMemo(
    () => resolveGrid({ grid: params.grid, preset: params.preset, size: params.size, seed: params.seed }),
    [params.grid, params.preset, params.size, params.seed],
  );
  const grid = src.grid;
  const opts = useMemo(() => lookupOptions({ align: params.align, vflip: params.vflip, wrap: params.wrap }), [params.align, params.vflip, params.wrap]);
  const range = useMemo(() => gridRange(grid), [grid]);
  const q = useMemo(() => lookupAt(grid, u, v, opts), [grid, u, v, opts]);
  const dq = useMemo(() => drawnLookup(grid, u, v, opts), [grid, u, v, opts]);
  const sphere = useMemo(
    () => sphereModel(grid, { x: params.x, y: params.y, z: params.z, normalize: params.normalize }, opts),
    [grid, params.x, params.y, params.z, params.normalize, opts],
  );
  const ro = readouts(q, sphere);
  const notes = addressingNotes(u, v, opts, q);
  const examQ = isExamQuery(src, opts, u, v);
  const examS = isExamSphere(src, opts, sphere);
  // While dragging, only the marker, the stencil and the readouts follow the pointer; the worked
  // panel (KaTeX) catches up on release.
  const committedQ = useMemo(() => lookupAt(grid, params.u, params.v, opts), [grid, params.u, params.v, opts]);
  const workedQ = useDeferredValue(committedQ);

  const dir = useMemo<[number, number, number] | null>(() => {
    if (!sphere.ok) return null;
    return [params.x / sphere.r, params.y / sphere.r, params.z / sphere.r];
  }, [sphere, params.x, params.y, params.z]);

  const onMove = useCallback(
    (ut: number, vt: number, final: boolean) => {
      const nv = opts.vflip ? Math.round((1 - vt) * 10000) / 10000 : vt;
      if (final) {
        setDrag(null);
        setParams({ u: ut, v: nv });
      } else setDrag({ u: ut, v: nv });
    },
    [opts.vflip, setParams],
  );
  const onPick = useCallback(
    (p: [number, number, number]) => {
      const r4 = (x: number) => Math.round(x * 10000) / 10000 + 0;
      setParams({ x: r4(p[0]), y: r4(p[1]), z: r4(p[2]) });
    },
    [setParams],
  );

  useShortcuts({ reset: () => setParams({ u: 0.4, v: 0.24 }) });

  const presetChoice: PresetChoice = params.preset === 'grid' ? (src.isExam ? 'exam' : 'custom') : (params.preset as PresetChoice);
  const presetOptions: { value: PresetChoice; label: string }[] = [
    { value: 'exam', label: 'The exam’s 5 × 5 grid' },
    { value: 'checker', label: 'Checkerboard' },
    { value: 'gradient', label: 'Gradient' },
    { value: 'random', label: 'Random (seeded)' },
  ];
  if (presetChoice === 'custom') presetOptions.push({ value: 'custom', label: 'Custom (from the grid text)' });

  const setCell = (x: number) => {
    if (!selected) return;
    const next = withCell(grid, selected.i, selected.j, x);
    const text = gridTextIfFits(next);
    if (text === null) {
      setEditError(`This grid is too large to store in a link (over ${GRID_TEXT_MAX} characters), so its cells cannot be edited; pick a smaller size.`);
      return;
    }
    setEditError(null);
    setParams({ preset: 'grid', grid: text });
  };

  const controls = (
    <>
      <Panel title="Query point (u, v)">
        <Slider label="u" value={u} min={-2} max={3} step={0.001} onChange={(x) => setParams({ u: x })} testId="u-slider" />
        <Slider label="v" value={v} min={-2} max={3} step={0.001} onChange={(x) => setParams({ v: x })} testId="v-slider" />
        <p className="tx-small">Or click / drag on the grid (arrow keys move the point when the grid has focus).</p>
      </Panel>
      <Panel title="Conventions">
        <Select
          label="Where the values sit"
          value={opts.align}
          options={[
            { value: 'corner', label: 'Corner nodes i/(N − 1) (the exam’s)' },
            { value: 'center', label: 'Texel centres (i + ½)/N (GPU)' },
          ]}
          onChange={(x) => setParams({ align: x })}
          testId="align-select"
        />
        <Toggle label="Flip v: v′ = 1 − v (the key accepts it)" checked={params.vflip} onChange={(x) => setParams({ vflip: x })} testId="vflip-toggle" />
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
      <Panel title="Texture">
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
            <NumberField label="Size N (N × N, 2 to 64)" value={params.size} min={2} max={64} step={1} onChange={(x) => setParams({ size: Math.round(x) })} testId="size-field" />
            {params.preset === 'random' ? (
              <button type="button" onClick={() => setParams({ seed: (params.seed + 1) % 4294967296 })}>
                New random values (seed {params.seed + 1})
              </button>
            ) : null}
          </>
        ) : null}
        <Toggle
          label="Edit cells (click a node)"
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
          <p className="tx-small">Click a node on the grid to edit its value.</p>
        ) : null}
        {editError ? <Notice kind="warn">{editError}</Notice> : null}
        <GridText key={params.grid + params.preset} text={params.preset === 'grid' ? params.grid : (gridTextIfFits(grid) ?? '')} onApply={(t) => setParams({ preset: 'grid', grid: t })} />
      </Panel>
      <Panel title="Sphere point (x, y, z)">
        <NumberField label="x" value={params.x} min={-1000} max={1000} onChange={(x) => setParams({ x })} testId="x-field" />
        <NumberField label="y" value={params.y} min={-1000} max={1000} onChange={(y) => setParams({ y })} testId="y-field" />
        <NumberField label="z" value={params.z} min={-1000} max={1000} onChange={(z) => setParams({ z })} testId="z-field" />
        <Toggle label="Normalize by (2π, π)" checked={params.normalize} onChange={(x) => setParams({ normalize: x })} testId="normalize-toggle" />
        <button type="button" onClick={() => setParams({ x: 1, y: 1, z: Math.SQRT2 })}>
          The exam’s point (y/x = 1, z/r = √2/2)
        </button>
      </Panel>
    </>
  );

  const main = (
    <>
      <Panel title="The texel grid">
        {src.error ? (
          <Notice kind="warn" testId="grid-error">
            <strong>grid</strong>: {src.error} Using the exam’s 5 × 5 grid instead.
          </Notice>
        ) : null}
        <GridView grid={grid} opts={opts} range={range} q={dq} onMove={onMove} editing={editing} selected={selected} onSelect={(i, j) => setSelected({ i, j })} present={mode.present} />
        <Legend range={range} />
        <div className="readouts tx-readouts">
          <Readout id="nearest" label="Nearest (Q3a)" value={ro.nearest} note={examQ ? keyNote(ro.nearest, KEY_PRINTED.nearest) : undefined} />
          <Readout id="bilinear" label="Bilinear (Q3b)" value={ro.bilinear} note={examQ ? keyNote(ro.bilinear, KEY_PRINTED.bilinear) : undefined} />
          <Readout id="query-uv" label="(u, v) as used" value={`(${fmtShort(q.bil.u)}, ${fmtShort(q.bil.v)})`} />
        </div>
        {notes.length ? (
          <Notice kind="info" testId="addressing-note">
            {notes.map((n) => (
              <span key={n} className="tx-note-line">
                {n}
              </span>
            ))}
          </Notice>
        ) : null}
        <p className="tx-small">
          <span className="tx-key nearest" /> nearest node · <span className="tx-key cell" /> the bilinear cell: each of its four nodes is weighted by the area of the
          sub-rectangle opposite to it (same colour).
        </p>
      </Panel>
      <Panel title="Worked steps (the key’s form, live numbers)">
        <QueryWorked grid={grid} opts={opts} q={workedQ} isExamQuery={isExamQuery(src, opts, params.u, params.v)} />
      </Panel>
      <Panel title="The whole texture, reconstructed">
        <Reconstruction grid={grid} opts={opts} range={range} qu={dq.bil.u} qv={dq.bil.v} />
        <p className="tx-small">
          Both images show [0, 1]² {opts.vflip ? '(in the flipped frame v′)' : ''} magnified; the cross is the query. Nearest copies the closest value, so
          it is blocky; bilinear blends the four around the point, so it is continuous but shows a crease along every node line.
        </p>
      </Panel>
    </>
  );

  const aside = (
    <Panel title="Spherical mapping (Q3c)">
      <SphereView grid={grid} opts={opts} range={range} normalize={params.normalize} dir={dir} onPick={onPick} height={mode.present ? 420 : 320} />
      {!sphere.ok ? (
        <Notice kind="warn" testId="sphere-error">
          <strong>x, y, z</strong>: {sphere.error} The sphere readouts show “none” until you pick another point.
        </Notice>
      ) : null}
      <div className="readouts">
        <Readout id="sphere-u" label={params.normalize ? 'u = φ / 2π' : 'u = φ (radians)'} value={ro.sphereU} />
        <Readout id="sphere-v" label={params.normalize ? 'v = θ / π' : 'v = θ (radians)'} value={ro.sphereV} />
        <Readout
          id="sphere-bilinear"
          label={params.normalize ? 'Bilinear at (u, v)' : 'Bilinear at (φ, θ), not normalized'}
          value={ro.sphereBilinear}
          note={examS && ro.sphereBilinear !== null ? keyNote(ro.sphereBilinear, params.normalize ? KEY_PRINTED.sphere : KEY_PRINTED.sphereRaw) : undefined}
        />
      </div>
      {sphere.ok ? (
        <>
          <MathTex
            display
            tex={`\\begin{gathered}r = ${texNum(sphere.r)} \\\\ \\varphi = \\operatorname{atan2}(y, x) = ${texNum(sphere.phi)}${sphere.pole ? '\\ (\\text{pole: defined as } 0)' : ''} \\\\ \\theta = \\arccos(z/r) = ${texNum(sphere.theta)} \\\\ (u, v) = \\left(\\frac{\\varphi}{2\\pi}, \\frac{\\theta}{\\pi}\\right) = (${texNum(sphere.normalized.u)},\\ ${texNum(sphere.normalized.v)})\\end{gathered}`}
          />
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
          {examS ? <ExamSphereNote normalized={sphere.normalized.bil.value} raw={sphere.raw.bil.value} /> : null}
          <details className="tx-details">
            <summary>Bilinear steps for the sphere point ({params.normalize ? 'normalized' : 'not normalized'})</summary>
            <MathTex display tex={`\\begin{aligned}${bilinearTex(sphere.chosen, opts)}\\end{aligned}`} />
          </details>
        </>
      ) : null}
      <p className="tx-small">
        <strong>Seam.</strong> atan2 returns angles in (−π, π]; adding 2π to the negative ones puts φ in [0, 2π), so u runs from 0 at +x all the way
        round to just below 1. The meridian φ = 0 (red) is where u jumps from 1 back to 0: u = 1 is never produced, so the seam belongs to u = 0. Unless the
        texture’s left and right columns match (or the lookup repeats with texel centres), the picture jumps there.
      </p>
      <p className="tx-small">
        <strong>Poles.</strong> On the z axis (x = y = 0) every φ names the same point, so u is undefined; we define u = 0. θ is computed as atan2(√(x² + y²),
        z), which equals arccos(z/r) but keeps full precision near the poles.
      </p>
    </Panel>
  );

  return <SceneLayout controls={controls} main={main} aside={aside} />;
}

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
    <Notice kind="info" testId="key-note">
      <span className="tx-note-text">
      On the exam’s grid the texture is the linear function 21 + 4u − 20v, which bilinear filtering reproduces exactly. Normalized, (1/8, 1/4) gives{' '}
      {texPlain(normalized)} ({agreesWithKey(normalized, KEY_PRINTED.sphere) ? 'as the key prints' : `the key prints ${KEY_PRINTED.sphere.value}`}). Not
      normalized, (π/4, π/4) ≈ (0.785, 0.785) is still inside [0, 1], so no addressing is involved, and the value is 21 − 4π = {texPlain(closed)}; this
      lookup gives {texPlain(raw)}.{' '}
      {agreesWithKey(raw, KEY_PRINTED.sphereRaw)
        ? `The key’s ${KEY_PRINTED.sphereRaw.value} agrees.`
        : `The key prints ${KEY_PRINTED.sphereRaw.value}, which differs in the second decimal (the exact value rounds to ${raw.toFixed(2)}).`}
      </span>
    </Notice>
  );
}

function Legend({ range }: { range: { min: number; max: number } }) {
  const stops = Array.from({ length: 11 }, (_, k) => colorCss(k / 10)).join(', ');
  return (
    <div className="tx-legend" aria-hidden="true">
      <span>{fmtShort(range.min)}</span>
      <span className="tx-legend-bar" style={{ background: `linear-gradient(to right, ${stops})` }} />
      <span>{fmtShort(range.max)}</span>
    </div>
  );
}

/** The grid as text (rows top to bottom); applies only text that parses, else says why. */
function GridText({ text, onApply }: { text: string; onApply: (t: string) => void }) {
  const [draft, setDraft] = useState(text);
  const [error, setError] = useState<string | null>(null);
  const apply = () => {
    const t = draft.trim();
    const r = parseGrid(t);
    if (!r.ok) {
      setError(r.error);
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
