/**
 * CSV for spreadsheets: every cell that a spreadsheet could read as a formula is made text, for a
 * comma-separated reader and for one that splits on semicolons or tabs (a `Ada;=3+3` cell is two
 * cells there), and the text starts with a byte-order mark so that accented names open right in
 * Excel. Also the class table the results page downloads (one row per student), here rather than
 * beside the collation so that the page does not load the grading code to offer it.
 */

import type { Collation } from './collate';
import { QUESTION_IDS } from '../practice/model';

const NUMBER = /^-?\d+(\.\d+)?(e[+-]?\d+)?$/i;
/** A formula's first character, at the start of a cell or after a separator some reader splits on. */
const FORMULA_START = /(^|[;,\t\r\n])(\s*)([=+\-@\t\r|])/g;

export function csvCell(x: string | number): string {
  const s = String(x);
  if (typeof x === 'number' || NUMBER.test(s)) return s;
  // a quote before each formula start: the reader shows it as text
  const safe = s.replace(FORMULA_START, (_m, sep: string, sp: string, c: string) => `${sep}${sp}'${c}`);
  return /[",;\t\n\r]/.test(safe) ? `"${safe.replace(/"/g, '""')}"` : safe;
}

/** Rows as CSV text (CRLF line ends, a leading byte-order mark). */
export function csvText(rows: readonly (readonly (string | number)[])[]): string {
  return '\uFEFF' + rows.map((r) => r.map(csvCell).join(',')).join('\r\n') + '\r\n';
}

/** One row per student: name, file, attempts, then each question's best score and max. */
export function studentsCsv(c: Collation): string {
  const head: (string | number)[] = [
    'student',
    'file',
    'attempts',
    ...QUESTION_IDS.flatMap((q) => [`${q} score`, `${q} max`]),
  ];
  const rows = c.students.map((s): (string | number)[] => [
    s.student,
    s.file,
    s.attempts,
    ...QUESTION_IDS.flatMap((q): (string | number)[] => {
      const b = s.best[q];
      return b ? [b.score, b.max] : ['', ''];
    }),
  ]);
  return csvText([head, ...rows]);
}
