/**
 * #/ray-sphere — exam Q5: the quadratic of a ray and a sphere, its discriminant, every case, and
 * what floating point does to the textbook form (Ray Tracing Gems ch. 7).
 */
import { useCallback, useDeferredValue, useEffect, useMemo, useRef, useState } from 'react';
import type { SceneProps } from '../../app/scene';
import { MathTex, Notice, NumberField, Panel, Plot, Readout, SceneLayout, Select, useShortcuts, type PlotTrace } from '../../ui';
import type { RaySphereHit } from '../../core/geometry';
import { CASE_PRESETS, PRECISION_PRESETS, schema, type Preset, type RaySphereParams } from './params';
import { CASE_TEXT, computeModel, gCurve, type RaySphereModel, type V3 } from './model';
import { CrossSection } from './view/CrossSection';
import { View3D } from './view/View3D';
import { DistantImages, ErrorVsDistance, PrecisionTable } from './view/Precision';
import './ray-sphere.css';

const CASE_NAME: Record<string, string> = {
  miss: 'Miss',
  tangent: 'Tangent',
  'two-hits': 'Two hits',
  inside: 'Origin inside',
  behind: 'Sphere behind',
};

export default function RaySphereScene({ params, setParams, mode }: SceneProps<typeof schema>) {
  // Drags fire pointer events faster than frames: coalesce parameter updates to one per frame.
  const pending = useRef<Partial<RaySphereParams> | null>(null);
  const raf = useRef(0);
  const setSoon = useCallback(
    (patch: Partial<RaySphereParams>) => {
      pending.current = { ...pending.current, ...patch };
      if (raf.current) return;
      raf.current = requestAnimationFrame(() => {
        raf.current = 0;
        const p = pending.current;
        pending.current = null;
        if (p) setParams(p);
      });
    },
    [setParams],
  );
  useEffect(() => () => cancelAnimationFrame(raf.current), []);

  const model = useMemo(() => computeModel(params), [params]);
  // Heavy panels (KaTeX, Plotly, the precision table) follow a throttled, deferred copy: the
  // cross-section, the 3D view and the readouts update every frame while dragging; the plots and
  // the derivation at most every 150 ms (and always with the final values).
  const slow = useDeferredValue(useThrottled(model, 150));
  useShortcuts({ reset: () => setParams({ ...CASE_PRESETS[0]!.params, method: 'stable' }) });

  const res = model.chosen;
  const { o, d, c, r, problems } = model.input;
  const hereErrors = useMemo(
    () => ({ naive: slow.rows.find((x) => x.method === 'naive')?.errDisc ?? null, stable: slow.rows.find((x) => x.method === 'stable')?.errDisc ?? null }),
    [slow],
  );
  const activePreset = [...CASE_PRESETS, ...PRECISION_PRESETS].find((p) => samePreset(p, params));

  const controls = (
    <>
      <Panel title="Presets: the five cases">
        <div className="rs-presets" role="group" aria-label="Case presets">
          {CASE_PRESETS.map((p) => (
            <button key={p.id} type="button" data-testid={`preset-${p.id}`} aria-pressed={activePreset?.id === p.id} onClick={() => setParams(p.params)}>
              {p.label}
            </button>
          ))}
        </div>
      </Panel>
      <Panel title="Presets that break the textbook form">
        <div className="rs-presets" role="group" aria-label="Precision presets">
          {PRECISION_PRESETS.map((p) => (
            <button key={p.id} type="button" data-testid={`preset-${p.id}`} aria-pressed={activePreset?.id === p.id} onClick={() => setParams(p.params)}>
              {p.label}
            </button>
          ))}
        </div>
        {activePreset ? <p className="rs-small">{activePreset.what}</p> : null}
      </Panel>
      <Panel title="Ray and sphere">
        <Select
          label="Method (for the readouts)"
          value={params.method as 'stable' | 'naive'}
          options={[
            { value: 'stable', label: 'robust (Ray Tracing Gems ch. 7)' },
            { value: 'naive', label: 'textbook (−b ± √Δ) / 2a' },
          ]}
          onChange={(m) => setParams({ method: m })}
          testId="method"
        />
        <VecField label="Origin o" name="o" value={params.o} onChange={(v) => setParams({ o: v })} />
        <VecField label="Direction d" name="d" value={params.d} onChange={(v) => setParams({ d: v })} />
        <VecField label="Centre c" name="c" value={params.c} onChange={(v) => setParams({ c: v })} />
        <NumberField label="Radius r" value={params.r} onChange={(x) => setParams({ r: x })} min={-1e12} max={1e12} step={0.1} testId="input-r" />
        <p className="rs-small">d need not be unit length: t is then measured in units of |d|.</p>
      </Panel>
    </>
  );

  const main = (
    <>
      {problems.length ? (
        <Notice kind="error" testId="input-problems">
          <p>
            <strong>These inputs do not describe a ray and a sphere</strong>, so the scene uses safe values:
          </p>
          <ul>
            {problems.map((p) => (
              <li key={p}>{p}</li>
            ))}
          </ul>
        </Notice>
      ) : null}
      {model.fatal ? (
        <Notice kind="error" testId="input-fatal">
          {model.fatal} Try smaller numbers, or pick a preset.
        </Notice>
      ) : null}
      <Panel title="Result" className="rs-result">
        <CaseBanner res={res} />
        <div className="readouts">
          <Readout id="a" label="a = d·d" value={res?.a ?? null} digits={10} />
          <Readout id="b" label="b = 2 d·(o − c)" value={res?.b ?? null} digits={10} />
          <Readout id="c" label="c = |o − c|² − r²" value={res?.c ?? null} digits={10} />
          <Readout id="discriminant" label={`Δ = b² − 4ac (${params.method === 'naive' ? 'textbook' : 'robust'})`} value={res?.discriminant ?? null} digits={10} />
          <Readout id="t0" label="t₀" value={res?.t0 ?? null} digits={10} />
          <Readout id="t1" label="t₁" value={res?.t1 ?? null} digits={10} />
          <Readout id="t-hit" label="t-hit (nearest t ≥ 0)" value={res?.tHit ?? null} digits={10} />
          <Readout id="case" label="case" value={res?.case ?? null} />
        </div>
        {res && model.reference && res.case !== model.reference.case ? (
          <Notice kind="warn" testId="method-wrong">
            The {params.method === 'naive' ? 'textbook' : 'robust'} form says <strong>{res.case}</strong>, but the exact answer for these inputs (double-double
            reference) is <strong>{model.reference.case}</strong>: rounding has changed the case. See the precision table below.
          </Notice>
        ) : null}
        {res?.nearTangent && res.case !== 'tangent' ? (
          <p className="rs-small rs-near">
            |Δ| is within this method’s rounding error of 0: the ray is tangent to within double precision, and whether it hits is decided by the last bits.
          </p>
        ) : null}
      </Panel>
      <Panel title="Cross-section through the ray and the centre">
        <CrossSection o={o} d={d} c={c} r={r} res={res} distanceRatio={model.distanceRatio} onChange={(patch) => setSoon(patch)} />
      </Panel>
      <Panel title="3D view">
        <View3D o={o} d={d} c={c} r={r} res={res} distanceRatio={model.distanceRatio} height={mode.present ? 420 : 320} dark={mode.theme === 'dark'} />
      </Panel>
      <Panel title="g(t) = a t² + b t + c and its roots">
        <GPlot model={slow} />
      </Panel>
      <Panel title="Derivation">
        <Derivation model={slow} />
      </Panel>
      <Panel title="Precision: textbook vs robust, against a double-double reference">
        <PrecisionTable model={slow} />
        <PrecisionExplainer />
      </Panel>
    </>
  );

  const aside = (
    <>
      <Panel title="A distant sphere, one ray per pixel">
        <DistantImages />
      </Panel>
      <Panel title="Error against distance">
        <ErrorVsDistance current={Number(slow.distanceRatio.toPrecision(3))} here={hereErrors} />
        <p className="rs-small">
          Median over 12 rays per distance, aimed 0.1 r … 0.95 r off the centre; the crosses are the current ray’s Δ errors. The textbook Δ loses digits like u·(D/r)² (u = 2⁻⁵³): by D ≈ 10⁸ r
          nothing is left. The robust Δ grows only like u·(D/r), and its roots stay accurate to the last bits.
        </p>
      </Panel>
    </>
  );

  return <SceneLayout controls={controls} main={main} aside={aside} />;
}

