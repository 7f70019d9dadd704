/**
 * Plain-text formulas written straight into JSX keep their parentheses on one line: a group such
 * as "(x + 2)²" or "1/(b − a)" (ui/texBreaks `textFormulaGroups`) must not hold a breakable space
 * in a JSX text of any component under src/, or the line may wrap inside it at some width. Such
 * text goes through `keepTextParenthesesTogether` (or `Superscripted`), which makes those spaces
 * no-break spaces. Text inside <code>, <kbd>, <samp> and <pre> is left alone (code, not prose).
 * The whole-page browser test checks the rendered page at one width; this checks every width.
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';
import { textFormulaGroups } from '../../src/ui/texBreaks';
import { filesUnder } from './sourceFiles';

const root = path.resolve(__dirname, '../..');
const CODE_TAGS = new Set(['code', 'kbd', 'samp', 'pre']);

function insideCode(node: ts.Node): boolean {
  for (let n: ts.Node | undefined = node.parent; n; n = n.parent) {
    if (ts.isJsxElement(n) && CODE_TAGS.has(n.openingElement.tagName.getText())) return true;
  }
  return false;
}

/** Each formula group with a breakable space in the JSX texts of `source`, as "line: group". */
function breakableFormulas(source: string, name = 'x.tsx'): string[] {
  const file = ts.createSourceFile(name, source, ts.ScriptTarget.Latest, true, ts.ScriptKind.TSX);
  const out: string[] = [];
  const visit = (node: ts.Node) => {
    if (ts.isJsxText(node) && !insideCode(node)) {
      // as JSX joins its lines: each line trimmed, lines joined by one space
      const text = node.text.replace(/\s*\n\s*/g, ' ');
      for (const [a, b] of textFormulaGroups(text)) {
        if (/[ \t]/.test(text.slice(a, b + 1))) {
          const line = file.getLineAndCharacterOfPosition(node.getStart()).line + 1;
          out.push(`${line}: ${text.slice(a, b + 1)}`);
        }
      }
    }
    ts.forEachChild(node, visit);
  };
  visit(file);
  return out;
}

describe('plain-text formulas in JSX', () => {
  it('finds a breakable group, also across source lines, and passes kept, code and prose ones', () => {
    expect(breakableFormulas('const a = <p>the pdf p = 1/(b − a) here</p>;')).toEqual(['1: (b − a)']);
    expect(breakableFormulas('const a = (\n  <p>\n    centres (i +\n    ½)/N\n  </p>\n);')).toEqual([
      '3: (i + ½)',
    ]);
    expect(
      breakableFormulas(
        "const a = <p>p = {keep('1/(b − a)')}, <code>(x + 2)^2</code> (a remark in prose)</p>;",
      ),
    ).toEqual([]);
  });

  it('no component under src/ writes a formula group that can break', () => {
    const found = filesUnder(path.join(root, 'src'), /\.tsx$/).flatMap((f) =>
      breakableFormulas(readFileSync(f, 'utf8'), f).map((o) => `${path.relative(root, f)}:${o}`),
    );
    expect(found).toEqual([]);
  });
});
