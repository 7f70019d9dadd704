/** The sweep sampled for its plots: Δ by both methods, the cases, the tangencies and the g(t) window. */
import { intersectRaySphere, type RaySphereCase } from '../../core/geometry';
import { sweepAt, type Sweep } from './sweep';
import type { RaySphereParams } from './params';

export interface SweepSeries {
  t: number[];
  x: number[];
  /** Δ by each method at each sample (in the meaning b² − 4ac). */
  discNaive: number[];
  discStable: number[];
  /** The chosen method's case at each sample. */
  cases: RaySphereCase[];
  /** Positions t where the robust Δ changes sign (tangency), refined by bisection. */
  tangents: number[];
  /** Samples where the textbook Δ has the wrong sign (against the robust one, which is within its error bound). */
  naiveSignWrong: number;
  /** A fixed window for the g(t) plot over the whole sweep: t range (before the shift) and g range. */
  gWindow: { tMin: number; tMax: number; gMin: number; gMax: number; shift: number };
}

/**
 * Sample the sweep (n + 1 positions) for the Δ plot, the case strip and the g(t) plot's fixed
 * window. Pure; t-independent (memoise on the parameters).
 */
export function sweepSeries(p: Pick<RaySphereParams, 'method'>, sw: Sweep, n = 240): SweepSeries {
  const out: SweepSeries = {
    t: [],
    x: [],
    discNaive: [],
    discStable: [],
    cases: [],
    tangents: [],
    naiveSignWrong: 0,
    gWindow: { tMin: 0, tMax: 1, gMin: -1, gMax: 1, shift: 0 },
  };
  const { c, r } = sw.base;
  const method = p.method;
  let lo = Infinity;
  let hi = -Infinity;
  const tvs: number[] = [];
  const discs: number[] = [];
  let a = 1;
  for (let i = 0; i <= n; i++) {
    const t = i / n;
    const s = sweepAt(sw, t);
    const rn = intersectRaySphere(s.o, s.d, c, r, 'naive');
    const rs = intersectRaySphere(s.o, s.d, c, r, 'stable');
    if (!rn.ok || !rs.ok) continue;
    a = rs.a;
    out.t.push(t);
    out.x.push(s.x);
    out.discNaive.push(rn.discriminant);
    out.discStable.push(rs.discriminant);
    const ch = method === 'naive' ? rn : rs;
    out.cases.push(ch.case);
    if (Math.sign(rn.discriminant) !== Math.sign(rs.discriminant) && !rs.nearTangent) out.naiveSignWrong++;
    tvs.push(-ch.b / (2 * ch.a));
    discs.push(ch.discriminant);
    if (ch.t0 !== null) {
      lo = Math.min(lo, ch.t0);
      hi = Math.max(hi, ch.t1!);
    }
  }
  // tangency: sign changes of the robust Δ between samples, bisected to the last bit of t
  const sign = (t: number) => {
    const s = sweepAt(sw, t);
    const res = intersectRaySphere(s.o, s.d, c, r, 'stable');
    return res.ok ? Math.sign(res.discriminant) : 0;
  };
  for (let i = 1; i < out.t.length; i++) {
    const s0 = Math.sign(out.discStable[i - 1]);
    const s1 = Math.sign(out.discStable[i]);
    if (s0 === s1) continue;
    if (s1 === 0) {
      out.tangents.push(out.t[i]);
      continue;
    }
    if (s0 === 0) continue;
    let a0 = out.t[i - 1];
    let a1 = out.t[i];
    for (let k = 0; k < 60 && a1 - a0 > 1e-15; k++) {
      const m = 0.5 * (a0 + a1);
      const sm = sign(m);
      if (sm === 0) {
        a0 = a1 = m;
        break;
      }
      if (sm === s0) a0 = m;
      else a1 = m;
    }
    out.tangents.push(0.5 * (a0 + a1));
  }
  // g(t) window: every root of the sweep, and the vertex; t = 0 when it is not far off
  const tvMin = Math.min(...tvs);
  const tvMax = Math.max(...tvs);
  const spread = Number.isFinite(lo) ? hi - lo : 0;
  const discMax = Math.max(...discs.map(Math.abs));
  let half = Math.max(spread * 0.6, tvMax - tvMin, Math.sqrt(discMax) / a, 1e-300);
  if (!Number.isFinite(half) || half <= 0) half = 1;
  const mid = Number.isFinite(lo) ? 0.5 * (lo + hi) : 0.5 * (tvMin + tvMax);
  // a window narrower than the spacing of doubles near mid would collapse
  half = Math.max(half, Math.abs(mid) * 1e-12);
  let tMin = Math.min(mid - half, tvMin - 0.25 * half);
  let tMax = Math.max(mid + half, tvMax + 0.25 * half);
  if (Math.abs(mid) < 3 * half) {
    tMin = Math.min(tMin, -0.15 * half);
    tMax = Math.max(tMax, 0.15 * half);
  }
  const shift = Math.abs(mid) > 1e4 * (tMax - tMin) ? mid : 0;
  // g in vertex form a (t − t_v)² − Δ / 4a, over the window, for every sampled state
  let gMin = Infinity;
  let gMax = -Infinity;
  for (let i = 0; i < tvs.length; i++) {
    const tv = tvs[i];
    const k = discs[i] / (4 * a);
    const far = Math.max((tMin - tv) ** 2, (tMax - tv) ** 2);
    gMin = Math.min(gMin, -k);
    gMax = Math.max(gMax, a * far - k);
  }
  if (!(gMax > gMin)) {
    gMin -= 1;
    gMax += 1;
  }
  const pad = 0.08 * (gMax - gMin);
  out.gWindow = { tMin, tMax, gMin: Math.min(gMin - pad, -pad), gMax: gMax + pad, shift };
  return out;
}
