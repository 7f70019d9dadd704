/**
 * The race's growing curves are built incrementally per frame (view/RaceFigure.tsx raceCurves: the
 * segments below t joined once and extended as t grows). They must equal the paths drawn from
 * scratch from the model's frame at t (model.raceAt), for any order of positions (playing forward,
 * looping back, seeking).
 */
import { describe, expect, it } from 'vitest';
import { squarePdf1D } from '../../../src/core/sampling/pdf1d';
import { raceAt, racePoints, raceTrack } from '../../../src/scenes/monte-carlo/race';
import { raceCurves } from '../../../src/scenes/monte-carlo/view/raceCurves';

const f = (x: number) => (x + 2) ** 2;
const I = (4 ** 3 - 2 ** 3) / 3;

describe('race curves (incremental paths)', () => {
  const track = raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 11, 2000);
  const points = racePoints(track.max);
  // scales like the figure's (any affine / log maps will do; these are not round numbers)
  const ex = (n: number) => 64 + Math.log10(n) * 95.3;
  const ey = (v: number) => 150 - (v - I) * 3.7;
  const ly = (v: number) => 150 + Math.log10(v) * 21.1;
  const fig = { ex, ey, ly, floor: 1e-5 * I, R: 9.5 };

  /** The paths from scratch, as the figure drew them before (from raceAt's curve). */
  function reference(t: number) {
    const c = raceAt(track, t, points).curve;
    const clampE = (v: number) => (Number.isFinite(v) ? Math.max(v, fig.floor) : NaN);
    const clampY = (v: number) => Math.max(I - fig.R, Math.min(I + fig.R, v));
    const path = (ys: number[], sy: (v: number) => number) => {
      let d = '';
      c.n.forEach((n, k) => {
        if (!Number.isFinite(ys[k])) return;
        d += `${d ? 'L' : 'M'}${ex(n).toFixed(1)},${sy(ys[k]).toFixed(1)}`;
      });
      return d;
    };
    const band = (est: number[], se: number[]) => {
      const up: string[] = [];
      const dn: string[] = [];
      c.n.forEach((n, k) => {
        if (!Number.isFinite(se[k])) return;
        up.push(`${ex(n).toFixed(1)},${ey(clampY(est[k] + se[k])).toFixed(1)}`);
        dn.push(`${ex(n).toFixed(1)},${ey(clampY(est[k] - se[k])).toFixed(1)}`);
      });
      return up.length ? `M${up.join('L')}L${dn.reverse().join('L')}Z` : '';
    };
    return {
      uErr: path(c.uErr.map(clampE), ly),
      iErr: path(c.iErr.map(clampE), ly),
      uEst: path(c.u.map(clampY), ey),
      iEst: path(c.i.map(clampY), ey),
      uBand: band(c.u, c.uSe),
      iBand: band(c.i, c.iSe),
    };
  }

  it('equals the from-scratch paths forward, after a loop back, and after seeks', () => {
    const curves = raceCurves(track, points, fig, I);
    const ts = [
      0, 1, 2, 3, 5, 32, 33, 34, 35, 47, 48, 100, 101, 733, 1999, 2000, 0, 1, 4, 40, 1200, 17, 2000,
    ];
    for (const t of ts) expect(curves.at(t), `t = ${t}`).toEqual(reference(t));
  });

  it('the curves at 0 are empty and grow with t', () => {
    const curves = raceCurves(track, points, fig, I);
    expect(curves.at(0)).toEqual({ uErr: '', iErr: '', uEst: '', iEst: '', uBand: '', iBand: '' });
    expect(curves.at(1).uEst.startsWith('M')).toBe(true);
    expect(curves.at(1).uBand).toBe(''); // no standard error from one sample
    expect(curves.at(500).uEst.length).toBeGreaterThan(curves.at(50).uEst.length);
  });
});
