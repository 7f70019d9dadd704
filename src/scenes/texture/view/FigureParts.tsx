/** The smaller pieces of the scene's figure: the exam's grid, the legend, the path's and cells' fields. */
import { memo } from 'react';
import type { SceneProps } from '../../../kit/scene';
import { examGrid, gridToRows, texel, type LookupOptions, type TextureGrid } from '../../../core/texture';
import { Notice, NumberField, Select, ShowAsTable, Toggle, useStillT } from '../../../ui';
import { gridTableColumns, gridTableRows } from './describe';
import type { TextureSchema } from '../params';
import { colorCss } from '../../../core/colormap';
import type { AnimContext } from './anim';
import { formatRounded } from '../../../core/format';
import './FigureParts.css';

type Params = SceneProps<TextureSchema>['params'];
type SetParams = SceneProps<TextureSchema>['setParams'];

/** What the exam gives: its text and its grid. */
export function ExamGives() {
  return (
    <div className="exam-asks tx-gives">
      <span className="exam-asks-label">The exam gives</span>
      <p>
        A 5 × 5 texture with values at the nodes (u, v) = (i/4, j/4), v upward. (a), (b): look it up at (u, v)
        = (0.4, 0.24); (c): at a point on a sphere.
      </p>
      <ExamGridTable />
    </div>
  );
}

/** The exam's grid as the exam prints it (v = 1 on top). */
export const ExamGridTable = memo(function ExamGridTable() {
  const rows = gridToRows(examGrid());
  const n = rows.length;
  const top = rows[0] ?? [];
  return (
    <table
      className="tx-exam-grid"
      data-testid="exam-grid"
      aria-label="The exam’s texture: rows from v = 1 (top) to v = 0, columns u = 0 to 1"
    >
      <tbody>
        {rows.map((row, k) => (
          <tr key={k}>
            <th scope="row">{(n - 1 - k) / (n - 1)}</th>
            {row.map((x, i) => (
              <td key={i}>{x}</td>
            ))}
          </tr>
        ))}
        <tr>
          <th scope="row">v↑ u→</th>
          {top.map((_, i) => (
            <th key={i} scope="col">
              {i / (top.length - 1)}
            </th>
          ))}
        </tr>
      </tbody>
    </table>
  );
});

/** The texture's values as a table (the data the grid figure colours), rendered when opened. */
export const GridValues = memo(function GridValues({
  grid,
  opts,
}: {
  grid: TextureGrid;
  opts: LookupOptions;
}) {
  return (
    <ShowAsTable
      caption={`The texture’s ${grid.width} × ${grid.height} values, top row (largest v) first`}
      columns={gridTableColumns(grid, opts)}
      rows={gridTableRows(grid, opts)}
      summary="Show the texture as a table"
      testId="grid-table"
    />
  );
});

/** The colour scale from the grid's least to its greatest value. */
export const Legend = memo(function Legend({ range }: { range: { min: number; max: number } }) {
  const stops = Array.from({ length: 11 }, (_, k) => colorCss(k / 10)).join(', ');
  return (
    <div className="tx-legend" aria-hidden="true">
      <span>{formatRounded(range.min)}</span>
      <span className="tx-legend-bar" style={{ background: `linear-gradient(to right, ${stops})` }} />
      <span>{formatRounded(range.max)}</span>
    </div>
  );
});

/** The path's shape, beside the transport. */
export function PathKindSelect({ params, setParams }: { params: Params; setParams: SetParams }) {
  return (
    <label className="tx-path-kind">
      <span>Path</span>
      <select
        value={params.path}
        onChange={(e) => setParams({ path: e.target.value === 'circle' ? 'circle' : 'line' })}
        data-testid="path-select"
      >
        <option value="line">line to (u₂, v₂)</option>
        <option value="circle">circle through both</option>
      </select>
    </label>
  );
}

/** The path's end (u₂, v₂). */
export function PathEnd({ params, setParams }: { params: Params; setParams: SetParams }) {
  return (
    <div className="tx-path-end">
      <span>Path end</span>
      {(['u2', 'v2'] as const).map((k) => (
        <NumberField
          key={k}
          label={k === 'u2' ? 'u₂' : 'v₂'}
          value={params[k]}
          min={-4}
          max={4}
          step={0.01}
          onChange={(x) => setParams({ [k]: x })}
          testId={`${k}-field`}
        />
      ))}
    </div>
  );
}

/**
 * Editing one node's value: the switch, the node (chosen on the grid, or here by its column and row,
 * without pointing), its value field, and why an edit was refused. Until a node is chosen the
 * column and row show the node nearest the query.
 */
export function CellEditor({
  ctx,
  editing,
  onEditing,
  selected,
  onSelect,
  onCell,
  error,
}: {
  ctx: AnimContext;
  editing: boolean;
  onEditing: (on: boolean) => void;
  selected: { i: number; j: number } | null;
  onSelect: (i: number, j: number) => void;
  onCell: (x: number) => void;
  error: string | null;
}) {
  const { grid } = ctx;
  const near = ctx.frame(useStillT(ctx.store)).frame.lookup.near;
  const valid = selected && selected.i < grid.width && selected.j < grid.height ? selected : null;
  const node = valid ?? { i: near.i, j: near.j };
  const indices = (n: number) =>
    Array.from({ length: n }, (_, k) => ({ value: String(k), label: String(k) }));
  return (
    <div className="tx-edit">
      <Toggle
        label="Edit cells (click a node, or arrow keys on the grid, then Enter; or choose its column and row)"
        checked={editing}
        onChange={onEditing}
        testId="edit-toggle"
      />
      {editing ? (
        <div className="tx-edit-node">
          <Select
            label="Column i"
            value={String(node.i)}
            options={indices(grid.width)}
            onChange={(x) => onSelect(Number(x), node.j)}
            testId="cell-column"
          />
          <Select
            label="Row j (from the bottom)"
            value={String(node.j)}
            options={indices(grid.height)}
            onChange={(x) => onSelect(node.i, Number(x))}
            testId="cell-row"
          />
        </div>
      ) : null}
      {editing && valid ? (
        <NumberField
          label={`Value at column ${valid.i}, row ${valid.j} (from the bottom)`}
          value={texel(grid, valid.i, valid.j)}
          onChange={onCell}
          step={1}
          testId="cell-field"
        />
      ) : editing ? (
        <p className="tx-small">
          Click a node, focus the grid and use the arrow keys, or choose a column and row, to edit its value.
        </p>
      ) : null}
      {error ? <Notice kind="warn">{error}</Notice> : null}
    </div>
  );
}
