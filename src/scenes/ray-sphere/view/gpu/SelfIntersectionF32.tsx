/**
 * Self-intersection in float32 (why renderers test t > t_min, or move the start point): shadow
 * rays from the float32 hit points toward a light, the acne they make, the fraction of
 * self-hits against the offset ε at several distances, and pbrt's error-bound offset.
 */
import { ScrollTable } from '../Precision';
import { useEffect, useMemo, useRef, useState } from 'react';
import { Plot, Readout, SERIES, Slider, type PlotLayout, type PlotTrace } from '../../../../ui';
import {
  ACNE_EPSILONS,
  acneSweepF32,
  shadowAcneF32,
  sphereImageSetup,
  type AcneSweep,
} from '../../../../core/geometry';

const W = 96;
const SWEEP_W = 48;
const DISTANCES = [10, 100, 1e3, 1e4];
/** One colour per distance: the shared plot palette (≥ 3 : 1 in both themes, apart for colour-blind readers). */
const COLOURS = SERIES;
const n = Math.hypot(-1, 0.8, 0.6);
/** A directional light up and to the left of the camera (unit). */
export const ACNE_LIGHT = [-1 / n, 0.8 / n, 0.6 / n] as const;

const sup = (D: number) => `10${String(Math.round(Math.log10(D))).replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[+d])}`;

