/** Shared look of the scene's plots: colours, margins, layouts, and the run bar. */
import type { ReactNode } from 'react';
import { NumberField, SERIES, type Dash, type PlotLayout } from '../../../ui';
import type { WorkerFactory, WorkerJob } from '../../../workers';
import type { ProblemArgs } from '../jobs';
import type { McTasks } from '../mc.worker';
import { schema } from '../params';

/**
 * The shared plot colours (src/ui/palette: 3 : 1 on every background in both themes, apart under
 * colour-vision deficiencies); Plot resolves the var() when it draws. With more strategies than
 * colours, the dash tells the ones of one colour apart.
 */
export const COLORS = SERIES;
/** Opacity of a histogram's bars in the shared colours: still 3 : 1 on the page in both themes. */
export const BAR_OPACITY = 0.75;
/** The colour of references drawn over the data (the exact value, guides). */
export const REFERENCE = 'var(--muted)';
/** Line dashes per strategy, in step with COLORS: the legend matches a line by its dash, not only its colour. */
export const DASHES: readonly Dash[] = [
  'solid',
  'dash',
  'dot',
  'dashdot',
  'longdash',
  'longdashdot',
  '5px,2px,1px,2px',
];
/** The line of strategy i: its colour and its dash. */
export const strategyLine = (i: number, width = 2) => ({
  color: COLORS[i % COLORS.length],
  dash: DASHES[i % DASHES.length],
  width,
});
export const arr = (a: ArrayLike<number>) => Array.from(a);
export const MARGIN = { l: 60, r: 12, t: 12, b: 48 };

// Layouts are module constants: Plot re-renders whenever its layout object changes identity.
export const L_FUNC: PlotLayout = { margin: MARGIN, xaxis: { title: { text: 'x' } } };
export const L_EST: PlotLayout = {
  xaxis: { type: 'log', title: { text: 'N (samples)' } },
  yaxis: { title: { text: 'estimate' } },
  margin: MARGIN,
};
/** A log-log layout with these axis titles. */
const logLog = (x: string, y: string): PlotLayout => ({
  xaxis: { type: 'log', title: { text: x } },
  yaxis: { type: 'log', title: { text: y }, exponentformat: 'power' },
  margin: MARGIN,
});
export const L_ERR = logLog('N', '|estimate − exact|');
export const L_RMSE = logLog('N', 'RMSE');
export const L_TIME = logLog('ms per estimate (measured here)', 'RMSE');
export const L_HIST: PlotLayout = {
  xaxis: { title: { text: 'estimate ⟨I⟩' } },
  yaxis: { title: { text: 'count' } },
  bargap: 0,
  margin: MARGIN,
};

export function Heading({ children }: { children: ReactNode }) {
  return <h3 className="mc-plot-title">{children}</h3>;
}

/** What every worker-run panel is given: the problem, its exact value, and the worker to run it in. */
export interface PanelRunProps {
  args: ProblemArgs;
  exact: number;
  makeWorker: WorkerFactory<McTasks>;
}

type RunTask = Pick<
  WorkerJob<unknown, unknown>,
  'running' | 'waiting' | 'progress' | 'error' | 'cancel' | 'run'
>;

/** A job's progress with Cancel while it runs, Run again when it is done, and its failure. */
export function RunBar({ task, label }: { task: RunTask; label: ReactNode }) {
  const { running, waiting, progress } = task;
  return (
    <>
      <div className="mc-runbar">
        {waiting && !running ? (
          <span role="status">Waiting for the run above to finish…</span>
        ) : running ? (
          <>
            <progress max={1} value={progress} aria-label="progress" />
            <span role="status">
              {label} {Math.round(progress * 100)} %
            </span>
            <button type="button" onClick={task.cancel}>
              Cancel
            </button>
          </>
        ) : (
          <button type="button" onClick={task.run}>
            Run again
          </button>
        )}
      </div>
      {task.error ? <p className="field-error">The run failed: {task.error.message}</p> : null}
    </>
  );
}

/** The panels' count fields: label and test id (the range is the URL parameter's, ../params). */
const COUNT_FIELDS = {
  runs: { label: 'runs', testId: 'runs-input' },
  hn: { label: 'samples per estimate', testId: 'hn-input' },
} as const;

/** A whole-number field with a note beside it (how many runs or samples a panel uses). */
export function CountField({
  name,
  value,
  onChange,
  note,
}: {
  name: keyof typeof COUNT_FIELDS;
  value: number;
  onChange: (v: number) => void;
  note: ReactNode;
}) {
  const { min, max } = schema[name];
  return (
    <div className="mc-inline">
      <NumberField
        {...COUNT_FIELDS[name]}
        value={value}
        min={min}
        max={max}
        step={1}
        onChange={(v) => onChange(Math.round(v))}
      />
      <span className="mc-note">{note}</span>
    </div>
  );
}

/** Positive finite values, null elsewhere (a gap on a log axis). */
export const clampArr = (a: Float64Array) => arr(a).map((v) => (Number.isFinite(v) && v > 0 ? v : null));
