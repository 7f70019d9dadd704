/**
 * "Show as table": the data of a plot as a real table, for readers who cannot see the plot and for
 * anyone who wants the numbers. The rows are rendered only once the disclosure has been opened.
 */
import { ScrollBox } from './ScrollBox';
import { useState } from 'react';
import { formatSignificant } from './format';
import './a11y.css';

export interface ShowAsTableProps {
  caption: string;
  columns: readonly string[];
  rows: readonly (readonly number[])[] | readonly (readonly string[])[];
  testId?: string;
  /** How a number cell is written (default: 4 significant digits). */
  format?: (v: number) => string;
  /** The disclosure's text (default "Show as table"). */
  summary?: string;
}

const defaultFormat = (v: number) =>
  Number.isFinite(v) ? formatSignificant(v, 4, 'times').replace(/^-/, '−') : '—';

export function ShowAsTable({
  caption,
  columns,
  rows,
  testId,
  format = defaultFormat,
  summary = 'Show as table',
}: ShowAsTableProps) {
  const [opened, setOpened] = useState(false);
  return (
    <details
      className="data-table"
      data-testid={testId}
      onToggle={(e) => {
        if ((e.currentTarget as HTMLDetailsElement).open) setOpened(true);
      }}
    >
      <summary>{summary}</summary>
      {opened ? (
        <ScrollBox className="data-table-scroll" label={caption}>
          <table>
            <caption>{caption}</caption>
            <thead>
              <tr>
                {columns.map((c) => (
                  <th key={c} scope="col">
                    {c}
                  </th>
                ))}
              </tr>
            </thead>
            <tbody>
              {rows.map((row, i) => (
                <tr key={i}>
                  {row.map((v, j) => (
                    <td key={j}>{typeof v === 'number' ? format(v) : v}</td>
                  ))}
                </tr>
              ))}
            </tbody>
          </table>
        </ScrollBox>
      ) : null}
    </details>
  );
}
