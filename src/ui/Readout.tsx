import { formatNumber } from './format';
import './readout.css';

export { formatNumber };

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

/** The visible text of a readout's value (as {@link Readout} shows it). */
export function readoutText(value: number | string | null | undefined, digits = 6): string {
  return typeof value === 'number'
    ? formatNumber(value, digits)
    : value === null || value === undefined
      ? '—'
      : value;
}

/**
 * Writes a readout's value into the `<output>` of a {@link LiveReadout} directly (no React render):
 * for figures that follow an animation frame by frame. Writes only what changed.
 */
export function writeReadout(
  el: HTMLElement | null,
  value: number | string | null | undefined,
  digits = 6,
): void {
  if (!el) return;
  const dv = readoutValue(value);
  if (el.getAttribute('data-value') === dv && el.firstChild) return;
  el.setAttribute('data-value', dv);
  el.title = dv === 'none' ? 'not applicable' : dv;
  el.textContent = readoutText(value, digits);
}

/**
 * A readout whose value React does not render: the owner writes it with {@link writeReadout}
 * (from an animation frame subscription, and after each of its renders), so a playing animation
 * updates the number without re-rendering. Same markup and test hooks as {@link Readout}.
 */
export function LiveReadout({
  id,
  label,
  note,
  outRef,
}: Omit<ReadoutProps, 'value' | 'digits' | 'unit'> & { outRef: React.RefObject<HTMLOutputElement | null> }) {
  return (
    <div className="readout">
      <span className="readout-label">{label}</span>
      <output ref={outRef} className="readout-value" data-testid={id} />
      {note ? <span className="readout-note">{note}</span> : null}
    </div>
  );
}

export function Readout({ id, label, value, digits = 6, unit, note }: ReadoutProps) {
  const dv = readoutValue(value);
  const text = readoutText(value, digits);
  return (
    <div className="readout">
      <span className="readout-label">{label}</span>
      <output
        className="readout-value"
        data-testid={id}
        data-value={dv}
        title={dv === 'none' ? 'not applicable' : dv}
      >
        {text}
        {unit && dv !== 'none' ? <span className="readout-unit"> {unit}</span> : null}
      </output>
      {note ? <span className="readout-note">{note}</span> : null}
    </div>
  );
}
