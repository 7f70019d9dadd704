/**
 * An audio trace of a 1-D plot: focus it and press Enter (or p) to hear the curve left to right
 * (pitch follows the value, stereo position follows x, a tick at each marked event), step point by
 * point with ←/→ (Home/End: the ends), Esc stops. The current point's values are spoken through the
 * page's live region. Sound is off until asked; the Web Audio code loads on first use; a change of
 * the data (a reset, a new parameter) stops the sound and plays nothing by itself.
 */
import { useEffect, useId, useRef, useState, type KeyboardEvent } from 'react';
import { announce } from './announce';
import './a11y.css';
import { formatSignificant } from './format';
import type { Playing } from './audioEngine';
import { useKeyHelp, type KeyHelp } from './shortcuts';

export type TraceEventKind = 'zero' | 'root' | 'kink' | 'tangent';

export interface TraceEvent {
  x: number;
  kind: TraceEventKind;
  label?: string;
}

export interface AudioTraceProps {
  /** What is traced ("g(t) along the ray"). */
  label: string;
  xs: ArrayLike<number>;
  ys: ArrayLike<number>;
  xLabel: string;
  yLabel: string;
  events?: readonly TraceEvent[];
  format?: (v: number) => string;
  testId?: string;
  /** Length of a sweep in seconds (default 4). */
  seconds?: number;
}

const EVENT_WORDS: Record<TraceEventKind, string> = {
  zero: 'zero crossing',
  root: 'root',
  kink: 'kink',
  tangent: 'tangency',
};

const defaultFormat = (v: number) =>
  Number.isFinite(v) ? formatSignificant(v, 3, 'times').replace(/^-/, '−') : 'no value';

type Engine = typeof import('./audioEngine');
let enginePromise: Promise<Engine> | null = null;
/** The Web Audio part, loaded once, on the first request for sound. */
export function loadAudioEngine(): Promise<Engine> {
  enginePromise ??= import('./audioEngine');
  return enginePromise;
}

/** The events within half a step of point i (what stepping onto it names). */
function eventsAt(events: readonly TraceEvent[], xs: ArrayLike<number>, i: number): TraceEvent[] {
  const x = xs[i]!;
  const prev = i > 0 ? xs[i - 1]! : x;
  const next = i + 1 < xs.length ? xs[i + 1]! : x;
  const lo = x - Math.abs(x - prev) / 2;
  const hi = x + Math.abs(next - x) / 2;
  return events.filter((e) => e.x >= Math.min(lo, hi) && e.x <= Math.max(lo, hi));
}

/** The sentence spoken for point i: "t = 1.2, g = −0.3; root". */
export function pointText(
  xs: ArrayLike<number>,
  ys: ArrayLike<number>,
  i: number,
  xLabel: string,
  yLabel: string,
  events: readonly TraceEvent[],
  format: (v: number) => string,
): string {
  const evs = eventsAt(events, xs, i).map((e) => e.label ?? EVENT_WORDS[e.kind]);
  const n = Math.min(xs.length, ys.length);
  return `${xLabel} = ${format(xs[i]!)}, ${yLabel} = ${format(ys[i]!)}${evs.length ? `; ${evs.join(', ')}` : ''} (point ${i + 1} of ${n})`;
}

/** The trace's keys, for the `?` list. */
const TRACE_KEYS: readonly KeyHelp[] = [
  { keys: 'Enter or p', label: 'play the curve left to right', where: 'On a focused audio trace' },
  { keys: '← →', label: 'step point by point', where: 'On a focused audio trace' },
  { keys: 'Home / End', label: 'the first / last point', where: 'On a focused audio trace' },
  { keys: 'Esc', label: 'stop', where: 'On a focused audio trace' },
];

