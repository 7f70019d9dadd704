/**
 * The float32 curves of the error-against-distance plot: the median relative error of Δ and of
 * t-hit for both methods in float32 (precisionF32.ts), and the u₃₂ (D/r)² guide, where the
 * textbook form breaks (D/r ≈ 1/√u₃₂ = 4096, against 1/√u ≈ 10⁸ in float64).
 */
import type { PlotTrace } from '../../../ui';
import type { ErrorSeries } from '../errorSeries';
import { errorVsDistanceF32 } from '../precisionF32';
import { ERROR_COLOURS, guide, methodCurves } from './errorCurves';

const U32 = 2 ** -24;

/** The float32 error series at the plot's distances up to 10⁹ r. */
export function f32ErrorSeries(distances: number[]): ErrorSeries {
  // beyond 10⁹ radii a float32 sphere's centre is too coarse (spacing ≳ 64 r) to aim at
  return errorVsDistanceF32(distances.filter((D) => D <= 1e9));
}

export function f32ErrorTraces(s: ErrorSeries): PlotTrace[] {
  const colours = { naive: ERROR_COLOURS.naiveF32, stable: ERROR_COLOURS.stableF32 };
  return [
    ...methodCurves(s, colours, ', float32', { size: 4, symbol: 'square' }),
    guide(s, (D) => U32 * D * D, 'u₃₂ (D/r)²', ERROR_COLOURS.guideF32),
  ];
}
