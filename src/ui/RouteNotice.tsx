import { useMemo } from 'react';
import { queryProblems, type ShellFlags } from '../kit/shell';

/**
 * The parameter notice of a page without a scene schema (home, guide): shell parameters it could
 * not use (theme=…, a repeated one) and names it does not take, as the scenes' notice lists them.
 */
export function RouteNotice({
  flags,
  query,
  known = [],
}: {
  flags: ShellFlags;
  query: string;
  known?: readonly string[];
}) {
  const problems = useMemo(
    () => [...flags.problems, ...queryProblems(query, known)],
    [flags.problems, query, known],
  );
  if (!problems.length) return null;
  return (
    <div className="notice notice-warn param-notice" role="status" data-testid="param-notice">
      <p>
        <strong>Some link parameters could not be used:</strong>
      </p>
      <ul>
        {problems.map((p, i) => (
          <li key={`${p.name}-${i}`}>
            <code>{p.name}</code> {p.message}
          </li>
        ))}
      </ul>
    </div>
  );
}
