import { formatSignificant } from '../ui/format';

/** A texel grid ("a,b,c;d,e,f;…", top row first) as a table with its u and v axes. */
export function GridTable({ text, testId }: { text: string; testId?: string }) {
  const rows = text.split(';').map((r) => r.split(','));
  const n = rows.length;
  return (
    <div className="grid-scroll">
      <table className="grid-table" data-testid={testId} data-value={text}>
        <caption className="sr-only">
          Texel values: rows from v = 1 (top) to v = 0 (bottom), columns from u = 0 to u = 1
        </caption>
        <tbody>
          {rows.map((r, k) => (
            <tr key={k}>
              <th scope="row">{formatSignificant(1 - k / (n - 1), 3, 'e')}</th>
              {r.map((x, i) => (
                <td key={i}>{x}</td>
              ))}
            </tr>
          ))}
          <tr>
            <th scope="row" className="axis-corner">
              v ↑ u →
            </th>
            {rows[0].map((_, i) => (
              <th key={i} scope="col">
                {formatSignificant(i / (n - 1), 3, 'e')}
              </th>
            ))}
          </tr>
        </tbody>
      </table>
    </div>
  );
}
