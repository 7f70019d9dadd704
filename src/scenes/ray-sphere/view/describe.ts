/**
 * What the ray–sphere figures show, in words, with the numbers a sighted student reads from them:
 * the cross-section's description (the case, Δ, the roots, the hit point, how close the line comes
 * to the centre), each handle's value text, and the summaries of the g(t) and Δ plots. Pure
 * functions of the model, no DOM; numbers as the readouts write them (4 significant digits here,
 * a real minus sign).
 */
import type { RaySphereHit } from '../../../core/geometry';
import { formatNumber } from '../../../ui/Readout';
import { closestApproach } from '../frame';
import { FAR_RATIO, type RaySphereModel } from '../model';
import { type ErrorSeries } from '../errorSeries';
import { type SweepMode } from '../sweep';
import { type SweepSeries } from '../sweepSeries';
import type { RayState, Target } from './crossLayout';
import { sweepCoord } from './format';

/** A number for prose and speech: 4 significant digits (or `digits`), a real minus sign. */
export function num(x: number, digits = 4): string {
  return formatNumber(x, digits).replace(/^-/, '−');
}

/**
 * Digits enough to tell a and b apart (4 at least, 10 at most, as the readouts): two roots
 * 2·10⁻⁵ apart at t ≈ 10⁵ need 11 digits, and get the readouts' 10.
 */
export function digitsApart(a: number, b: number): number {
  const gap = Math.abs(a - b);
  const big = Math.max(Math.abs(a), Math.abs(b));
  if (!(gap > 0) || !(big > 0) || !Number.isFinite(big)) return 4;
  return Math.max(4, Math.min(10, Math.ceil(Math.log10(big / gap)) + 2));
}

/** A vector: (x, y, z), each as {@link num}. */
export const vec = (p: readonly number[], digits = 4) => `(${p.map((x) => num(x, digits)).join(', ')})`;

/** The point o + t d. */
export const pointAt = (o: readonly number[], d: readonly number[], t: number): [number, number, number] => [
  o[0] + t * d[0],
  o[1] + t * d[1],
  o[2] + t * d[2],
];

/** The handles' accessible names. */
export const HANDLE_NAMES: Record<Target, string> = {
  o: 'ray origin o',
  tip: 'ray direction d (arrow tip)',
  c: 'sphere centre C',
  r: 'sphere radius r',
};

/** What the ray does, in a few words (for a handle's value text, after each move). */
export function caseShort(res: RaySphereHit | null): string {
  if (!res) return 'no result';
  const D = `Δ = ${num(res.discriminant)}`;
  const k = res.t0 !== null && res.t1 !== null ? digitsApart(res.t0, res.t1) : 4;
  switch (res.case) {
    case 'miss':
      return `the ray misses (${D})`;
    case 'tangent':
      return `the ray touches the sphere at t = ${num(res.tHit ?? res.t0 ?? NaN)} (Δ = 0)`;
    case 'two-hits':
      return `the ray hits at t₀ = ${num(res.t0!, k)} and leaves at t₁ = ${num(res.t1!, k)}`;
    case 'inside':
      return `the origin is inside; the ray leaves at t₁ = ${num(res.t1!)}`;
    case 'behind':
      return `the sphere is behind the origin (t₀ = ${num(res.t0!, k)}, t₁ = ${num(res.t1!, k)}), no hit`;
  }
}

/**
 * A handle's slider attributes: where it is (value text, ending with what the ray does now) and a
 * number for aria-valuenow (the radius; the direction's angle in the figure, in degrees; a
 * point's first coordinate).
 */
export function handleText(
  target: Target,
  ray: RayState,
  dir2: readonly [number, number],
): { valueText: string; valueNow: number; min?: number; max?: number } {
  // what the ray does now (nothing while the results are hidden: ask=1 before Reveal)
  const what = ray.res ? `; ${caseShort(ray.res)}` : '';
  if (target === 'r') return { valueText: `r = ${num(ray.r)}${what}`, valueNow: ray.r, min: 0 };
  if (target === 'tip') {
    const deg = Math.round((Math.atan2(dir2[1], dir2[0]) * 180) / Math.PI);
    return {
      valueText: `d = ${vec(ray.d)}, at ${deg}° in the figure${what}`,
      valueNow: deg,
      min: -180,
      max: 180,
    };
  }
  const p = target === 'o' ? ray.o : ray.c;
  // a point's first coordinate, within the bounds the URL accepts
  return {
    valueText: `${target === 'o' ? 'o' : 'C'} = ${vec(p)}${what}`,
    valueNow: p[0],
    min: -1e12,
    max: 1e12,
  };
}

