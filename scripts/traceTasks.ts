/**
 * The tasks of a page's main thread in a Chromium trace (categories `devtools.timeline` and
 * `disabled-by-default-devtools.timeline`): each top-level task with its wall time and the
 * thread's own CPU time inside it (the trace's thread duration). CPU time is what the page's code
 * costs: a machine busy with other work stretches a task's wall time (the thread waits for a core,
 * or for the GPU process to take a frame) far more than its CPU time. Shared by
 * scripts/perf-longtasks.mjs and the storm browser test (tests/e2e/storm.spec.ts).
 */

export interface TraceEvent {
  name: string;
  ph: string;
  pid: number;
  tid: number;
  ts: number;
  dur?: number;
  tdur?: number;
  args?: { name?: string; data?: { url?: string } & Record<string, unknown> } & Record<string, unknown>;
}

export interface MainTask {
  /** Start (trace clock, µs). */
  ts: number;
  /** Wall time (ms). */
  wall: number;
  /** The main thread's CPU time inside the task (ms). */
  cpu: number;
}

/**
 * The renderer main thread that ran the page served from `origin` (the CrRendererMain thread with
 * the most events naming a script of that origin), or null.
 */
export function pageMainThread(events: readonly TraceEvent[], origin: string): string | null {
  const names = new Map<string, string | undefined>();
  for (const e of events)
    if (e.ph === 'M' && e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args?.name);
  const ours = new Map<string, number>();
  for (const e of events) {
    const k = `${e.pid}:${e.tid}`;
    if (names.get(k) === 'CrRendererMain' && String(e.args?.data?.url ?? '').startsWith(origin))
      ours.set(k, (ours.get(k) ?? 0) + 1);
  }
  return [...ours.entries()].sort((a, b) => b[1] - a[1])[0]?.[0] ?? null;
}

/** The complete events of one thread, in time order. */
export function threadEvents(events: readonly TraceEvent[], thread: string): TraceEvent[] {
  return events
    .filter((e) => `${e.pid}:${e.tid}` === thread && e.ph === 'X' && typeof e.dur === 'number')
    .sort((a, b) => a.ts - b.ts);
}

/** The top-level tasks (RunTask events not nested in another) of a thread's events. */
export function topLevelTasks(ev: readonly TraceEvent[]): MainTask[] {
  const tasks: MainTask[] = [];
  let until = -Infinity;
  for (const e of ev) {
    if (e.name !== 'RunTask' || e.ts < until) continue;
    const dur = e.dur ?? 0;
    until = e.ts + dur;
    tasks.push({ ts: e.ts, wall: dur / 1000, cpu: (e.tdur ?? dur) / 1000 });
  }
  return tasks;
}

/** The page's main-thread tasks in a trace (empty when the page's thread is not in it). */
export function mainThreadTasks(events: readonly TraceEvent[], origin: string): MainTask[] {
  const thread = pageMainThread(events, origin);
  return thread ? topLevelTasks(threadEvents(events, thread)) : [];
}

/** The part of a CDP session tracing needs (Playwright's CDPSession has it). */
export interface TraceSession {
  send(
    method: 'Tracing.start',
    params: { categories: string; transferMode: 'ReportEvents' },
  ): Promise<unknown>;
  send(method: 'Tracing.end'): Promise<unknown>;
  on(event: 'Tracing.dataCollected', fn: (e: { value: TraceEvent[] }) => void): unknown;
  off(event: 'Tracing.dataCollected', fn: (e: { value: TraceEvent[] }) => void): unknown;
  once(event: 'Tracing.tracingComplete', fn: () => void): unknown;
}

/** The categories the task list needs (more may be added, e.g. the JavaScript sampler). */
export const TASK_CATEGORIES = ['devtools.timeline', 'disabled-by-default-devtools.timeline'];

export async function startTrace(
  cdp: TraceSession,
  categories: readonly string[] = TASK_CATEGORIES,
): Promise<void> {
  await cdp.send('Tracing.start', { categories: categories.join(','), transferMode: 'ReportEvents' });
}

/** Stop tracing and collect every event. */
export async function stopTrace(cdp: TraceSession): Promise<TraceEvent[]> {
  const chunks: TraceEvent[] = [];
  const done = new Promise<void>((resolve) => cdp.once('Tracing.tracingComplete', resolve));
  const collect = (e: { value: TraceEvent[] }) => chunks.push(...e.value);
  cdp.on('Tracing.dataCollected', collect);
  await cdp.send('Tracing.end');
  await done;
  cdp.off('Tracing.dataCollected', collect);
  return chunks;
}
