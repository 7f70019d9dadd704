/**
 * Solid angle and area lights (exam Q6): dω = dA cos θ_l / r² drawn, the rendering equation over
 * solid angle and over area, and three estimators of the light reflected by a Lambertian floor —
 * uniform area (the key's), solid-angle (spherical rectangle) and cosine hemisphere sampling —
 * against the analytic reference (Lambert's formula). All figures come from ./model over the core.
 */
import { useEffect, useMemo, useRef, useState } from 'react';
import type { SceneProps } from '../../app/scene';
import { MathTex, Notice, NumberField, Panel, Plot, Readout, SceneLayout, Select, Slider, Toggle, useSeenOnce, useShortcuts } from '../../ui';
import type { PlotTrace } from '../../ui';
import { useWorkerJob } from '../../workers';
import type { LightStrategy } from '../../core/lights';
import { STRATEGIES, STRATEGY_LABEL, STRATEGY_SHORT, buildModel, convergence, drawSamples, estimateAll, floorJob, patchModel, targetValue, type StrategyEstimate, type TimingPoint } from './model';
import { PRESETS, schema, type AreaLightParams } from './params';
import { Scene3D } from './view/Scene3D';
import { FloorImages } from './view/FloorImages';
import { PatchFigure } from './view/PatchFigure';
import './area-light.css';

type Schema = typeof schema;

const DRAWN = 256;
/** Largest n per strategy estimated on the main thread. */
const SYNC_MAX = 65536;
const COLORS: Record<LightStrategy, string> = { area: '#b34700', 'solid-angle': '#1f5fa8', cosine: '#1d7a3a' };
const makeWorker = () => new Worker(new URL('./floor.worker.ts', import.meta.url), { type: 'module' });

const LEGEND_TOP = { orientation: 'h', x: 0, y: 1.02, yanchor: 'bottom' };

const fmt = (x: number, d = 4) => (Number.isFinite(x) ? Number(x.toPrecision(d)).toString() : '—');

