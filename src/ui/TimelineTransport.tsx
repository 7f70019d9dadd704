/**
 * The transport of the shared timeline (src/ui/timeline.ts): play / pause, step, reset, speed,
 * loop and a labelled, keyboard-operable scrubber. Space / s / r work while focus is inside it
 * (and, in classroom mode, anywhere on the page through the shortcut registry). In classroom mode
 * `r` is the page's everywhere, also here: back to the scene's opening state, not to t = 0 (the
 * Reset button still puts the animation back to its start).
 */
import { useId, useRef, type KeyboardEvent, type ReactNode } from 'react';
import { TIMELINE_SPEEDS } from '../kit/timeline';
import { useClassroomKeys } from './shortcuts';
import { TEXT_HZ, useTimelineFrame, type Timeline } from './timeline';
import './timeline.css';

export interface TimelineTransportProps {
  timeline: Timeline;
  /** What the animation shows, e.g. "Warp morph" (names the group and the scrubber). */
  label: string;
  /** How a position reads (scrubber text and aria-valuetext), e.g. `sample 12 of 64`. */
  format?: (t: number) => string;
  /** Extra controls shown after the built-in ones (e.g. a path preset). */
  children?: ReactNode;
  testId?: string;
}

const PLAY_LABEL = '▶ Play';
const PAUSE_LABEL = '❚❚ Pause';

function speedText(s: number): string {
  return s === 0.25 ? '¼×' : s === 0.5 ? '½×' : `${s}×`;
}

export function TimelineTransport({
  timeline: tl,
  label,
  format,
  children,
  testId = 'timeline',
}: TimelineTransportProps) {
  const id = useId();
  const classroom = useClassroomKeys();
  // The scrubber's thumb follows every frame; data-t, the position text and aria-valuetext at most
  // TEXT_HZ times a second while playing (exact when paused): direct writes, so a timeline
  // with a low renderHz (or none) needs no React render of the transport while it plays.
  const scrub = useRef<HTMLInputElement>(null);
  const root = useRef<HTMLDivElement>(null);
  const pos = useRef<HTMLOutputElement>(null);
  const lastText = useRef(-Infinity);
  const textOf = (t: number) =>
    format ? format(t) : tl.integer ? `${t} of ${tl.max}` : `${Math.round((t / (tl.max || 1)) * 100)} %`;
  useTimelineFrame(tl, (t, playing) => {
    const el = scrub.current;
    if (el && Number(el.value) !== t) el.value = String(t);
    const now = performance.now();
    if (playing && now - lastText.current < 1000 / TEXT_HZ - 1) return;
    lastText.current = now;
    const st = String(t);
    if (root.current && root.current.getAttribute('data-t') !== st) root.current.setAttribute('data-t', st);
    const text = textOf(t);
    if (el && el.getAttribute('aria-valuetext') !== text) el.setAttribute('aria-valuetext', text);
    // the output's text node is React's: change its value in place (React re-renders it on pause)
    const node = pos.current?.firstChild;
    if (node && node.nodeType === 3 && node.nodeValue !== text) node.nodeValue = text;
  });
  const text = textOf(tl.t);
  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const target = e.target as HTMLElement;
    if (target.tagName === 'SELECT') return;
    let handled = true;
    if (e.key === ' ' || e.code === 'Space') tl.toggle();
    else if (e.key === 's' || e.key === 'S') tl.step();
    else if ((e.key === 'r' || e.key === 'R') && !classroom) tl.reset();
    else handled = false;
    if (handled) {
      // preventDefault also stops a focused button's own Space click; the page-wide classroom
      // shortcuts skip events that were already handled
      e.preventDefault();
      e.stopPropagation();
    }
  };
  const onKeyUp = (e: KeyboardEvent<HTMLDivElement>) => {
    if (e.key === ' ' || e.code === 'Space') e.preventDefault();
  };
  return (
    <div
      ref={root}
      className="timeline"
      role="group"
      aria-label={`${label}: animation`}
      data-testid={testId}
      data-t={String(tl.t)}
      data-playing={tl.playing ? '1' : '0'}
      onKeyDown={onKeyDown}
      onKeyUp={onKeyUp}
    >
      <div className="timeline-buttons">
        <button
          type="button"
          className="timeline-play"
          // the wider of the two labels, laid out invisibly under the label: one width for both
          data-wide={PAUSE_LABEL}
          onClick={tl.toggle}
          aria-pressed={tl.playing}
          data-testid={`${testId}-play`}
          title="Play / pause (Space)"
        >
          {tl.playing ? PAUSE_LABEL : PLAY_LABEL}
        </button>
        <button type="button" onClick={tl.step} data-testid={`${testId}-step`} title="Step forward (s)">
          Step ▸
        </button>
        <button
          type="button"
          onClick={tl.reset}
          data-testid={`${testId}-reset`}
          title={classroom ? 'Back to the start' : 'Back to the start (r)'}
        >
          ↺ Reset
        </button>
        <label className="timeline-speed">
          <span>Speed</span>
          <select
            value={tl.speed}
            onChange={(e) => tl.setSpeed(Number(e.target.value))}
            data-testid={`${testId}-speed`}
          >
            {TIMELINE_SPEEDS.map((s) => (
              <option key={s} value={s}>
                {speedText(s)}
              </option>
            ))}
          </select>
        </label>
        <label className="timeline-loop">
          <input type="checkbox" checked={tl.loop} onChange={(e) => tl.setLoop(e.target.checked)} /> Loop
        </label>
        {children}
      </div>
      <div className="timeline-scrub">
        <label htmlFor={`${id}-scrub`} className="sr-only">
          {label}: position
        </label>
        <input
          id={`${id}-scrub`}
          ref={scrub}
          type="range"
          min={0}
          max={tl.max}
          step={tl.integer ? 1 : tl.max / 1000}
          value={tl.t}
          aria-valuetext={text}
          data-testid={`${testId}-scrub`}
          onChange={(e) => tl.seek(Number(e.target.value))}
        />
        <output ref={pos} htmlFor={`${id}-scrub`} className="timeline-pos" data-testid={`${testId}-pos`}>
          {text}
        </output>
      </div>
    </div>
  );
}