export function AudioTrace({
  label,
  xs,
  ys,
  xLabel,
  yLabel,
  events = [],
  format = defaultFormat,
  testId,
  seconds = 4,
}: AudioTraceProps) {
  useKeyHelp(TRACE_KEYS);
  const id = useId();
  const n = Math.min(xs.length, ys.length);
  const [index, setIndex] = useState<number | null>(null);
  const [playing, setPlaying] = useState(false);
  const [volume, setVolume] = useState(50);
  const [error, setError] = useState<string | null>(null);
  const sound = useRef<Playing | null>(null);
  // sound is off until asked: stepping blips only once the reader has asked to listen
  const soundOn = useRef(false);
  const volumeRef = useRef(volume);
  volumeRef.current = volume;

  const stop = () => {
    sound.current?.stop();
    sound.current = null;
    setPlaying(false);
  };

  // new data (a reset, a parameter change): stop, and start stepping from the beginning again
  useEffect(() => {
    setIndex(null);
    return () => {
      sound.current?.stop();
      sound.current = null;
      setPlaying(false);
    };
  }, [xs, ys]);

  const play = () => {
    if (n === 0) {
      announce(`${label}: no data to play.`, { now: true });
      return;
    }
    if (sound.current) {
      stop();
      announce('Stopped.', { now: true });
      return;
    }
    soundOn.current = true;
    setPlaying(true);
    announce(
      `Playing ${label}, ${xLabel} from ${format(xs[0]!)} to ${format(xs[n - 1]!)}, ${seconds} seconds.`,
      { now: true },
    );
    loadAudioEngine()
      .then((engine) =>
        engine.playTrace({
          xs,
          ys,
          ticks: events.map((e) => e.x),
          seconds,
          volume: volumeRef.current / 100,
        }),
      )
      .then((p) => {
        sound.current = p;
        void p.done.then(() => {
          if (sound.current === p) {
            sound.current = null;
            setPlaying(false);
          }
        });
      })
      .catch((err: unknown) => {
        setPlaying(false);
        const msg = `Sound could not start (${err instanceof Error ? err.message : String(err)}); stepping with the arrow keys still reads the values.`;
        setError(msg);
        announce(msg, { now: true });
      });
  };

  const stepTo = (i: number) => {
    if (n === 0) return;
    const j = Math.min(n - 1, Math.max(0, i));
    setIndex(j);
    announce(pointText(xs, ys, j, xLabel, yLabel, events, format), { now: true });
    if (soundOn.current && !sound.current) {
      void loadAudioEngine().then(
        (engine) => {
          const xr = engine.rangeOf(xs);
          const yr = engine.rangeOf(ys);
          return engine.blip(ys[j]!, yr, xs[j]!, xr, volumeRef.current / 100);
        },
        () => undefined,
      );
    }
  };

  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const onSlider = e.target instanceof HTMLInputElement;
    const onButton = e.target instanceof HTMLButtonElement;
    switch (e.key) {
      case 'Enter':
        if (onButton || onSlider) return; // the button's own click
        e.preventDefault();
        play();
        return;
      case 'p':
        e.preventDefault();
        play();
        return;
      case 'Escape':
        if (!sound.current) return;
        e.preventDefault();
        stop();
        announce('Stopped.', { now: true });
        return;
    }
    if (onSlider) return; // arrows, Home and End set the volume there
    const cur = index ?? -1;
    if (e.key === 'ArrowRight') stepTo(cur + 1);
    else if (e.key === 'ArrowLeft') stepTo(index === null ? 0 : cur - 1);
    else if (e.key === 'Home') stepTo(0);
    else if (e.key === 'End') stepTo(n - 1);
    else return;
    e.preventDefault();
  };

  const helpId = `${id}-help`;
  return (
    <div
      className="audio-trace"
      role="group"
      aria-label={`Audio trace: ${label}`}
      aria-describedby={helpId}
      tabIndex={0}
      data-testid={testId}
      data-playing={playing ? '1' : undefined}
      onKeyDown={onKeyDown}
    >
      <button
        type="button"
        onClick={play}
        aria-pressed={playing}
        data-testid={testId ? `${testId}-listen` : undefined}
      >
        {playing ? 'Stop' : 'Listen'}
      </button>
      <label className="audio-trace-volume">
        Volume
        <input
          type="range"
          min={0}
          max={100}
          step={5}
          value={volume}
          onChange={(e) => {
            const v = Number(e.currentTarget.value);
            setVolume(v);
            sound.current?.setVolume(v / 100);
          }}
        />
      </label>
      <span
        className="audio-trace-point small"
        aria-hidden="true"
        data-testid={testId ? `${testId}-point` : undefined}
      >
        {index === null ? `${n} points` : pointText(xs, ys, index, xLabel, yLabel, events, format)}
      </span>
      <p id={helpId} className="audio-trace-help small">
        {label}: Enter or <kbd>p</kbd> plays it left to right (pitch follows {yLabel}, left to right follows{' '}
        {xLabel}
        {events.length ? ', a tick at each marked point' : ''}); <kbd>←</kbd> <kbd>→</kbd> step point by
        point, <kbd>Home</kbd> <kbd>End</kbd> the ends, <kbd>Esc</kbd> stops.
      </p>
      {error ? (
        <p className="small notice notice-warn" role="status">
          {error}
        </p>
      ) : null}
    </div>
  );
}