/** `value`, but changing at most once per `ms` (leading and trailing edges). */
function useThrottled<T>(value: T, ms: number): T {
  const [out, setOut] = useState(value);
  const last = useRef(0);
  useEffect(() => {
    const now = performance.now();
    const wait = last.current + ms - now;
    if (wait <= 0) {
      last.current = now;
      setOut(value);
      return;
    }
    const id = setTimeout(() => {
      last.current = performance.now();
      setOut(value);
    }, wait);
    return () => clearTimeout(id);
  }, [value, ms]);
  return out;
}

function samePreset(p: Preset, params: RaySphereParams): boolean {
  const eq = (x: readonly number[] | undefined, y: readonly number[]) => !x || x.every((v, i) => v === y[i]);
  return eq(p.params.o, params.o) && eq(p.params.d, params.d) && eq(p.params.c, params.c) && (p.params.r === undefined || p.params.r === params.r);
}

function VecField({ label, name, value, onChange }: { label: string; name: string; value: readonly number[]; onChange: (v: V3) => void }) {
  return (
    <fieldset className="rs-vec">
      <legend>{label}</legend>
      {(['x', 'y', 'z'] as const).map((axis, i) => (
        <NumberField
          key={axis}
          label={axis}
          value={value[i]!}
          min={-1e12}
          max={1e12}
          step={0.1}
          testId={`input-${name}-${axis}`}
          onChange={(x) => {
            const v = [value[0]!, value[1]!, value[2]!] as V3;
            v[i] = x;
            onChange(v);
          }}
        />
      ))}
    </fieldset>
  );
}

