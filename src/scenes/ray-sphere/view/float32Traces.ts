/**
 * The float32 curves of the error-against-distance plot: the median relative error of Δ and of
 * t-hit for both methods in float32 (precisionF32.ts), and the u₃₂ (D/r)² guide, where the
 * textbook form breaks (D/r ≈ 1/√u₃₂ = 4096, against 1/√u ≈ 10⁸ in float64).
 */
import type { PlotTrace } from '../../../ui';
import type { ErrorSeries } from '../model';
import { errorVsDistanceF32 } from '../precisionF32';

const U32 = 2 ** -24;

/** The float32 error series at the plot's distances up to 10⁹ r. */
export function f32ErrorSeries(distances: number[]): ErrorSeries {
  // beyond 10⁹ radii a float32 sphere's centre is too coarse (spacing ≳ 64 r) to aim at
  return errorVsDistanceF32(distances.filter((D) => D <= 1e9));
}

export function f32ErrorTraces(s: ErrorSeries): PlotTrace[] {
  return [
    {
      x: s.dist,
      y: s.discNaive,
      name: 'textbook Δ, float32',
      mode: 'lines+markers',
      line: { color: '#e67e22' },
      marker: { size: 4, symbol: 'square' },
    },
    {
      x: s.dist,
      y: s.discStable,
      name: 'robust Δ, float32',
      mode: 'lines+markers',
      line: { color: '#16a085' },
      marker: { size: 4, symbol: 'square' },
    },
    {
      x: s.dist,
      y: s.hitNaive,
      name: 'textbook t<sub>hit</sub>, float32',
      mode: 'lines',
      line: { color: '#e67e22', dash: 'dot' },
    },
    {
      x: s.dist,
      y: s.hitStable,
      name: 'robust t<sub>hit</sub>, float32',
      mode: 'lines',
      line: { color: '#16a085', dash: 'dot' },
    },
    {
      x: s.dist,
      y: s.dist.map((D) => Math.min(1, U32 * D * D)),
      name: 'u₃₂ (D/r)²',
      mode: 'lines',
      line: { color: '#d9a066', width: 1, dash: 'dash' },
    },
  ];
}