/** Where the ray is in the sweep animation (τ: the timeline's position, not the ray's t). */
export interface SweepPlace {
  mode: SweepMode;
  /** The timeline position τ ∈ [0, 1] (0.5: the typed ray). */
  tau: number;
  /** The sweep coordinate (h / r or ψ / α) there. */
  x: number;
}

/** The sweep position as the transport writes it: "τ = 0.500, h / r = 0.388". */
export function sweepPlaceText(p: SweepPlace): string {
  const x = Number.isFinite(p.x) ? p.x.toFixed(3).replace(/^-/, '−') : String(p.x);
  return `τ = ${p.tau.toFixed(3)}, ${sweepCoord(p.mode)} = ${x}`;
}

/**
 * The cross-section in words: the case with Δ and the roots, the hit point, how close the line
 * passes the centre, then the ray and the sphere, the sweep position and the method.
 */
export function describeRaySphere(
  m: RaySphereModel,
  opts: { method: 'stable' | 'naive'; sweep?: SweepPlace; ask?: boolean },
): string {
  const { o, d, c, r } = m.input;
  const res = m.chosen;
  const parts: string[] = [];
  if (opts.ask)
    parts.push('The ray and the sphere; where (and whether) the ray meets it is hidden until you reveal it.');
  else if (!res) parts.push(`No result: ${m.fatal ?? 'the inputs cannot be used'}.`);
  else {
    const D = `Δ = ${num(res.discriminant)}`;
    const near = closestApproach(o, d, c);
    const gap = near - r;
    const passes =
      `the line passes ${num(near)} from C, ` +
      (gap > 0
        ? `${num(gap)} beyond the radius`
        : gap < 0
          ? `${num(-gap)} inside the radius`
          : 'exactly at the radius');
    const at = (t: number) => `p = ${vec(pointAt(o, d, t))}`;
    const k = res.t0 !== null && res.t1 !== null ? digitsApart(res.t0, res.t1) : 4;
    const t0 = res.t0 !== null ? num(res.t0, k) : '';
    const t1 = res.t1 !== null ? num(res.t1, k) : '';
    switch (res.case) {
      case 'miss':
        parts.push(`The ray misses: ${D} < 0, no real root; ${passes}.`);
        break;
      case 'tangent':
        parts.push(
          `The ray is tangent: Δ = 0, one double root t₀ = t₁ = ${num(res.tHit!)}, touching at ${at(res.tHit!)}; ${passes}.`,
        );
        break;
      case 'two-hits':
        parts.push(
          `The ray hits: ${D} > 0, roots t₀ = ${t0} and t₁ = ${t1}, both ≥ 0. ` +
            `It enters at t₀, the hit point ${at(res.t0!)}, and leaves at t₁; ${passes}.`,
        );
        break;
      case 'inside':
        parts.push(
          `The origin is inside the sphere: ${D}, t₀ = ${t0} lies behind the origin; ` +
            `the hit is the exit t₁ = ${t1} at ${at(res.t1!)}.`,
        );
        break;
      case 'behind':
        parts.push(
          `The sphere is behind the origin: ${D} ≥ 0 but both roots t₀ = ${t0} and ` +
            `t₁ = ${t1} are negative, so the ray (t ≥ 0) has no hit.`,
        );
        break;
    }
    if (res.nearTangent && res.case !== 'tangent')
      parts.push('|Δ| is within rounding error of 0: the last bits decide whether it hits.');
  }
  parts.push(`Ray o = ${vec(o)}, d = ${vec(d)}; sphere C = ${vec(c)}, r = ${num(r)}.`);
  if (m.distanceRatio > FAR_RATIO)
    parts.push(`Not to scale: the origin is ${num(m.distanceRatio, 3)} radii from the centre.`);
  if (opts.sweep && !opts.ask) parts.push(`Sweep ${sweepPlaceText(opts.sweep)}.`);
  parts.push(
    `${opts.method === 'naive' ? 'Textbook' : 'Robust'} Δ, ${m.precision === 'f32' ? 'float32' : 'double'} arithmetic.`,
  );
  return parts.join(' ');
}