function CaseBanner({ res }: { res: RaySphereHit | null }) {
  if (!res) return null;
  return (
    <div className={`rs-case case-${res.case}`} data-testid="case-banner">
      <strong>{CASE_NAME[res.case]}</strong>
      <span>{CASE_TEXT[res.case]}</span>
    </div>
  );
}

/** A number for TeX: 6 significant digits, e-notation as × 10^n. */
function tx(x: number | null, digits = 6): string {
  if (x === null || !Number.isFinite(x)) return '\\text{none}';
  if (x === 0) return '0';
  const ax = Math.abs(x);
  if (ax >= 1e-3 && ax < 1e7) return String(Number(x.toPrecision(digits)));
  const [m, e] = x.toExponential(digits - 1).split('e');
  return `${Number(m)} \\times 10^{${Number(e)}}`;
}

function Derivation({ model }: { model: RaySphereModel }) {
  const res = model.chosen;
  if (!res) return <p>No derivation: the inputs overflow.</p>;
  const { o, d, c, r } = model.input;
  const v = (p: readonly number[]) => `(${p.map((x) => tx(x, 4)).join(', ')})`;
  const roots =
    res.t0 === null
      ? `\\Delta < 0 \\;\\Rightarrow\\; \\text{no real root: miss}`
      : `t_{0,1} = \\frac{-b \\mp \\sqrt{\\Delta}}{2a} = ${tx(res.t0, 8)},\\; ${tx(res.t1, 8)}`;
  const hit = res.tHit === null ? `\\text{no root } t \\ge 0 \\;\\Rightarrow\\; \\text{no hit}` : `t_{\\text{hit}} = \\min\\{t_i \\ge 0\\} = ${tx(res.tHit, 8)}`;
  return (
    <div className="rs-derivation">
      <p>A point of the ray is p(t) = o + t d; it is on the sphere when its distance to c is r:</p>
      <MathTex display tex={`\\lVert \\mathbf o + t\\,\\mathbf d - \\mathbf c \\rVert^2 = r^2`} />
      <p>Expand with f = o − c (a dot product with itself is a squared length):</p>
      <MathTex display tex={`(\\mathbf d\\cdot\\mathbf d)\\,t^2 + 2\\,(\\mathbf d\\cdot\\mathbf f)\\,t + (\\mathbf f\\cdot\\mathbf f - r^2) = 0`} />
      <MathTex display tex={`a t^2 + b t + c = 0`} />
      <MathTex display tex={`a = \\mathbf d\\cdot\\mathbf d,\\quad b = 2\\,\\mathbf d\\cdot\\mathbf f,\\quad c = \\mathbf f\\cdot\\mathbf f - r^2`} />
      <p>
        With o = {v(o)}, d = {v(d)}, c = {v(c)}, r = {tx(r, 4)}:
      </p>
      <MathTex display tex={`a = ${tx(res.a)},\\quad b = ${tx(res.b)},\\quad c = ${tx(res.c)}`} />
      <MathTex display tex={`\\Delta = b^2 - 4ac = ${tx(res.discriminant)}`} />
      <MathTex display tex={roots} />
      <MathTex display tex={hit} />
      <p>
        Two conditions make a hit: <strong>Δ ≥ 0</strong> (the line meets the sphere) and <strong>a root t ≥ 0</strong> (the meeting point is in front of the origin). The hit is the
        smallest such root.
      </p>
      <p>The robust form (Ray Tracing Gems, ch. 7) computes the same Δ without subtracting two huge numbers, and picks the root formula that never cancels:</p>
      <MathTex display tex={`\\Delta = 4a\\left(r^2 - \\Bigl\\lVert \\mathbf f - \\tfrac{\\mathbf f\\cdot\\mathbf d}{a}\\,\\mathbf d \\Bigr\\rVert^2\\right)`} />
      <MathTex display tex={`q = -\\left(\\tfrac b2 + \\operatorname{sign}(b)\\,\\tfrac{\\sqrt{\\Delta}}{2}\\right),\\qquad t = \\frac{c}{q},\\; \\frac{q}{a}`} />
    </div>
  );
}

