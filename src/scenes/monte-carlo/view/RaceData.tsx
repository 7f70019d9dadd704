/**
 * The race for readers who cannot see it: the words of each of its figures at the position React
 * renders (the paused t), its curves as a table, and audio traces of the running estimates and of
 * |error| against N. Everything comes from the model's frame at t (model.raceAt).
 */
import { useMemo } from 'react';
import { AudioTrace, ShowAsTable } from '../../../ui';
import { countIn } from '../raceHistogram';
import { raceAt, type RaceTrack } from '../race';
import {
  crossings,
  describeErrors,
  describeEstimate,
  describeIntegrand,
  describeRace,
  type RaceCurve,
} from './describeRace';

/** The words of the race's figures at t: the main description and each plot's. */
export function raceWords(o: {
  track: RaceTrack;
  t: number;
  points: readonly number[];
  importanceName: string;
  half: [number, number] | null;
  a: number;
  b: number;
  /** f on the drawn grid. */
  fValues: ArrayLike<number>;
  /** ask=1: held at its start, nothing of the result said. */
  held: boolean;
}) {
  const { track, half } = o;
  const fr = raceAt(track, o.t, o.points, 0);
  const t = fr.t;
  const I = track.exact;
  // f's range on the grid (a NaN where f is undefined takes no part; none left: ±Infinity)
  const fs = Array.from(o.fValues).filter((v) => !Number.isNaN(v));
  const fMin = Math.min(...fs);
  const fMax = Math.max(...fs);
  return {
    main: describeRace({
      t,
      max: track.max,
      uniform: fr.uniform,
      importance: fr.importance,
      importanceName: o.importanceName,
      exact: I,
      held: o.held,
      half: half
        ? {
            lo: half[0],
            hi: half[1],
            uniform: countIn(track.uniform.x, t, half[0], half[1]),
            importance: countIn(track.importance.x, t, half[0], half[1]),
          }
        : null,
    }),
    integrand: describeIntegrand({
      a: o.a,
      b: o.b,
      fMin,
      fMax,
      importanceName: o.importanceName,
      uniform: fr.uniform,
      importance: fr.importance,
    }),
    errors: describeErrors(fr.curve, fr.importance.zeroVariance),
    uniform: describeEstimate('uniform', fr.curve.n, fr.curve.u, fr.uniform, I),
    importance: describeEstimate('importance', fr.curve.n, fr.curve.i, fr.importance, I),
  };
}

/** Rows of the curves' table: every point up to N = 10, then about a dozen per decade, and the last. */
function tableRows(c: RaceCurve): number[][] {
  const rows: number[][] = [];
  for (let k = 0; k < c.n.length; k++)
    if (c.n[k] <= 10 || k % 4 === 0 || k === c.n.length - 1)
      rows.push([c.n[k], c.u[k], c.uSe[k], c.uErr[k], c.i[k], c.iSe[k], c.iErr[k]]);
  return rows;
}

const log10s = (v: readonly number[]) => v.map((x) => (x > 0 ? Math.log10(x) : NaN));

/** The curves as a table, and the audio traces of the running estimates and of |error| (log–log). */
export function RaceData({
  curve,
  exact,
  zeroVarianceImportance,
}: {
  curve: RaceCurve;
  exact: number;
  /** The importance lane's |error| is rounding noise: no trace of it. */
  zeroVarianceImportance: boolean;
}) {
  // one set of arrays per curve: a trace starts over when its data changes identity
  const d = useMemo(() => {
    const logN = log10s(curve.n);
    const events = (est: readonly number[]) =>
      crossings(logN, est, exact).map((x) => ({ x, kind: 'zero' as const, label: 'crosses the exact I' }));
    const lanes = [
      ['uniform', curve.u, curve.uErr],
      ['importance', curve.i, curve.iErr],
    ] as const;
    // each lane's running estimate (a tick where it crosses I), and its |error| on log–log axes
    // (none for a lane with zero variance: its |error| is rounding noise)
    const traces = lanes.flatMap(([lane, est, err]) => [
      {
        id: `trace-${lane}-estimate`,
        label: `${lane} running estimate against log₁₀ N`,
        ys: est,
        yLabel: `${lane} estimate`,
        events: events(est),
      },
      ...(lane === 'importance' && zeroVarianceImportance
        ? []
        : [
            {
              id: `trace-${lane}-error`,
              label: `${lane} |error| against N, log–log`,
              ys: log10s(err),
              yLabel: 'log₁₀ |error|',
              events: [],
            },
          ]),
    ]);
    return { logN, traces, rows: tableRows(curve) };
  }, [curve, exact, zeroVarianceImportance]);
  return (
    <section className="mc-race-data" aria-label="The race as a table and as sound">
      <ShowAsTable
        caption="The race’s curves: each lane’s running estimate, its ± s/√N and |error| against N"
        columns={[
          'N',
          'uniform ⟨I⟩',
          'uniform s/√N',
          'uniform |error|',
          'importance ⟨I⟩',
          'importance s/√N',
          'importance |error|',
        ]}
        rows={d.rows}
        testId="race-table"
      />
      <div className="mc-traces">
        {d.traces.map((tr) => (
          <AudioTrace
            key={tr.id}
            label={tr.label}
            xs={d.logN}
            ys={tr.ys}
            xLabel="log₁₀ N"
            yLabel={tr.yLabel}
            events={tr.events}
            testId={tr.id}
          />
        ))}
      </div>
    </section>
  );
}
