/**
 * When each formula of a page is typeset: KaTeX for a formula on or near the screen
 * runs at once, in the shared sliced queue (./chunked: short tasks that yield between slices); the
 * others in idle time once the page's opening is over (./whenQuiet openingDone), a few per idle
 * period, in page order; everything still waiting before
 * printing (`flushMathForPrint`). The scheduling is ./viewQueue's.
 */
import { afterPaint } from './afterPaint';
import { nextTask, runChunked } from './chunked';
import { createViewQueue } from './viewQueue';
import { openingDone } from './whenQuiet';

/** How far off screen a formula still counts as "near" (typeset at once). */
export const NEAR_MARGIN = '600px';

const queue = createViewQueue({
  margin: NEAR_MARGIN,
  perIdle: 4,
  idleTimeoutMs: 1500,
  runNear: runChunked,
  idleAfter: openingDone,
});

/**
 * Typeset `job` soon: at once if `el` is near the screen, else in idle time. Returns a cancel
 * function (call it on unmount or when the formula changes).
 */
export const scheduleMath: (el: Element | null, job: () => void) => () => void = queue.schedule;

/** Typeset everything still waiting, now (before printing). */
export const flushMathForPrint: () => void = queue.flush;

/**
 * Characters of typeset HTML put into the page per frame, at most (one formula always goes): one
 * or two formulas, whose parsing, style and layout take 10–20 ms on a 2-core desktop, under the
 * 50 ms a phone (Lighthouse: 4× slower) may spend in one task. A whole derivation at once was
 * 30–40 ms there.
 */
export const HTML_PER_FRAME = 6_000;

const arrivals: { cost: number; insert: () => void }[] = [];
let inserting = false;

function insertBatch(): void {
  let spent = 0;
  while (arrivals.length && (spent === 0 || spent + arrivals[0].cost <= HTML_PER_FRAME)) {
    const a = arrivals.shift()!;
    spent += a.cost;
    try {
      a.insert();
    } catch (e) {
      setTimeout(() => {
        throw e;
      });
    }
  }
  // the next batch after this one has been rendered and painted
  void afterPaint().then(() => {
    inserting = false;
    pumpInserts();
  });
}

function pumpInserts(): void {
  if (inserting || !arrivals.length) return;
  inserting = true;
  nextTask(insertBatch);
}

/**
 * Put a typeset formula (`cost`: its HTML's length) into the page soon: a few per frame. The
 * worker answers a whole screen of formulas at once, and React would commit them together (tens
 * of ms of HTML parsing and layout in one task on a phone), so `insert` (which sets the
 * formula's state) runs in batches of at most {@link HTML_PER_FRAME} characters, one batch per
 * painted frame.
 */
export function insertTypeset(cost: number, insert: () => void): void {
  arrivals.push({ cost, insert });
  pumpInserts();
}
