/**
 * The shared colours of plot lines and of the two Monte Carlo strategies, as CSS custom properties
 * (./palette.css sets them per theme, loaded with this module; tests/ui/palette.test.ts checks their contrast and that
 * they stay apart under colour-vision deficiencies). SVG and CSS use them as they are; Plotly traces
 * may give them as `var(--series-1)` (src/ui/Plot.tsx resolves them when it draws); a canvas or
 * WebGL view reads them with {@link resolveColor}.
 */
import './palette.css';

export const SERIES = ['var(--series-1)', 'var(--series-2)', 'var(--series-3)', 'var(--series-4)'] as const;
export const STRATEGY_COLOR = {
  uniform: 'var(--strategy-uniform)',
  importance: 'var(--strategy-importance)',
} as const;

const VAR_RE = /^var\(\s*(--[\w-]+)\s*(?:,\s*([^)]+))?\)$/;

/** `var(--x)` → the current value of --x on the root element (its fallback, or the text, if none). */
export function resolveColor(color: string, root?: Element): string {
  const m = VAR_RE.exec(color.trim());
  if (!m || typeof document === 'undefined') return color;
  const v = getComputedStyle(root ?? document.documentElement)
    .getPropertyValue(m[1]!)
    .trim();
  return v || m[2]?.trim() || color;
}

/**
 * A copy of Plotly traces with every `var(--…)` string in them (colours of lines, markers, fills)
 * replaced by its current value; data arrays are passed through untouched.
 */
export function resolveTraceColors<T>(value: T, root?: Element, depth = 0): T {
  if (typeof value === 'string') return (value.startsWith('var(') ? resolveColor(value, root) : value) as T;
  if (depth > 4 || value === null || typeof value !== 'object' || ArrayBuffer.isView(value)) return value;
  if (Array.isArray(value)) {
    if (value.length === 0 || typeof value[0] === 'number') return value;
    let changed = false;
    const out = value.map((v: unknown) => {
      const r = resolveTraceColors(v, root, depth + 1);
      if (r !== v) changed = true;
      return r;
    });
    return (changed ? out : value) as T;
  }
  let copy: Record<string, unknown> | null = null;
  for (const [k, v] of Object.entries(value as Record<string, unknown>)) {
    const r = resolveTraceColors(v, root, depth + 1);
    if (r !== v) (copy ??= { ...(value as Record<string, unknown>) })[k] = r;
  }
  return (copy ?? value) as T;
}
