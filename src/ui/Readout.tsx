import { formatSignificant } from './format';

/**
 * A number the scene shows, readable by people and by tests: `data-testid` names it and
 * `data-value` holds the full-precision value as `String(x)` prints it (the contract), or "none"
 * when it does not apply or is not finite. The visible text may be rounded.
 */
export interface ReadoutProps {
  id: string;
  label: React.ReactNode;
  value: number | string | null | undefined;
  /** Significant digits shown (default 6). */
  digits?: number;
  unit?: string;
  /** Small print under the value (e.g. "± 0.02" or "key prints 21.45"). */
  note?: React.ReactNode;
}

/** `data-value` of a readout: String(x) for finite numbers, the string itself, or "none". */
export function readoutValue(value: number | string | null | undefined): string {
  if (value === null || value === undefined) return 'none';
  if (typeof value === 'number') return Number.isFinite(value) ? String(value) : 'none';
  return value;
}

/** Visible text of a number: `digits` significant digits, trailing zeros trimmed, "×10⁻⁵" style; "—" when not finite. */
export function formatNumber(x: number, digits = 6): string {
  return Number.isFinite(x) ? formatSignificant(x, digits, 'times') : '—';
}

export function Readout({ id, label, value, digits = 6, unit, note }: ReadoutProps) {
  const dv = readoutValue(value);
  const text = typeof value === 'number' ? formatNumber(value, digits) : value === null || value === undefined ? '—' : value;
  return (
    <div className="readout">
      <span className="readout-label">{label}</span>
      <output className="readout-value" data-testid={id} data-value={dv} title={dv === 'none' ? 'not applicable' : dv}>
        {text}
        {unit && dv !== 'none' ? <span className="readout-unit"> {unit}</span> : null}
      </output>
      {note ? <span className="readout-note">{note}</span> : null}
    </div>
  );
}
