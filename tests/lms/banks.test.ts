/**
 * Question banks read back: the Moodle XML and QTI 2.1 files parse, hold N × questions items, each
 * item's answers are the generator's for its seed (recomputed here from the seed, formulas at the
 * point the item states), with the app's tolerance, and every named mistake's feedback is there.
 */
import { describe, expect, it } from 'vitest';
import { XMLParser } from 'fast-xml-parser';
import { unzipSync } from 'fflate';
import { bankVariants, moodleXml, parseItemId, qtiPackageFiles } from '../../src/lms/banks';
import { buildPackages } from '../../src/lms/packages';
import { variantOf } from '../../src/lms/grade';
import { allAnswers, QUESTION_IDS, type AnswerSpec, type QuestionId } from '../../src/practice/model';
import { katexMathml } from '../../src/lms/mathml';
import katex from 'katex';

/** The band the app allows a 3-significant-figure decimal: half a unit in the third figure. */
const band = (x: number) => (x === 0 ? 1e-15 : 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(x))) - 2));
const near = (a: number, b: number) => Math.abs(a - b) <= band(a) + band(b);
const N = 3;
const SEED = 40;
const QS: QuestionId[] = [...QUESTION_IDS];
const variants = bankVariants({ questions: QS, variants: N, seed: SEED });
const parser = new XMLParser({
  ignoreAttributes: false,
  attributeNamePrefix: '@',
  cdataPropName: '#cdata',
  parseTagValue: false,
});
const arr = <T>(x: T | T[] | undefined): T[] => (x === undefined ? [] : Array.isArray(x) ? x : [x]);

/** The expected value of an answer at the point a prompt names ("… at theta = 0.471 …"). */
function expectedAt(spec: AnswerSpec, prompt: string): number | null {
  if (spec.kind === 'number') return spec.expected;
  if (spec.kind !== 'formula') return null;
  const m = new RegExp(`at ${spec.variables[0]} = (-?[\\d.e+-]+)`).exec(prompt);
  expect(m, `the prompt "${prompt}" names its point`).not.toBeNull();
  return spec.expected(Number(m![1]));
}

const unescapeCloze = (s: string) =>
  s
    .replace(/\\(.)/g, '$1')
    .replace(/&quot;/g, '"')
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&amp;/g, '&');

