/**
 * The shared colours of plot lines and of the two Monte Carlo strategies, as CSS custom properties
 * (./palette.css sets them per theme, loaded with this module; tests/ui/palette.test.ts checks their contrast and that
 * they stay apart under colour-vision deficiencies). SVG and CSS use them as they are; the Plot
 * component's traces may give them as `var(--series-1)` (src/ui/Plot.tsx resolves them when it
 * draws); a canvas or WebGL view reads them with {@link resolveColor}.
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
