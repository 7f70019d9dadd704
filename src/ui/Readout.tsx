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

/** Visible text of a number: `digits` significant digits, trailing zeros trimmed. */
export function formatNumber(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return '—';
  if (x === 0) return '0';
  const ax = Math.abs(x);
  if (ax >= 1e-4 && ax < 1e9) {
    const s = x.toPrecision(digits);
    // toPrecision switches to "2.00000e+8" when the integer part has more digits than asked for
    if (!s.includes('e')) return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
  }
  const [m, e] = x.toExponential(Math.max(0, digits - 1)).split('e');
  const mt = m!.includes('.') ? m!.replace(/\.?0+$/, '') : m!;
  return `${mt}×10${superscript(e!)}`;
}

function superscript(e: string): string {
  const map: Record<string, string> = { '-': '⁻', '+': '', '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹' };
  return [...e].map((c) => map[c] ?? c).join('');
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
