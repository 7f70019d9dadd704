/**
 * The sound of an audio trace (Web Audio), loaded on first use only: a sine tone whose pitch
 * follows y and whose stereo position follows x, swept left to right, with a short tick at each
 * marked event (zero crossings, roots, kinks, tangency). One AudioContext for the page, created
 * on the reader's first request for sound.
 */

export interface TraceSound {
  xs: ArrayLike<number>;
  ys: ArrayLike<number>;
  /** x positions of the events to tick at. */
  ticks: readonly number[];
  /** Length of the sweep in seconds. */
  seconds: number;
  /** 0 … 1. */
  volume: number;
}

export interface Playing {
  stop(): void;
  setVolume(v: number): void;
  /** Resolves when the sweep ends or is stopped. */
  done: Promise<void>;
}

/** Lowest and highest pitch of a sweep, Hz (two octaves around A4). */
export const PITCH_LO = 220;
export const PITCH_HI = 880;

let ctx: AudioContext | null = null;

function context(): AudioContext {
  if (!ctx || ctx.state === 'closed') {
    const Ctor =
      window.AudioContext ??
      (window as unknown as { webkitAudioContext?: typeof AudioContext }).webkitAudioContext;
    if (!Ctor) throw new Error('this browser has no Web Audio');
    ctx = new Ctor();
  }
  return ctx;
}

/** Pitch of y in [lo, hi] on a log scale (equal steps of y are equal musical intervals). */
export function pitchOf(y: number, lo: number, hi: number): number {
  const t = hi > lo ? (y - lo) / (hi - lo) : 0.5;
  return PITCH_LO * Math.pow(PITCH_HI / PITCH_LO, Math.min(1, Math.max(0, t)));
}

/** Stereo position of x in [lo, hi]: −1 (left) … 1 (right). */
export function panOf(x: number, lo: number, hi: number): number {
  return hi > lo ? Math.min(1, Math.max(-1, (2 * (x - lo)) / (hi - lo) - 1)) : 0;
}

function extent(a: ArrayLike<number>): [number, number] {
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < a.length; i++) {
    const v = a[i]!;
    if (!Number.isFinite(v)) continue;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  return lo <= hi ? [lo, hi] : [0, 1];
}

/** A short blip (one point stepped to): `ms` long at the pitch of y. */
export async function blip(
  y: number,
  yRange: [number, number],
  x: number,
  xRange: [number, number],
  volume: number,
) {
  const ac = context();
  if (ac.state === 'suspended') await ac.resume();
  const t0 = ac.currentTime + 0.01;
  const osc = ac.createOscillator();
  const gain = ac.createGain();
  const pan = ac.createStereoPanner();
  osc.frequency.value = Number.isFinite(y) ? pitchOf(y, yRange[0], yRange[1]) : PITCH_LO;
  pan.pan.value = panOf(x, xRange[0], xRange[1]);
  gain.gain.setValueAtTime(0, t0);
  gain.gain.linearRampToValueAtTime(0.3 * volume, t0 + 0.01);
  gain.gain.linearRampToValueAtTime(0, t0 + 0.12);
  osc.connect(gain).connect(pan).connect(ac.destination);
  osc.start(t0);
  osc.stop(t0 + 0.13);
}

/** Play the sweep (see module doc). */
export async function playTrace(s: TraceSound): Promise<Playing> {
  const ac = context();
  if (ac.state === 'suspended') await ac.resume();
  const n = Math.min(s.xs.length, s.ys.length);
  const [xlo, xhi] = extent(s.xs);
  const [ylo, yhi] = extent(s.ys);
  const t0 = ac.currentTime + 0.05;
  const T = s.seconds;
  const master = ac.createGain();
  master.gain.value = s.volume;
  master.connect(ac.destination);

  const osc = ac.createOscillator();
  osc.type = 'sine';
  const voice = ac.createGain();
  const pan = ac.createStereoPanner();
  osc.connect(voice).connect(pan).connect(master);
  voice.gain.setValueAtTime(0, t0);
  const timeOf = (x: number) => t0 + (xhi > xlo ? ((x - xlo) / (xhi - xlo)) * T : 0);
  for (let i = 0; i < n; i++) {
    const x = s.xs[i]!;
    const y = s.ys[i]!;
    if (!Number.isFinite(x)) continue;
    const t = timeOf(x);
    // a value that is not a number is a gap: silence there
    voice.gain.setValueAtTime(Number.isFinite(y) ? 0.25 : 0, t);
    if (Number.isFinite(y)) osc.frequency.setValueAtTime(pitchOf(y, ylo, yhi), t);
    pan.pan.setValueAtTime(panOf(x, xlo, xhi), t);
  }
  voice.gain.setValueAtTime(0, t0 + T + 0.02);
  osc.start(t0);
  osc.stop(t0 + T + 0.05);
  const nodes: OscillatorNode[] = [osc];

  for (const x of s.ticks) {
    if (!Number.isFinite(x) || x < xlo || x > xhi) continue;
    const t = timeOf(x);
    const tick = ac.createOscillator();
    tick.type = 'square';
    tick.frequency.value = 1760;
    const g = ac.createGain();
    g.gain.setValueAtTime(0, t);
    g.gain.linearRampToValueAtTime(0.15, t + 0.005);
    g.gain.linearRampToValueAtTime(0, t + 0.04);
    const tp = ac.createStereoPanner();
    tp.pan.value = panOf(x, xlo, xhi);
    tick.connect(g).connect(tp).connect(master);
    tick.start(t);
    tick.stop(t + 0.05);
    nodes.push(tick);
  }

  let resolve!: () => void;
  const done = new Promise<void>((r) => (resolve = r));
  let stopped = false;
  osc.onended = () => {
    stopped = true;
    master.disconnect();
    resolve();
  };
  return {
    done,
    setVolume: (v) => master.gain.setValueAtTime(v, ac.currentTime),
    stop: () => {
      if (stopped) return;
      stopped = true;
      for (const o of nodes) {
        try {
          o.stop();
        } catch {
          /* not started yet or already stopped */
        }
      }
      master.disconnect();
      resolve();
    },
  };
}

export { extent as rangeOf };
