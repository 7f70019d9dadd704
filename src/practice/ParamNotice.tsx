import type { ParamProblem } from '../kit/params';

/** A bulleted list of short texts (each is its own key: a list never holds one text twice). */
export function TextList({ items }: { items: readonly string[] }) {
  return (
    <ul>
      {items.map((t) => (
        <li key={t}>{t}</li>
      ))}
    </ul>
  );
}

/** The link parameters a practice page could not use (nothing when there are none). */
export function ParamNotice({
  problems,
  heading = false,
}: {
  problems: readonly ParamProblem[];
  heading?: boolean;
}) {
  if (!problems.length) return null;
  return (
    <div className="notice notice-warn" role="status" data-testid="param-notice">
      {heading ? (
        <p>
          <strong>Some link parameters could not be used:</strong>
        </p>
      ) : null}
      <TextList items={problems.map((p) => `${p.name} ${p.message}.`)} />
    </div>
  );
}
