import { useEffect, useState, type ReactNode } from 'react';
import { ExprField } from '../../../ui';

/** A typed-expression field (commits on Enter / blur). */
export function FnField(props: {
  label: ReactNode;
  value: string;
  error: string | null;
  onCommit: (s: string) => void;
  testId?: string;
  hint?: ReactNode;
}) {
  return (
    <ExprField
      label={props.label}
      value={props.value}
      error={props.error}
      onCommit={props.onCommit}
      testId={props.testId}
      hint={
        props.hint ?? (
          <>
            in x, e.g. <code>(x+2)^2</code>, <code>exp(-x)*sin(3x)</code>
          </>
        )
      }
    />
  );
}

/** Parse "1.16, 1.98, 0.54" → numbers, or an error message. Empty → null (draw samples instead). */
export function parseSamples(
  text: string,
): { ok: true; value: number[] | null } | { ok: false; message: string } {
  const t = text.trim();
  if (t === '') return { ok: true, value: null };
  const parts = t.split(/[,;\s]+/).filter((s) => s !== '');
  if (parts.length > 32) return { ok: false, message: `at most 32 samples (got ${parts.length})` };
  const xs: number[] = [];
  for (const p of parts) {
    const x = Number(p);
    if (!Number.isFinite(x)) return { ok: false, message: `“${p}” is not a number` };
    xs.push(x);
  }
  return { ok: true, value: xs };
}

/** The `samples` list: given → exactly these are used; empty → N samples are drawn. */
export function SamplesField({
  value,
  onCommit,
}: {
  value: number[] | null;
  onCommit: (v: number[] | null) => void;
}) {
  const shown = value ? value.join(', ') : '';
  const [error, setError] = useState<string | null>(null);
  useEffect(() => setError(null), [shown]);
  return (
    <ExprField
      label="given samples x (comma list)"
      value={shown}
      placeholder="empty: draw N samples"
      error={error}
      testId="samples-input"
      hint="when given, exactly these samples are used"
      onCommit={(s) => {
        const r = parseSamples(s);
        if (!r.ok) setError(r.message);
        else {
          setError(null);
          onCommit(r.value);
        }
      }}
    />
  );
}