/** The 3D view in words: what the ray does, the ray and the sphere, and how to turn the view. */
export function describe3D(m: RaySphereModel): string {
  const { o, d, c, r } = m.input;
  const hit =
    m.chosen && m.chosen.tHit !== null
      ? ` The hit point p = ${vec(pointAt(o, d, m.chosen.tHit))} is marked on the sphere.`
      : '';
  return (
    `The ray and the sphere in 3D: ${caseShort(m.chosen)}.${hit} Ray o = ${vec(o)}, d = ${vec(d)}; ` +
    `sphere C = ${vec(c)}, r = ${num(r)}. Focus the view to orbit it with the arrow keys; + and − zoom, ` +
    'Home resets it.'
  );
}

// ---------------------------------------------------------------------------------------------
// The plots: g(t) along the ray, Δ against the sweep.

/** g(t) sampled on the sweep's fixed window, in vertex form (accurate where a t² + b t + c cancels). */
export function gSamples(res: RaySphereHit, w: SweepSeries['gWindow'], n = 48): { t: number[]; g: number[] } {
  const tv = -res.b / (2 * res.a);
  const k = res.discriminant / (4 * res.a);
  const t: number[] = [];
  const g: number[] = [];
  for (let i = 0; i <= n; i++) {
    const x = w.tMin + ((w.tMax - w.tMin) * i) / n;
    t.push(x);
    g.push(res.a * (x - tv) * (x - tv) - k);
  }
  return { t, g };
}

/** The roots of g as events for an audio trace (a tangent's double root is one event). */
export function gEvents(res: RaySphereHit | null): { x: number; kind: 'root' | 'tangent'; label: string }[] {
  if (!res || res.t0 === null) return [];
  if (res.t0 === res.t1)
    return [{ x: res.t0, kind: 'tangent', label: `double root t₀ = t₁ = ${num(res.t0)}` }];
  return [
    { x: res.t0, kind: 'root', label: `root t₀ = ${num(res.t0)}` },
    { x: res.t1!, kind: 'root', label: `root t₁ = ${num(res.t1!)}` },
  ];
}

/** The g(t) plot in words: the parabola's lowest point, where it crosses zero, which root is the hit. */
export function describeGPlot(res: RaySphereHit | null, w: SweepSeries['gWindow']): string {
  const range = `t from ${num(w.tMin)} to ${num(w.tMax)}`;
  if (!res) return `g(t) along the ray, ${range}: no result.`;
  const tv = -res.b / (2 * res.a);
  const gv = -res.discriminant / (4 * res.a);
  const head = `g(t) = a t² + b t + c along the ray, ${range}: a parabola opening upward, lowest at t = ${num(tv)} where g = ${num(gv)}`;
  if (res.t0 === null) return `${head}, above zero everywhere: no root, a miss.`;
  if (res.t0 === res.t1)
    return `${head}: it touches zero at t = ${num(res.t0)} (a double root, tangent)${res.tHit === null ? ', behind the origin' : ''}.`;
  const hit =
    res.tHit === null
      ? 'both are negative, so no hit'
      : res.tHit === res.t0
        ? 't₀ is the hit'
        : 't₀ is behind the origin, t₁ is the hit';
  const k = digitsApart(res.t0, res.t1!);
  return `${head}; it crosses zero at t₀ = ${num(res.t0, k)} and t₁ = ${num(res.t1!, k)}: ${hit}.`;
}

/** The tangencies of the sweep as audio-trace events (Δ = 0), at their sweep coordinates. */
export function deltaEvents(tangentX: readonly number[], mode: SweepMode) {
  return tangentX.map((x) => ({
    x,
    kind: 'tangent' as const,
    label: `tangent, Δ = 0 at ${sweepCoord(mode)} = ${num(x)}`,
  }));
}

