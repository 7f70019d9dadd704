/**
 * The race (RaceFigure) and Q4(d)'s numbers (exam/Q4d), each computing the shared track in its own
 * render: the track is the largest computation of the scene's first screen, and React renders
 * a transition component by component, yielding between them, so out of MonteCarloScene's own
 * render it makes its own short task instead of lengthening the scene's. Both read one cached
 * track (the last one computed), so the second is free.
 */
import { curves } from '../curves';
import { heavierHalf } from '../raceHistogram';
import { raceAt, racePoints, raceTrack, type RaceTrack } from '../race';
import type { Exact, Fn1 } from '../integral';
import type { PdfChoice } from '../pdfChoice';
import type { Pdf1D } from '../../../core/sampling/pdf1d';
import { RaceFigure, type RaceProps } from './RaceFigure';
import { RaceData } from './RaceData';

/** What the race is computed from (RaceFigure's track and curve). */
export interface RaceInput {
  f: Fn1;
  a: number;
  b: number;
  /** The importance lane's pdf: its sampler and its density (drawn on f). */
  sampler: Pdf1D;
  density: Fn1;
  exact: number;
  seed: number;
}

interface Race {
  track: RaceTrack;
  curve: ReturnType<typeof curves>;
  /** The half of [a, b] where the importance pdf is heavier (model.heavierHalf). */
  half: [number, number];
}

let last: (Race & { input: RaceInput }) | null = null;

const same = (p: RaceInput, q: RaceInput) =>
  p.f === q.f &&
  p.a === q.a &&
  p.b === q.b &&
  p.sampler === q.sampler &&
  p.density === q.density &&
  Object.is(p.exact, q.exact) &&
  p.seed === q.seed;

/** The race's input, or null when there is none to run (no f yet, no importance pdf, no finite integral). */
export function raceInputOf(
  f: Fn1 | null,
  imp: Extract<PdfChoice, { ok: true }> | null,
  exact: Exact | null,
  a: number,
  b: number,
  seed: number,
): RaceInput | null {
  if (!f || !imp || !exact || !Number.isFinite(exact.value)) return null;
  return { f, a, b, sampler: imp.sampler, density: imp.density, exact: exact.value, seed };
}

/** The track and the drawn curve of `input`, computed once per input (model.raceTrack, model.curves). */
export function raceOf(input: RaceInput): Race {
  if (last && (last.input === input || same(last.input, input))) return last;
  const { f, a, b, sampler, density, exact, seed } = input;
  last = {
    input,
    track: raceTrack(f, a, b, sampler, exact, seed),
    curve: curves(f, density, a, b, 200),
    half: heavierHalf(sampler, a, b),
  };
  return last;
}

/** What the race shows besides its track: the importance pdf's names, the position, classroom/ask modes. */
type RaceShown = Omit<RaceProps, keyof Race | 'a' | 'b'>;

export function RaceSection({ input, ...shown }: RaceShown & { input: RaceInput | null }) {
  if (!input)
    return <p className="mc-note">The animation needs a finite integral and a usable importance pdf.</p>;
  const { track, curve, half } = raceOf(input);
  return <RaceFigure {...shown} track={track} curve={curve} half={half} a={input.a} b={input.b} />;
}

/**
 * The race at position t as a table and as sound (./RaceData), under the figure: t is the paused
 * position the page's link holds, so it follows the race on pause, step, seek and reset.
 */
export function RaceDataSection({ input, t }: { input: RaceInput | null; t: number }) {
  if (!input) return null;
  const { track } = raceOf(input);
  const fr = raceAt(track, t, racePoints(track.max), 0);
  return (
    <RaceData curve={fr.curve} exact={track.exact} zeroVarianceImportance={fr.importance.zeroVariance} />
  );
}
