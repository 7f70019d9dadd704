/**
 * A bare whole-number input for small settings (a pass mark, a count): what is typed is rounded and
 * clamped to [min, max]; anything unreadable (an empty box, text) becomes `fallback`.
 */
export function IntInput({
  min,
  max,
  value,
  fallback,
  onChange,
}: {
  min: number;
  max: number;
  value: number;
  fallback: number;
  onChange: (v: number) => void;
}) {
  return (
    <input
      type="number"
      min={min}
      max={max}
      value={value}
      onChange={(e) => onChange(Math.min(max, Math.max(min, Math.round(Number(e.target.value)) || fallback)))}
    />
  );
}
