import { useMemo, type ReactNode } from 'react';
import { queryProblems, type ShellFlags } from '../kit/shell';

/**
 * The notice that lists the link parameters a page could not use, one line per problem (the name,
 * then why). `lead` is the sentence above the list; `children` follow the list (a Dismiss button).
 */
export function ParamNotice({
  problems,
  lead,
  children,
}: {
  problems: readonly { name: string; message: string }[];
  lead: ReactNode;
  children?: ReactNode;
}) {
  return (
    <div className="notice notice-warn param-notice" role="status" data-testid="param-notice">
      <p>{lead}</p>
      <ul>
        {problems.map((p, i) => (
          <li key={`${p.name}-${i}`}>
            <code>{p.name}</code> {p.message}
          </li>
        ))}
      </ul>
      {children}
    </div>
  );
}

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
  return <ParamNotice problems={problems} lead={<strong>Some link parameters could not be used:</strong>} />;
}
