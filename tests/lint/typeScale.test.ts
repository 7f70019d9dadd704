/**
 * The type scale (src/ui/theme.css, --text-xs … --text-xl): every font size a stylesheet gives HTML
 * text is one of its steps. A size in rem or em outside the scale fails here with its file and line.
 * Left free, on purpose: px sizes (SVG figure labels, drawn in the figure's own units), the tick
 * size variable, `inherit`, `max()` and `clamp()` (classroom minimums, page titles), 1em, and the
 * typeset formulas' 1.08em (KaTeX's own fonts, a fixed ratio to the text around them).
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { filesUnder } from './sourceFiles';

const root = path.resolve(__dirname, '../..');

const SCALE = /^var\(--text-(xs|s|m|l|xl)\)$/;
const FREE = [
  /^\d+(\.\d+)?px$/,
  /^var\(--tick-size, \d+(\.\d+)?px\)$/,
  /^inherit$/,
  /^(max|clamp)\(.*\)$/,
  /^1em$/,
  /^1\.08em$/,
];

/** Every `font-size: …` declaration of a stylesheet that is neither a scale step nor free, as "line: value". */
function offScale(css: string): string[] {
  const out: string[] = [];
  css.split('\n').forEach((line, i) => {
    const m = /(?<![-\w])font-size\s*:\s*([^;]+);/.exec(line);
    if (!m) return;
    const v = m[1]!.trim();
    if (SCALE.test(v) || FREE.some((r) => r.test(v))) return;
    out.push(`${i + 1}: ${v}`);
  });
  return out;
}

describe('the type scale', () => {
  it('finds a size off the scale, and passes the scale and the free forms', () => {
    expect(offScale('.a {\n  font-size: 0.85rem;\n}\n.b { font-size: 0.9em; }')).toEqual([
      '2: 0.85rem',
      '4: 0.9em',
    ]);
    expect(
      offScale(
        '.a { font-size: var(--text-s); }\n.b { font-size: 13px; }\n.c { --plot-font-size: 13; }\n' +
          '.d { font-size: max(0.8em, 18px); }\n.e { font-size: var(--tick-size, 12px); }',
      ),
    ).toEqual([]);
  });

  it('every stylesheet under src/ sizes its text on the scale', () => {
    const found = filesUnder(path.join(root, 'src'), /\.css$/).flatMap((f) =>
      offScale(readFileSync(f, 'utf8')).map((o) => `${path.relative(root, f)}:${o}`),
    );
    expect(found).toEqual([]);
  });
});
