/**
 * The race's growing curves and moving marks as SVG geometry: the |error|, estimate and ± band
 * polylines of each lane (segments formatted once per track, joined up to t), the rugs of the
 * latest samples and the newest-sample markers, with the direct writes a frame makes to them.
 */
import { coordText, type Scale } from '../../../ui/chartScale';
import { M, PH } from './raceSvg';
import { raceLaneAt, type LaneState, type RaceTrack } from '../race';

/** Samples shown in each rug (the latest ones). */
export const RECENT = 40;

/**
 * The growing curves (|error|, estimate, ± standard-error band of each lane) as polylines over the
 * sample counts `points` below t, plus the point at t itself: the segments at `points` are formatted
 * once; `at(t)` joins those below t, reusing the previous call's joined prefix when t grew.
 */
export function raceCurves(
  track: RaceTrack,
  points: readonly number[],
  fig: { ex: Scale; ey: Scale; ly: Scale; floor: number; R: number },
  I: number,
) {
  const { ex, ey, ly, floor, R } = fig;
  const clampY = (v: number) => Math.max(I - R, Math.min(I + R, v));
  const xy = (n: number, y: number) => `${coordText(ex(n))},${coordText(y)}`;
  type Seg = { err: string | null; est: string | null; up: string | null; dn: string | null };
  const seg = (s: LaneState): Seg => {
    const n = s.n;
    const est = clampY(s.estimate);
    const ok = Number.isFinite(s.stderr);
    return {
      err: Number.isFinite(s.absError) ? xy(n, ly(Math.max(s.absError, floor))) : null,
      est: Number.isFinite(est) ? xy(n, ey(est)) : null,
      up: ok ? xy(n, ey(clampY(s.estimate + s.stderr))) : null,
      dn: ok ? xy(n, ey(clampY(s.estimate - s.stderr))) : null,
    };
  };
  const segU = points.map((n) => seg(raceLaneAt(track.uniform, n, I)));
  const segI = points.map((n) => seg(raceLaneAt(track.importance, n, I)));
  /** A polyline's joined prefix over the first k points (forward, or reversed for a band's lower edge). */
  const prefix = (segs: Seg[], key: keyof Seg, reversed: boolean) => {
    let k = 0;
    let s = '';
    return (upTo: number) => {
      if (upTo < k) {
        k = 0;
        s = '';
      }
      for (; k < upTo; k++) {
        const g = segs[k][key];
        if (g) s = s ? (reversed ? `${g}L${s}` : `${s}L${g}`) : g;
      }
      return s;
    };
  };
  const lanes = ([segU, segI] as const).map((segs) => ({
    err: prefix(segs, 'err', false),
    est: prefix(segs, 'est', false),
    up: prefix(segs, 'up', false),
    dn: prefix(segs, 'dn', true),
  }));
  const join = (...parts: (string | null)[]) => parts.filter((p) => p).join('L');
  return {
    at(t: number): Pick<RaceGeom, 'uErr' | 'iErr' | 'uBand' | 'iBand' | 'uEst' | 'iEst'> {
      t = Math.max(0, Math.min(track.max, Math.floor(t)));
      // the points below t (points is increasing)
      let lo = 0;
      let hi = points.length;
      while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (points[mid] < t) lo = mid + 1;
        else hi = mid;
      }
      const k = lo;
      const out = [] as string[][];
      for (const [L, lane] of [
        [lanes[0], track.uniform],
        [lanes[1], track.importance],
      ] as const) {
        const tail: Seg = t >= 1 ? seg(raceLaneAt(lane, t, I)) : { err: null, est: null, up: null, dn: null };
        const err = join(L.err(k), tail.err);
        const est = join(L.est(k), tail.est);
        const up = join(L.up(k), tail.up);
        const dn = join(tail.dn, L.dn(k));
        out.push([err ? `M${err}` : '', est ? `M${est}` : '', up ? `M${up}L${dn}Z` : '']);
      }
      return {
        uErr: out[0][0],
        uEst: out[0][1],
        uBand: out[0][2],
        iErr: out[1][0],
        iEst: out[1][1],
        iBand: out[1][2],
      };
    },
  };
}

export interface RaceGeom {
  uErr: string;
  iErr: string;
  uBand: string;
  iBand: string;
  uEst: string;
  iEst: string;
  /** Screen x of the latest samples, oldest first. */
  rugU: number[];
  rugI: number[];
  dotU: { x: number; y: number } | null;
  dotI: { x: number; y: number } | null;
}

export const rugY = (row: number) => M.t + PH - 16 + row * 9;
/** Opacity steps of a rug (the latest RECENT samples, in age order). */
export const RUG_BUCKETS = 4;

/** A rug's tick marks as RUG_BUCKETS paths, oldest first: sample j of the RECENT slots goes to bucket ⌊j·B/RECENT⌋. */
export function rugPaths(xs: number[], y: number): string[] {
  const out: string[] = Array.from({ length: RUG_BUCKETS }, () => '');
  const off = RECENT - xs.length;
  for (let j = 0; j < xs.length; j++) {
    const b = Math.min(RUG_BUCKETS - 1, Math.floor(((j + off) * RUG_BUCKETS) / RECENT));
    out[b] += `M${coordText(xs[j])},${coordText(y)}v7`;
  }
  return out;
}

/** Moves a rug to the latest samples. */
export function drawRug(g: Element | null, xs: number[], y: number): void {
  if (!g) return;
  const d = rugPaths(xs, y);
  const kids = g.children;
  for (let k = 0; k < kids.length && k < d.length; k++) kids[k].setAttribute('d', d[k]);
}

/** Moves a newest-sample marker (a dashed drop line and a dot). */
export function drawDot(g: Element | null, d: { x: number; y: number } | null): void {
  if (!g) return;
  const el = g as SVGGElement;
  if (!d) {
    el.style.display = 'none';
    return;
  }
  if (el.style.display) el.style.display = '';
  const [line, dot] = g.children;
  const x = String(d.x);
  line?.setAttribute('x1', x);
  line?.setAttribute('x2', x);
  line?.setAttribute('y2', String(d.y));
  dot?.setAttribute('cx', x);
  dot?.setAttribute('cy', String(d.y));
}