/** Runs of equal cases along the sweep: "miss to h / r = −1, two hits to 1, miss". */
function caseRuns(s: SweepSeries, mode: SweepMode): string {
  const names: Record<string, string> = {
    miss: 'miss',
    tangent: 'tangent',
    'two-hits': 'two hits',
    inside: 'origin inside',
    behind: 'sphere behind',
  };
  // each run ends halfway between its last sample and the next run's first
  const runs: { c: string; to: number }[] = [];
  s.cases.forEach((c, i) => {
    const last = runs[runs.length - 1];
    if (last && last.c === c) return;
    if (last) last.to = (s.x[i - 1] + s.x[i]) / 2;
    runs.push({ c, to: NaN });
  });
  if (runs.length > 8) return `the case changes ${runs.length - 1} times`;
  return runs
    .map((r, i) =>
      i < runs.length - 1 ? `${names[r.c]} up to ${sweepCoord(mode)} ≈ ${num(r.to, 3)}` : names[r.c],
    )
    .join(', then ');
}

/** The Δ plot in words: its range, where it crosses zero, the cases along the sweep, the textbook's wrong signs, where it is now. */
export function describeDeltaPlot(
  s: SweepSeries,
  tangentX: readonly number[],
  mode: SweepMode,
  now: { x: number; disc: number | null },
): string {
  const coord = sweepCoord(mode);
  const xs = s.x.filter(Number.isFinite);
  if (!xs.length) return 'Δ against the sweep: no data.';
  let iMax = 0;
  s.discStable.forEach((v, i) => {
    if (v > s.discStable[iMax]) iMax = i;
  });
  const parts = [
    `Δ against ${coord} from ${num(xs[0], 3)} to ${num(xs[xs.length - 1], 3)} (robust line, textbook dots): ` +
      `largest ${num(s.discStable[iMax])} at ${coord} = ${num(s.x[iMax], 3)}.`,
    tangentX.length
      ? `It crosses zero at ${coord} = ${tangentX.map((x) => num(x, 3)).join(' and ')} (tangent).`
      : 'It never crosses zero in this sweep.',
    `Cases along the sweep: ${caseRuns(s, mode)}.`,
  ];
  if (s.naiveSignWrong > 0)
    parts.push(
      `The textbook Δ has the wrong sign (or is 0) at ${s.naiveSignWrong} of ${s.x.length} positions.`,
    );
  if (now.disc !== null && Number.isFinite(now.x))
    parts.push(`Now at ${coord} = ${num(now.x, 3)}: Δ = ${num(now.disc)}.`);
  return parts.join(' ');
}

// ---------------------------------------------------------------------------------------------
// Explore further: the error against distance, the distant-sphere images.

/** The first distance at which an error reaches `level` (null: never). */
function firstAt(dist: readonly number[], err: readonly number[], level: number): number | null {
  const i = err.findIndex((e) => e >= level);
  return i < 0 ? null : dist[i];
}

/**
 * The error plot in words: where each form's Δ has lost half its digits and all of them, in
 * float64 and (given the float32 series) in float32, and the robust form's largest error.
 */
export function describeErrorPlot(
  s: ErrorSeries,
  f32?: Pick<ErrorSeries, 'dist' | 'discNaive' | 'discStable'>,
): string {
  const D = (x: number | null) => (x === null ? 'never in the plotted range' : `by D ≈ ${num(x, 2)} r`);
  const lost = (d: readonly number[], e: readonly number[]) =>
    `half its digits ${D(firstAt(d, e, 1e-8))}, all of them ${D(firstAt(d, e, 0.5))}`;
  const worst = (e: readonly number[]) => num(Math.max(...e), 2);
  const parts = [
    `Median relative error against the distance D = |o − C| / r from ${num(s.dist[0], 2)} to ${num(s.dist[s.dist.length - 1], 2)} (log–log).`,
    `In float64 the textbook Δ loses ${lost(s.dist, s.discNaive)}; it grows like u (D/r)². The robust Δ's error grows only like u D/r, at most ${worst(s.discStable)}.`,
  ];
  if (f32 && f32.dist.length)
    parts.push(
      `In float32 the textbook Δ loses all its digits ${D(firstAt(f32.dist, f32.discNaive, 0.5))}; the robust Δ's error is at most ${worst(f32.discStable)}.`,
    );
  return parts.join(' ');
}