export function SelfIntersectionF32() {
  const [dist, setDist] = useState(1e3);
  const [epsExp, setEpsExp] = useState(-6);
  const [pbrt, setPbrt] = useState(false);
  const eps = 10 ** epsExp;
  const setup = useMemo(() => sphereImageSetup(dist, W, W), [dist]);
  const acne = useMemo(() => shadowAcneF32(setup, ACNE_LIGHT, pbrt ? 'pbrt' : eps), [setup, eps, pbrt]);
  const [sweeps, setSweeps] = useState<AcneSweep[] | null>(null);
  useEffect(() => {
    // after the image has been painted: about 0.1 s of float32 shadow rays
    const id = setTimeout(
      () =>
        setSweeps(DISTANCES.map((D) => acneSweepF32(sphereImageSetup(D, SWEEP_W, SWEEP_W), D, ACNE_LIGHT))),
      50,
    );
    return () => clearTimeout(id);
  }, []);
  const cv = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    const g = cv.current?.getContext('2d');
    if (!g) return;
    const img = g.createImageData(W, W);
    const col: Record<number, [number, number, number]> = {
      0: [32, 35, 42],
      1: [70, 66, 60],
      2: [236, 228, 206],
      3: [200, 30, 40],
    };
    for (let i = 0; i < W * W; i++) {
      const c = col[acne.kind[i]];
      img.data.set([c[0], c[1], c[2], 255], 4 * i);
    }
    g.putImageData(img, 0, 0);
  }, [acne]);
  const fraction = acne.lit ? acne.selfHits / acne.lit : 0;
  const here = sweeps?.find((s) => s.dist === dist) ?? null;
  const data = useMemo<PlotTrace[]>(
    () =>
      (sweeps ?? []).flatMap((s, k) => [
        {
          x: s.eps.slice(1),
          y: s.fraction.slice(1),
          name: `D/r = ${sup(s.dist)}`,
          mode: 'lines+markers',
          line: { color: COLOURS[k] },
          marker: { size: 4 },
        },
        {
          x: [s.pbrtOffset, s.pbrtOffset],
          y: [0, 1],
          name: `pbrt offset, ${sup(s.dist)}`,
          mode: 'lines',
          line: { color: COLOURS[k], dash: 'dot', width: 1 },
          showlegend: false,
        },
      ]),
    [sweeps],
  );
  const layout = useMemo(
    (): PlotLayout => ({
      xaxis: { type: 'log', title: { text: 'offset ε along the normal (radii)' }, exponentformat: 'power' },
      yaxis: { title: { text: 'fraction of lit pixels self-shadowed' }, range: [0, 1] },
      legend: { x: 0.99, y: 0.99, xanchor: 'right', yanchor: 'top', bgcolor: 'rgba(0,0,0,0)' },
      margin: { l: 64, r: 12, t: 12, b: 56 },
    }),
    [],
  );
  return (
    <div className="rs-acne" data-testid="acne-panel">
      <h3>Self-intersection in float32: shadow acne</h3>
      <p className="rs-small">
        From every float32 hit point a shadow ray goes toward a light up and to the left. The sphere is
        convex, so on its lit side nothing can shadow it: every red pixel is the surface intersecting itself,
        because the float32 hit point landed slightly inside. Moving the start point by ε along the normal
        cures it once ε exceeds the hit point’s rounding error, a few u₃₂·D for coordinates of size D.
      </p>
      <div className="rs-presets" role="group" aria-label="Distance for the acne image">
        {DISTANCES.map((D) => (
          <button
            key={D}
            type="button"
            aria-pressed={dist === D}
            data-testid={`acne-dist-${D}`}
            onClick={() => setDist(D)}
          >
            D/r = {sup(D)}
          </button>
        ))}
      </div>
      <Slider
        label={'Offset, log₁₀(ε\u00a0/\u00a0r)'}
        value={epsExp}
        min={-8}
        max={-1}
        step={0.25}
        onChange={setEpsExp}
        testId="acne-eps"
      />
      <label className="rs-small">
        <input
          type="checkbox"
          checked={pbrt}
          onChange={(e) => setPbrt(e.target.checked)}
          data-testid="acne-pbrt"
        />{' '}
        use pbrt’s error-bound offset instead (reproject, bound the error with γₙ terms, offset by Σ|nᵢ|δᵢ)
      </label>
      <div className="rs-images">
        <figure>
          <canvas
            ref={cv}
            width={W}
            height={W}
            className="rs-canvas rs-gpu-canvas"
            role="img"
            aria-label={`Shadow acne image at D/r = ${sup(dist)}: ${acne.selfHits} of ${acne.lit} lit pixels shadow themselves`}
            data-testid="acne-img"
          />
          <figcaption>red: lit pixels that shadow themselves</figcaption>
        </figure>
      </div>
      <div className="readouts">
        <Readout
          id="acne-fraction"
          label="self-shadowed fraction of the lit pixels"
          value={fraction}
          digits={3}
        />
        <Readout id="acne-lit" label="lit pixels" value={acne.lit} />
        <Readout
          id="acne-pbrt-offset"
          label="pbrt offset here (largest, radii)"
          value={here ? here.pbrtOffset : null}
          digits={3}
        />
        <Readout
          id="acne-eps-needed"
          label="smallest swept ε with no acne (radii)"
          value={here ? here.epsNeeded : null}
          digits={3}
        />
      </div>
      {sweeps ? (
        <>
          <Plot
            data={data}
            layout={layout}
            height={340}
            label="Fraction of self-shadowed lit pixels against the offset ε, one curve per distance"
            description={`${sweeps
              .map((s) =>
                s.epsNeeded === null
                  ? `At D/r = ${sup(s.dist)} no swept ε cures it`
                  : `At D/r = ${sup(s.dist)} the acne is gone from ε ≈ ${s.epsNeeded.toPrecision(2)} r`,
              )
              .join('; ')}: the offset needed grows in proportion to the distance. The table below lists it.`}
            testId="acne-plot"
          />
          <ScrollTable label="The offset that removes the acne at each distance">
            <table className="rs-precision" data-testid="acne-table">
              <thead>
                <tr>
                  <th scope="col">D / r</th>
                  <th scope="col">self-hits at ε = 0</th>
                  <th scope="col">ε needed (swept)</th>
                  <th scope="col">pbrt offset (largest)</th>
                  <th scope="col">self-hits with pbrt’s offset</th>
                </tr>
              </thead>
              <tbody>
                {sweeps.map((s) => (
                  <tr key={s.dist}>
                    <th scope="row">{sup(s.dist)}</th>
                    <td>{(100 * s.fraction[0]).toFixed(0)} %</td>
                    <td className="mono" data-testid={`acne-need-${s.dist}`} data-value={String(s.epsNeeded)}>
                      {s.epsNeeded === null ? 'none swept' : s.epsNeeded.toExponential(1)}
                    </td>
                    <td
                      className="mono"
                      data-testid={`acne-pbrt-${s.dist}`}
                      data-value={String(s.pbrtOffset)}
                    >
                      {s.pbrtOffset.toExponential(1)}
                    </td>
                    <td data-testid={`acne-pbrt-hits-${s.dist}`} data-value={String(s.pbrtSelfHits)}>
                      {s.pbrtSelfHits}
                    </td>
                  </tr>
                ))}
              </tbody>
            </table>
          </ScrollTable>
          <p className="rs-small">
            {SWEEP_W}×{SWEEP_W} camera rays per distance, ε swept from 10⁻⁸ r to 10⁻¹ r (
            {ACNE_EPSILONS.length - 1} steps). The ε a float32 renderer needs grows in proportion to the
            distance, as pbrt’s bound does; a fixed t<sub>min</sub> that is ample in double (10⁻⁴ r) is too
            small in float32 beyond about 10³ r. Below half a coordinate’s ulp an offset does nothing at all:
            p + ε n rounds back to p.
          </p>
        </>
      ) : (
        <p className="rs-small" aria-busy="true">
          Sweeping ε at four distances…
        </p>
      )}
    </div>
  );
}