describe('Moodle XML bank', () => {
  const xml = moodleXml(variants, 'test');
  const doc = parser.parse(xml);
  const questions = arr(doc.quiz.question).filter((q: any) => q['@type'] === 'cloze');

  it(`holds ${N} × ${QS.length} Cloze questions, one per seeded variant`, () => {
    expect(questions).toHaveLength(N * QS.length);
    const ids = questions.map((q: any) => parseItemId(q.idnumber));
    expect(new Set(ids.map((i: any) => `${i.question}-${i.seed}`)).size).toBe(N * QS.length);
    for (const q of QS) expect(ids.filter((i: any) => i.question === q)).toHaveLength(N);
  });

  it('each numeric gap is the expected value for its seed with the app tolerance; mistakes carry feedback', () => {
    let gapsChecked = 0;
    let mistakesChecked = 0;
    for (const q of questions) {
      const id = parseItemId(q.idnumber)!;
      const v = variantOf(id.question, id.seed);
      const text: string = q.questiontext.text['#cdata'];
      expect(q.generalfeedback.text['#cdata']).toContain('Worked solution');
      for (const spec of allAnswers(v)) {
        const row = new RegExp(
          `<p>${spec.label.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}[^<]*?: \\{1:(NUMERICAL|MULTICHOICE|SHORTANSWER):((?:\\\\.|[^}\\\\])*)\\}`,
        ).exec(text);
        expect(row, `${id.question}/${id.seed} has a gap for ${spec.name}`).not.toBeNull();
        const [, type, body] = row!;
        const prompt = row![0];
        const parts = body.split(/(?<!\\)~/);
        if (spec.kind === 'choice') {
          expect(type).toBe('MULTICHOICE');
          expect(parts.find((p) => p.startsWith('='))!.split('#')[0]).toBe(`=${spec.expected}`);
          for (const m of spec.mistakes) {
            expect(unescapeCloze(body)).toContain(m.message);
            mistakesChecked++;
          }
        } else {
          const e = expectedAt(spec, prompt);
          if (e === null) {
            expect(type).toBe('SHORTANSWER');
            expect(parts[0]).toMatch(/^=none#/);
          } else {
            expect(type).toBe('NUMERICAL');
            const [val, tol] = parts[0].slice(1).split('#')[0].split(':').map(Number);
            expect(Math.abs(val - e)).toBeLessThanOrEqual(1e-9 * Math.max(1, Math.abs(e)));
            expect(tol / band(e)).toBeCloseTo(1, 4);
            if (spec.kind === 'number')
              spec.mistakes.forEach((m, k) => {
                const shadows = [
                  e,
                  ...spec.alternatives.map((a) => a.value),
                  ...spec.mistakes.slice(0, k).map((x) => x.value),
                ];
                const hit = parts.find(
                  (p) =>
                    p.startsWith('%0%') &&
                    p.slice(3).split(':')[0] !== '*' &&
                    near(Number(p.slice(3).split(':')[0]), m.value),
                );
                if (!hit) {
                  expect(
                    shadows.some((x) => near(x, m.value)),
                    `${id.question}/${id.seed} ${spec.name} mistake ${m.id} is in the bank`,
                  ).toBe(true);
                  return;
                }
                const messages = spec.mistakes.filter((x) => near(x.value, m.value)).map((x) => x.message);
                expect(messages.some((msg) => unescapeCloze(hit).includes(msg))).toBe(true);
                if (unescapeCloze(hit).includes(m.message)) mistakesChecked++;
              });
          }
        }
        gapsChecked++;
      }
    }
    expect(gapsChecked).toBe(variants.reduce((n, v) => n + allAnswers(v).length, 0));
    expect(mistakesChecked).toBeGreaterThan(50);
  });
});

describe('QTI 2.1 package', () => {
  const files = qtiPackageFiles(variants, katexMathml(katex));

  it(`its manifest lists ${N} × ${QS.length} items, all present`, () => {
    const m = parser.parse(files['imsmanifest.xml']);
    const res = arr(m.manifest.resources.resource);
    expect(res).toHaveLength(N * QS.length);
    for (const r of res) {
      expect(r['@type']).toBe('imsqti_item_xmlv2p1');
      expect(files[r['@href']]).toBeTruthy();
    }
  });

  it('each item declares the expected responses for its seed, tolerances and the mistakes’ modal feedback', () => {
    let checked = 0;
    for (const [path, text] of Object.entries(files)) {
      if (!path.startsWith('items/')) continue;
      const item = parser.parse(text).assessmentItem;
      const id = parseItemId(item['@identifier'])!;
      const v = variantOf(id.question, id.seed);
      const decls = arr(item.responseDeclaration);
      const feedback = arr(item.modalFeedback);
      expect(feedback.some((f: any) => f['@identifier'] === 'SOLUTION')).toBe(true);
      const body = text.slice(text.indexOf('<itemBody>'), text.indexOf('</itemBody>'));
      for (const spec of allAnswers(v)) {
        const d = decls.find((x: any) => x['@identifier'] === `RESPONSE_${spec.name}`);
        expect(d, `${item['@identifier']} declares ${spec.name}`).toBeTruthy();
        const value = String(d.correctResponse.value);
        if (spec.kind === 'choice') {
          expect(d['@baseType']).toBe('identifier');
          expect(value).toBe(`C_${spec.expected}`);
        } else {
          const prompt = new RegExp(
            `${spec.label.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}[^<]*?: <textEntryInteraction responseIdentifier="RESPONSE_${spec.name}"`,
          ).exec(body);
          expect(prompt, `${item['@identifier']} asks for ${spec.name}`).not.toBeNull();
          const e = expectedAt(spec, prompt![0]);
          if (e === null) expect(value).toBe('none');
          else {
            expect(d['@baseType']).toBe('float');
            expect(Math.abs(Number(value) - e)).toBeLessThanOrEqual(1e-9 * Math.max(1, Math.abs(e)));
            const tol = new RegExp(
              `<equal toleranceMode="absolute" tolerance="([^ "]+) [^"]+"><variable identifier="RESPONSE_${spec.name}"/><correct`,
            ).exec(text);
            expect(tol, `${spec.name} has a tolerance`).not.toBeNull();
            expect(Number(tol![1]) / band(e)).toBeCloseTo(1, 4);
          }
        }
        if (spec.kind === 'number' && spec.expected !== null)
          for (const m of spec.mistakes) {
            if (near(m.value, spec.expected)) continue;
            expect(
              feedback.some((f: any) => String(f.p).includes(m.message.slice(0, 40))),
              `${spec.name} ${m.id}`,
            ).toBe(true);
          }
        checked++;
      }
    }
    expect(checked).toBe(variants.reduce((n, v) => n + allAnswers(v).length, 0));
  });

  it('the zips unzip to the same files, and the worked solution is MathML', () => {
    const out = buildPackages(
      { questions: ['q1'], variants: 2, seed: 3, mastery: 0.8, version: 't' },
      { 'index.html': new TextEncoder().encode('<html><head></head><body></body></html>') },
      katexMathml(katex),
    );
    const qti = unzipSync(out['questions-qti21.zip']);
    expect(Object.keys(qti).sort()).toEqual(['imsmanifest.xml', 'items/rml-q1-3.xml', 'items/rml-q1-4.xml']);
    expect(new TextDecoder().decode(qti['items/rml-q1-3.xml'])).toContain(
      '<math xmlns="http://www.w3.org/1998/Math/MathML"',
    );
    const scorm = unzipSync(out['practice-scorm12.zip']);
    expect(new TextDecoder().decode(scorm['index.html'])).toMatch(
      /^<html><head><meta name="rml-lms" content="\{&quot;kind&quot;:&quot;scorm12&quot;,&quot;questions&quot;:\[&quot;q1&quot;\],&quot;seed&quot;:3/,
    );
  });
});
