/**
 * When each formula of a page is typeset (issue 15): KaTeX for a formula on or near the screen
 * runs at once, in the shared sliced queue (./chunked: short tasks that yield between slices); the
 * others in idle time, a few per idle period, in page order; everything still waiting before
 * printing (`flushMathForPrint`). The scheduling is ./viewQueue's.
 */
import { runChunked } from './chunked';
import { createViewQueue } from './viewQueue';

/** How far off screen a formula still counts as "near" (typeset at once). */
export const NEAR_MARGIN = '600px';

const queue = createViewQueue({ margin: NEAR_MARGIN, perIdle: 4, idleTimeoutMs: 1500, runNear: runChunked });

/**
 * Typeset `job` soon: at once if `el` is near the screen, else in idle time. Returns a cancel
 * function (call it on unmount or when the formula changes).
 */
export const scheduleMath: (el: Element | null, job: () => void) => () => void = queue.schedule;

/** Typeset everything still waiting, now (before printing). */
export const flushMathForPrint: () => void = queue.flush;