function PrecisionExplainer() {
  return (
    <div className="rs-small">
      <p>
        The reference solves the same quadratic with the inputs taken as exact doubles, in double-double arithmetic (about 106 bits: Dekker’s TwoProduct and Knuth’s TwoSum),
        using Δ/4 = a r² − |d × f|² so that only the genuine cancellation is left. It is checked against 400-digit mathjs BigNumber arithmetic in the tests.
      </p>
      <p>
        Why the textbook form fails: when the sphere is far (|f| ≫ r), b² and 4ac are both about 4a|f|², and their difference, about 4a r², is what is left after
        cancelling them. Each carries a rounding error of about u·4a|f|² (u = 2⁻⁵³), so Δ’s relative error is about u·(|f|/r)²: a millionth at |f| ≈ 10⁵ r, everything at
        |f| ≈ 10⁸ r. The robust form first finds the point of the line closest to the centre, f − (f·d / a) d, whose length is comparable to r, so
        nothing large is subtracted.
      </p>
    </div>
  );
}

function GPlot({ model }: { model: RaySphereModel }) {
  const res = model.chosen;
  const { data, layout } = useMemo(() => {
    if (!res) return { data: [] as PlotTrace[], layout: {} };
    const g = gCurve(res);
    // When t is huge compared with the window, plot t − t_v so the axis stays readable.
    const tv = -res.b / (2 * res.a);
    const shift = Math.abs(tv) > 1e4 * (g.tMax - g.tMin) ? tv : 0;
    const xs = g.t.map((t) => t - shift);
    const roots = res.t0 === null ? [] : res.t0 === res.t1 ? [res.t0] : [res.t0, res.t1!];
    const traces: PlotTrace[] = [
      { x: xs, y: g.g, mode: 'lines', name: 'g(t)', line: { color: '#1f5fa8', width: 2 }, hovertemplate: 't=%{x}<br>g=%{y}<extra></extra>' },
      {
        x: roots.map((t) => t - shift),
        y: roots.map(() => 0),
        mode: 'markers+text',
        name: 'roots',
        text: roots.map((t) => (t === res.tHit ? 'hit' : t < 0 ? 't < 0' : '')),
        textposition: 'top center',
        marker: { size: 11, color: roots.map((t) => (t === res.tHit ? '#e8590c' : t < 0 ? '#888' : '#1f5fa8')), line: { width: 1, color: '#222' } },
      },
    ];
    const shapes: Record<string, unknown>[] = [{ type: 'line', xref: 'x', yref: 'paper', x0: g.tMin - shift, x1: g.tMax - shift, y0: 0, y1: 0, line: { width: 0 } }];
    if (shift === 0 && g.tMin < 0) {
      shapes.push({ type: 'rect', xref: 'x', yref: 'paper', x0: g.tMin, x1: 0, y0: 0, y1: 1, fillcolor: 'rgba(136,136,136,0.15)', line: { width: 0 } });
      shapes.push({ type: 'line', xref: 'x', yref: 'paper', x0: 0, x1: 0, y0: 0, y1: 1, line: { color: '#888', width: 1 } });
    }
    return {
      data: traces,
      layout: {
        showlegend: false,
        xaxis: { title: { text: shift ? `t − ${shift.toPrecision(12)}` : 't (grey: behind the origin, t < 0)' }, zeroline: false },
        yaxis: { title: { text: 'g(t)' }, zeroline: true, zerolinewidth: 2 },
        shapes,
        margin: { l: 56, r: 16, t: 10, b: 50 },
      },
    };
  }, [res]);
  if (!res) return null;
  return <Plot data={data} layout={layout} height={260} ariaLabel="The quadratic g(t) with its real roots marked on the t axis" testId="g-plot" />;
}