export default function AreaLightScene({ params, setParams, mode }: SceneProps<Schema>) {
  const set = (patch: Partial<AreaLightParams>) => setParams(patch);
  const model = useMemo(() => buildModel(params), [params]);
  const strategy = params.strategy as LightStrategy;
  const n = params.n;
  const seed = params.seed;

  // Up to SYNC_MAX samples per strategy the estimates are computed here (a few ms); beyond, in a
  // worker, so a slider drag never blocks the page. Same seeds and streams: the same numbers.
  const big = n > SYNC_MAX;
  const syncEstimates = useMemo(() => (big ? null : estimateAll(model, n, seed)), [big, model, n, seed]);
  const estTask = useWorkerJob<StrategyEstimate[]>(makeWorker, 'estimates', params, { enabled: big, delayMs: 150 });
  const estimates: StrategyEstimate[] = syncEstimates ?? estTask.result ?? STRATEGIES.map((s) => ({ strategy: s, estimate: NaN, stderr: NaN, n }));
  const pending = big && !estTask.result;
  const chosen = estimates.find((e) => e.strategy === strategy)!;
  const target = targetValue(model);
  const drawn = useMemo(() => drawSamples(model, strategy, DRAWN, seed), [model, strategy, seed]);
  const patch = useMemo(() => patchModel(model, params.pu, params.pv, params.psize, params.ptilt), [model, params.pu, params.pv, params.psize, params.ptilt]);
  const timingKey = JSON.stringify([model.p, model.lc, model.w, model.h, model.tilt, model.L, model.rho, model.occluder ? 1 : 0, seed]);
  // Convergence series (3 × 32768 samples) in the worker: ~0.1 s that a slider drag should not wait for.
  // The convergence and timing runs start when their panels come near the screen (not on load:
  // their results re-render the scene while the first screen should be answering input).
  const convBox = useRef<HTMLDivElement>(null);
  const timingBox = useRef<HTMLDivElement>(null);
  const convSeen = useSeenOnce(convBox);
  const timingSeen = useSeenOnce(timingBox);
  const convArgs = useMemo(() => ({ params, nMax: 1 << 15 }), [params]);
  const convTask = useWorkerJob<ReturnType<typeof convergence>>(makeWorker, 'convergence', convArgs, { key: timingKey, delayMs: 120, enabled: convSeen });
  const conv = convTask.result;

  const job = useMemo(() => floorJob(model, seed), [model, seed]);

  const timing = useWorkerJob<TimingPoint[]>(makeWorker, 'timing', params, { key: timingKey, delayMs: 400, enabled: timingSeen });

  const [playing, setPlaying] = useState(false);
  useShortcuts({
    step: () => set({ seed: (seed + 1) >>> 0 }),
    reset: () => set({ ...PRESETS[0]!.params }),
    playPause: () => setPlaying((p) => !p),
  });
  // "Play" re-draws with a new seed once a second (to watch the estimate jitter within its error bar).
  useEffect(() => {
    if (!playing) return;
    const t = setInterval(() => setParams({ seed: (Date.now() >>> 0) % 4294967295 }), 1000);
    return () => clearInterval(t);
  }, [playing, setParams]);

  const dark = mode.theme === 'dark';
  const vpHeight = mode.present ? 520 : 400;
  const zTarget = Number.isFinite(target) && chosen.stderr > 0 ? (chosen.estimate - target) / chosen.stderr : null;

  const convTraces: PlotTrace[] = useMemo(() => {
    const out: PlotTrace[] = [];
    for (const c of conv ?? []) {
      out.push({ x: Array.from(c.n), y: Array.from(c.absError), type: 'scatter', mode: 'lines', name: STRATEGY_SHORT[c.strategy], legendgroup: c.strategy, line: { color: COLORS[c.strategy], width: 2 } });
      out.push({ x: Array.from(c.n), y: Array.from(c.stderr), type: 'scatter', mode: 'lines', name: `std. error, ${STRATEGY_SHORT[c.strategy]}`, legendgroup: c.strategy, showlegend: false, line: { color: COLORS[c.strategy], dash: 'dot', width: 1.5 } });
    }
    return out;
  }, [conv]);
  const timingTraces: PlotTrace[] = useMemo(() => {
    const pts = timing.result ?? [];
    return STRATEGIES.map((s) => {
      const rows = pts.filter((r) => r.strategy === s && r.rmse > 0 && r.seconds > 0);
      return {
        x: rows.map((r) => r.seconds * 1e3),
        y: rows.map((r) => r.rmse),
        text: rows.map((r) => `N = ${r.n}`),
        type: 'scatter',
        mode: 'lines+markers',
        name: STRATEGY_SHORT[s],
        line: { color: COLORS[s] },
      };
    });
  }, [timing.result]);
  const patchTraces: PlotTrace[] = useMemo(
    () => [
      { x: Array.from(patch.series.side), y: Array.from(patch.series.relError), type: 'scatter', mode: 'lines', name: '|dA cos θ_l / r² − Ω| / Ω', line: { color: '#e4572e' } },
      { x: [patch.side], y: [Math.abs(patch.relError)], type: 'scatter', mode: 'markers', name: 'this patch', marker: { color: '#e4572e', size: 10 } },
    ],
    [patch],
  );

  const vec = (label: string, key: 'p' | 'lc', v: [number, number, number]) => (
    <fieldset className="al-vec">
      <legend>{label}</legend>
      {(['x', 'y', 'z'] as const).map((axis, k) => (
        <NumberField
          key={axis}
          label={axis}
          value={v[k]!}
          step={0.1}
          min={-1e9}
          max={1e9}
          testId={`${key}-${axis}`}
          onChange={(x) => {
            const nv: [number, number, number] = [...v];
            nv[k] = x;
            set({ [key]: nv } as Partial<AreaLightParams>);
          }}
        />
      ))}
    </fieldset>
  );

  const controls = (
    <>
      <Panel title="Presets">
        <div className="al-presets" role="group" aria-label="Presets">
          {PRESETS.map((pr) => (
            <button key={pr.id} type="button" title={pr.what} onClick={() => set({ ...pr.params })} data-testid={`preset-${pr.id}`}>
              {pr.label}
            </button>
          ))}
        </div>
      </Panel>
      <Panel title="Light and floor">
        {vec('Light centre', 'lc', params.lc)}
        <Slider label="Width w" value={params.ls?.[0] ?? 1} min={0} max={10} step={0.05} onChange={(x) => set({ ls: [x, params.ls?.[1] ?? 1] })} />
        <Slider label="Height h" value={params.ls?.[1] ?? 1} min={0} max={10} step={0.05} onChange={(x) => set({ ls: [params.ls?.[0] ?? 1, x] })} />
        <Slider label="Tilt about x" value={params.tilt} min={-180} max={180} step={1} unit="°" onChange={(x) => set({ tilt: x })} />
        <Slider label="Radiance L" value={params.L} min={0} max={10} step={0.1} onChange={(x) => set({ L: x })} />
        <Slider label="Albedo ρ" value={params.rho} min={0} max={1} step={0.01} onChange={(x) => set({ rho: x })} />
        {vec('Shading point p (normal +z)', 'p', params.p)}
        <Toggle label="Occluder between point and light" checked={params.occluder} onChange={(b) => set({ occluder: b })} />
      </Panel>
      <Panel title="Sampling">
        <Select
          label="Strategy"
          value={strategy}
          options={STRATEGIES.map((s) => ({ value: s, label: STRATEGY_LABEL[s] }))}
          onChange={(s) => set({ strategy: s })}
          testId="strategy"
        />
        <Slider label="Samples n" value={n} min={1} max={1000000} step={1} log onChange={(x) => set({ n: Math.round(x) })} />
        <NumberField label="Seed" value={seed} min={0} max={4294967295} step={1} onChange={(x) => set({ seed: Math.round(x) })} />
        <div className="al-row">
          <button type="button" onClick={() => set({ seed: (seed + 1) >>> 0 })}>
            New seed
          </button>
          <button type="button" aria-pressed={playing} onClick={() => setPlaying((p) => !p)}>
            {playing ? '❚❚ Stop reseeding' : '▶ Reseed every second'}
          </button>
        </div>
      </Panel>
      <Panel title="Q6(a) patch">
        <Slider label="Position u on the light" value={params.pu} min={0} max={1} step={0.01} onChange={(x) => set({ pu: x })} />
        <Slider label="Position v on the light" value={params.pv} min={0} max={1} step={0.01} onChange={(x) => set({ pv: x })} />
        <Slider label="Patch side" value={params.psize} min={0.001} max={2} log onChange={(x) => set({ psize: x })} />
        <Slider label="Patch tilt (relative)" value={params.ptilt} min={-89} max={89} step={1} unit="°" onChange={(x) => set({ ptilt: x })} />
      </Panel>
    </>
  );

  const scenePanel = (
    <>
      <Panel title="The scene">
        <Scene3D model={model} strategy={strategy} samples={drawn.points} terms={drawn.terms} patch={patch} height={vpHeight} dark={dark} />
        <p className="al-legend">
          Yellow: the emitting side of the light (its back is dark). Dots: the first {DRAWN} samples of the {STRATEGY_LABEL[strategy]} strategy
          {strategy === 'cosine' ? ' as directions on the unit hemisphere' : ' on the light, and their directions on the unit hemisphere'} — green where the
          sample contributes, red where it is wasted (below the horizon, blocked, or missing the light). Orange: the Q6(a) patch and its projection on the unit
          sphere.
        </p>
      </Panel>
    </>
  );

  const main = (
    <>
      {model.messages.map((m, i) => (
        <Notice key={i} kind={m.kind} testId={`al-message-${i}`}>
          {m.text}
        </Notice>
      ))}
      {mode.present ? scenePanel : null}
      <Panel title="Reflected radiance L_o at p">
        <div className="al-readouts">
          <Readout id="reference" label="reference (Lambert, no occluder)" value={model.reference} digits={7} />
          <Readout id="estimate" label={`estimate, ${STRATEGY_LABEL[strategy]}, n = ${n}`} value={chosen.estimate} digits={7} />
          <Readout id="stderr" label="standard error" value={chosen.stderr} digits={3} />
          <Readout id="solid-angle" label="solid angle Ω of the light" value={model.solidAngle} digits={7} unit="sr" />
          <Readout id="solid-angle-closed" label="Ω, closed form (light parallel to floor)" value={model.solidAngleClosed} digits={7} unit="sr" />
          <Readout id="reference-occluded" label="reference with occluder" value={model.occluder ? model.referenceOccluded : null} digits={7} />
          <Readout id="projected-solid-angle" label="∫ cos θ dω (clipped to the horizon)" value={model.projectedSolidAngle} digits={7} unit="sr" />
        </div>
        <p className="al-verdict" data-testid="al-verdict">
          {pending ? (
            <>
              <progress aria-label="Estimating" /> Estimating with n = {n} samples per strategy in the background…
            </>
          ) : zTarget === null
            ? chosen.stderr === 0 && chosen.estimate === target
              ? 'Every sample gave the same value: the estimate is exact here.'
              : 'No standard error yet (n < 2), or no analytic value to compare with.'
            : `The estimate is ${fmt(Math.abs(zTarget), 2)} standard errors ${zTarget >= 0 ? 'above' : 'below'} the ${model.occluder ? 'occluded ' : ''}reference${Math.abs(zTarget) <= 3 ? ' — within 3σ, as an unbiased estimator should be (about 997 times in 1000).' : ' — outside 3σ (happens about 3 times in 1000 for a correct estimator; try another seed).'}`}
        </p>
        <table className="al-table">
          <caption>All three strategies, n = {n} each, seed {seed}</caption>
          <thead>
            <tr>
              <th scope="col">strategy</th>
              <th scope="col">estimate</th>
              <th scope="col">std. error σ</th>
              <th scope="col">(est. − ref.)/σ</th>
            </tr>
          </thead>
          <tbody>
            {estimates.map((e) => (
              <tr key={e.strategy} className={e.strategy === strategy ? 'al-current' : undefined}>
                <th scope="row" title={STRATEGY_LABEL[e.strategy]}>
                  {STRATEGY_SHORT[e.strategy]}
                </th>
                <td>
                  <Readout id={`estimate-${e.strategy}`} label="" value={e.estimate} digits={5} />
                </td>
                <td>
                  <Readout id={`stderr-${e.strategy}`} label="" value={e.stderr} digits={2} />
                </td>
                <td>{e.stderr > 0 && Number.isFinite(target) ? fmt((e.estimate - target) / e.stderr, 3) : '—'}</td>
              </tr>
            ))}
          </tbody>
        </table>
      </Panel>
      {mode.present ? null : scenePanel}
      <Panel title="Q6(a): why dω = dA cos θ_l / r²">
        <p>
          A small patch of area dA at distance r, turned by θ_l away from the direction to p, shows p only its foreshortened area dA cos θ_l; at distance r
          that covers dA cos θ_l / r² of the unit sphere. The exact solid angle of the orange patch (Van Oosterom–Strackee) and the formula agree better
          and better as the patch shrinks — the error falls like the square of its size.
        </p>
        <PatchFigure patch={patch} />
        <MathTex display tex={String.raw`d\omega = \frac{dA^{\perp}}{r^2} = \frac{dA\,\cos\theta_l}{r^2}`} />
        <div className="al-readouts">
          <Readout id="patch-exact" label="exact Ω of the patch" value={patch.exact} digits={8} unit="sr" />
          <Readout id="patch-approx" label="dA cos θ_l / r²" value={patch.approx} digits={8} unit="sr" />
          <Readout id="patch-rel-error" label="relative difference" value={patch.relError} digits={3} />
          <Readout id="patch-r" label="r" value={patch.r} digits={5} />
          <Readout id="patch-cos" label="cos θ_l" value={patch.cosThetaL} digits={5} />
        </div>
        <Plot
          ariaLabel="Relative difference between dA cos θ_l / r² and the exact solid angle of the patch, against the patch side, log-log: a line of slope 2."
          data={patchTraces}
          height={240}
          layout={{ xaxis: { type: 'log', title: { text: 'patch side' } }, yaxis: { type: 'log', title: { text: 'relative difference' } }, showlegend: false }}
        />
      </Panel>
      <Panel title="Q6(b): the rendering equation over solid angle and over area">
        <MathTex display tex={String.raw`L_o(x,\omega_o) = \int_{\Omega} f(x,\omega_o,\omega_i)\,L_i(x,\omega_i)\cos\theta\,d\omega_i`} />
        <MathTex
          display
          tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_e(y)\,\colorbox{#d7ecd9}{$\color{#1c1d21}V(x,y)$}\,\cos\theta\,\colorbox{#fde2c8}{$\color{#1c1d21}\dfrac{\cos\theta_l}{r^2}$}\,dA_y`}
        />
        <p>
          The <span className="al-hl-j">Jacobian cos θ_l / r²</span> is Q6(a)’s dω/dA; the <span className="al-hl-v">visibility V</span> appears because
          over the light’s area nothing tells us whether the segment from x to y is blocked (over directions, L_i already includes it). With p_A = 1/|A|,
          the key’s estimator (Q6(c)) is
        </p>
        <MathTex display tex={String.raw`\langle L_o\rangle = \frac{|A|}{N}\sum_{i=1}^{N} f\,L\,V\,\cos\theta_i\,\frac{\cos\theta_{l,i}}{r_i^2}`} />
        <p>
          Solid-angle sampling draws ω uniformly over the light’s spherical rectangle (pdf 1/Ω), so each term is Ω f L V cos θ; cosine sampling draws ω
          with pdf cos θ / π, so each term is ρ L V when the ray hits the light and 0 when it misses. Here f = ρ/π, and the reference is
          (ρ/π) L ∫ cos θ dω by Lambert’s formula.
        </p>
      </Panel>
      <Panel title="Convergence">
        <div ref={convBox} />
        <Plot
          ariaLabel="Absolute error and standard error of the three estimators against the number of samples, log-log."
          data={convTraces}
          height={mode.present ? 380 : 300}
          layout={{ xaxis: { type: 'log', title: { text: 'N (samples)' } }, yaxis: { type: 'log', title: { text: 'error' } }, legend: LEGEND_TOP, margin: { l: 56, r: 16, t: 40, b: 44 } }}
        />
        <p className="al-note">Solid: |estimate − reference|. Dotted: the standard error s/√N the estimator reports. Both fall like N^−½; the strategies differ by a constant.</p>
      </Panel>
      <Panel title="Run time against error">
        <div ref={timingBox} className="al-progress-slot">
          {timing.running ? <progress max={1} value={timing.progress} aria-label="Timing progress" /> : null}
        </div>
        {timing.error ? <Notice kind="warn">Timing failed: {timing.error}</Notice> : null}
        <Plot
          ariaLabel="RMSE over independent runs against the run time of one estimate, for the three strategies, log-log."
          data={timingTraces}
          height={mode.present ? 360 : 280}
          layout={{ xaxis: { type: 'log', title: { text: 'time per estimate (ms)' } }, yaxis: { type: 'log', title: { text: 'RMSE' } }, legend: LEGEND_TOP, margin: { l: 56, r: 16, t: 40, b: 44 } }}
        />
        <p className="al-note">Each point: N = 16 … 4096 samples, RMSE over 24 independent runs, run time measured in a worker on this machine (best of three; noisy when the machine is busy). Lower-left wins.</p>
      </Panel>
      <Panel title="The floor, rendered with each strategy">
        <FloorImages job={job} />
        <p className="al-note">
          {job.size} × {job.size} pixels of floor, {fmt(2 * job.half, 3)} units across, all at the same samples per pixel. The light’s footprint is brightest;
          the grain is each strategy’s variance.
        </p>
      </Panel>
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}
