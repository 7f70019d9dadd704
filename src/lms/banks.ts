/**
 * Question banks from the practice generators: Moodle XML (one Cloze question per variant) and
 * QTI 2.1 (one assessmentItem per variant, in an IMS content package). See gaps.ts for how each
 * answer becomes a gap.
 *
 * Formulas: Moodle shows TeX between \( \) and \[ \] through its MathJax filter (on by default in
 * Moodle 4.x), so the givens and the worked solution keep the app's TeX. QTI 2.1 embeds MathML
 * (its own format for mathematics); `toMathml` turns the TeX into MathML (KaTeX), and without it
 * the TeX is kept as text.
 */
import type { QuestionId, Variant } from '../practice/model';
import { questionInfo } from '../practice/questions';
import { sheetSeed } from '../practice/questionList';
import { gapsOf, num, xmlEscape, type Gap } from './gaps';
import { variantOf } from './grade';

export interface BankChoice {
  questions: readonly QuestionId[];
  /** Variants per question. */
  variants: number;
  /** Base seed: the k-th variant of each question has seed sheetSeed(seed, k), as on a worksheet. */
  seed: number;
}

export function bankVariants(c: BankChoice): Variant[] {
  return c.questions.flatMap((q) =>
    Array.from({ length: c.variants }, (_, k) => variantOf(q, sheetSeed(c.seed, k))),
  );
}

/** The id a bank gives a variant: rml-q3-17 (read back by the tests and by the results page). */
export function itemId(v: Pick<Variant, 'question' | 'seed'>): string {
  return `rml-${v.question}-${v.seed}`;
}

export function parseItemId(id: string): { question: QuestionId; seed: number } | null {
  const m = /^rml-(q[1-6])-(\d{1,10})$/.exec(id);
  return m ? { question: m[1] as QuestionId, seed: Number(m[2]) } : null;
}

function cdata(html: string): string {
  return `<![CDATA[${html.replace(/]]>/g, ']]]]><![CDATA[>')}]]>`;
}

function gridHtml(text: string): string {
  const rows = text.split(';').map((r) => r.split(','));
  return `<table border="1" cellpadding="4">${rows
    .map((r) => `<tr>${r.map((x) => `<td>${xmlEscape(x)}</td>`).join('')}</tr>`)
    .join('')}</table><p>Rows from v = 1 (top) to v = 0 (bottom), columns from u = 0 to u = 1.</p>`;
}

function givensHtml(v: Variant, tex: (t: string, display: boolean) => string): string {
  return `<ul>${v.givens
    .map(
      (g) =>
        `<li>${xmlEscape(g.label)}: ${g.name === 'grid' ? gridHtml(g.value) : g.tex ? tex(g.tex, false) : xmlEscape(g.display)}</li>`,
    )
    .join('')}</ul>`;
}

function solutionHtml(v: Variant, tex: (t: string, display: boolean) => string): string {
  return v.solution
    .map((s) => `${s.text ? `<p>${xmlEscape(s.text)}</p>` : ''}${s.tex ? tex(s.tex, true) : ''}`)
    .join('\n');
}

// ---------------------------------------------------------------------------------------------
// Moodle XML

/** Text inside a Cloze gap: these characters must be backslash-escaped there. */
function clozeText(s: string): string {
  return xmlEscape(s).replace(/[\\}#~/"]/g, (c) => `\\${c}`);
}

function clozeGap(g: Gap): string {
  if (g.kind === 'choice') {
    const parts = g.options.map((o) => {
      if (o === g.expected) return `=${clozeText(o)}#${clozeText(`Correct. ${g.why}`)}`;
      const m = g.mistakes.find((x) => x.value === o);
      return `%0%${clozeText(o)}#${clozeText(m ? m.message : `Not right. ${g.why}`)}`;
    });
    return `{1:MULTICHOICE:${parts.join('~')}}`;
  }
  if (g.kind === 'none')
    return `{1:SHORTANSWER:=none#Correct.~%0%*#${clozeText('Not right: this quantity does not exist here (answer none).')}}`;
  const parts = [
    `=${num(g.value)}:${num(g.tol)}#Correct.`,
    ...g.alternatives.map((a) => `=${num(a.value)}:${num(g.tol)}#${clozeText(`Correct — ${a.message}`)}`),
    ...g.mistakes.map(
      (m) => `%0%${num(m.value as number)}:${num(g.tol)}#${clozeText(`${m.message} [${m.id}]`)}`,
    ),
    `%0%*#${clozeText('Not right. Check each step against the worked solution.')}`,
  ];
  return `{1:NUMERICAL:${parts.join('~')}}`;
}

const moodleTex = (t: string, display: boolean) =>
  display ? `<p>\\[${xmlEscape(t)}\\]</p>` : `\\(${xmlEscape(t)}\\)`;

export function moodleXml(variants: readonly Variant[], appVersion: string): string {
  const out: string[] = ['<?xml version="1.0" encoding="UTF-8"?>', '<quiz>'];
  let category = '';
  for (const v of variants) {
    const info = questionInfo(v.question);
    const cat = `$course$/top/Render Math Lab/Q${info.n} ${info.title}`;
    if (cat !== category) {
      category = cat;
      out.push(
        `  <question type="category"><category><text>${xmlEscape(cat)}</text></category><info format="html"><text>${cdata(`Seeded variants from Render Math Lab ${appVersion}.`)}</text></info></question>`,
      );
    }
    const gaps = gapsOf(v);
    const body = [
      `<p>${xmlEscape(v.statement)}</p>`,
      givensHtml(v, moodleTex),
      ...v.parts.map((p) => {
        const own = gaps.filter((g) => p.answers.some((a) => a.name === g.name));
        return `<p><strong>${xmlEscape(p.prompt)}</strong></p>${own
          .map((g) => `<p>${xmlEscape(g.prompt)}: ${clozeGap(g)}</p>`)
          .join('')}`;
      }),
      `<p><small>Give numbers to at least 3 significant figures.</small></p>`,
    ].join('\n');
    out.push(
      [
        `  <question type="cloze">`,
        `    <name><text>${xmlEscape(`Q${info.n} ${v.title} (variant ${v.seed})`)}</text></name>`,
        `    <questiontext format="html"><text>${cdata(body)}</text></questiontext>`,
        `    <generalfeedback format="html"><text>${cdata(`<p><strong>Worked solution of variant ${v.seed}</strong></p>${solutionHtml(v, moodleTex)}`)}</text></generalfeedback>`,
        `    <penalty>0.3333333</penalty>`,
        `    <hidden>0</hidden>`,
        `    <idnumber>${itemId(v)}</idnumber>`,
        `  </question>`,
      ].join('\n'),
    );
  }
  out.push('</quiz>', '');
  return out.join('\n');
}

// ---------------------------------------------------------------------------------------------
// QTI 2.1

export type TexToMathml = (tex: string, display: boolean) => string;

const QTI_NS = 'http://www.imsglobal.org/xsd/imsqti_v2p1';
const QTI_XSD = 'http://www.imsglobal.org/xsd/qti/qtiv2p1/imsqti_v2p1p2.xsd';

function ident(s: string): string {
  return s.replace(/[^A-Za-z0-9_.-]/g, '_');
}

function tolAttrs(g: { tol: number }): string {
  // the bank's band around the value (gaps.ts bankTolerance), as an absolute tolerance
  return `toleranceMode="absolute" tolerance="${num(g.tol)} ${num(g.tol)}"`;
}

function addScore(): string {
  return '<setOutcomeValue identifier="SCORE"><sum><variable identifier="SCORE"/><baseValue baseType="float">1</baseValue></sum></setOutcomeValue>';
}

function addFeedback(id: string): string {
  return `<setOutcomeValue identifier="FEEDBACK"><multiple><variable identifier="FEEDBACK"/><baseValue baseType="identifier">${id}</baseValue></multiple></setOutcomeValue>`;
}

/** The feedback identifier of a gap's mistake (unique in its item). */
export function feedbackId(gap: string, k: number): string {
  return ident(`M_${gap}_${k}`);
}

export function qtiItem(v: Variant, toMathml?: TexToMathml): string {
  const tex: TexToMathml =
    toMathml ?? ((t, d) => (d ? `<p><code>${xmlEscape(t)}</code></p>` : `<code>${xmlEscape(t)}</code>`));
  const gaps = gapsOf(v);
  const info = questionInfo(v.question);
  const decl: string[] = [];
  const rp: string[] = [];
  const fb: string[] = [];
  for (const g of gaps) {
    const r = ident(`RESPONSE_${g.name}`);
    if (g.kind === 'number') {
      decl.push(
        `<responseDeclaration identifier="${r}" cardinality="single" baseType="float"><correctResponse><value>${num(g.value)}</value></correctResponse></responseDeclaration>`,
      );
      const branches = [
        `<responseIf><equal ${tolAttrs(g)}><variable identifier="${r}"/><correct identifier="${r}"/></equal>${addScore()}</responseIf>`,
        ...g.alternatives.map(
          (a) =>
            `<responseElseIf><equal ${tolAttrs(g)}><variable identifier="${r}"/><baseValue baseType="float">${num(a.value)}</baseValue></equal>${addScore()}</responseElseIf>`,
        ),
        ...g.mistakes.map(
          (m, k) =>
            `<responseElseIf><equal ${tolAttrs(g)}><variable identifier="${r}"/><baseValue baseType="float">${num(m.value as number)}</baseValue></equal>${addFeedback(feedbackId(g.name, k))}</responseElseIf>`,
        ),
      ];
      rp.push(`<responseCondition>${branches.join('')}</responseCondition>`);
    } else if (g.kind === 'none') {
      decl.push(
        `<responseDeclaration identifier="${r}" cardinality="single" baseType="string"><correctResponse><value>none</value></correctResponse></responseDeclaration>`,
      );
      rp.push(
        `<responseCondition><responseIf><stringMatch caseSensitive="false"><variable identifier="${r}"/><correct identifier="${r}"/></stringMatch>${addScore()}</responseIf></responseCondition>`,
      );
    } else {
      decl.push(
        `<responseDeclaration identifier="${r}" cardinality="single" baseType="identifier"><correctResponse><value>${ident(`C_${g.expected}`)}</value></correctResponse></responseDeclaration>`,
      );
      const branches = [
        `<responseIf><match><variable identifier="${r}"/><correct identifier="${r}"/></match>${addScore()}</responseIf>`,
        ...g.mistakes.map(
          (m, k) =>
            `<responseElseIf><match><variable identifier="${r}"/><baseValue baseType="identifier">${ident(`C_${m.value}`)}</baseValue></match>${addFeedback(feedbackId(g.name, k))}</responseElseIf>`,
        ),
      ];
      rp.push(`<responseCondition>${branches.join('')}</responseCondition>`);
    }
    g.mistakes.forEach((m, k) =>
      fb.push(
        `<modalFeedback outcomeIdentifier="FEEDBACK" identifier="${feedbackId(g.name, k)}" showHide="show" title="${xmlEscape(`${g.label}: ${m.id}`)}"><p>${xmlEscape(m.message)}</p></modalFeedback>`,
      ),
    );
  }
  rp.push(
    `<setOutcomeValue identifier="FEEDBACK"><multiple><variable identifier="FEEDBACK"/><baseValue baseType="identifier">SOLUTION</baseValue></multiple></setOutcomeValue>`,
  );
  fb.push(
    `<modalFeedback outcomeIdentifier="FEEDBACK" identifier="SOLUTION" showHide="show" title="Worked solution"><div>${solutionHtml(v, tex)}</div></modalFeedback>`,
  );
  const interactions = v.parts
    .map((p) => {
      const own = gaps.filter((g) => p.answers.some((a) => a.name === g.name));
      return `<div><p><strong>${xmlEscape(p.prompt)}</strong></p>${own
        .map((g) => {
          const r = ident(`RESPONSE_${g.name}`);
          if (g.kind === 'choice')
            return `<choiceInteraction responseIdentifier="${r}" shuffle="false" maxChoices="1"><prompt>${xmlEscape(g.prompt)}</prompt>${g.options
              .map((o) => `<simpleChoice identifier="${ident(`C_${o}`)}">${xmlEscape(o)}</simpleChoice>`)
              .join('')}</choiceInteraction>`;
          return `<p>${xmlEscape(g.prompt)}: <textEntryInteraction responseIdentifier="${r}" expectedLength="16"/></p>`;
        })
        .join('')}</div>`;
    })
    .join('\n');
  return [
    '<?xml version="1.0" encoding="UTF-8"?>',
    `<assessmentItem xmlns="${QTI_NS}" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="${QTI_NS} ${QTI_XSD}" identifier="${itemId(v)}" title="${xmlEscape(`Q${info.n} ${v.title} (variant ${v.seed})`)}" adaptive="false" timeDependent="false">`,
    ...decl,
    '<outcomeDeclaration identifier="SCORE" cardinality="single" baseType="float"><defaultValue><value>0</value></defaultValue></outcomeDeclaration>',
    `<outcomeDeclaration identifier="MAXSCORE" cardinality="single" baseType="float"><defaultValue><value>${gaps.length}</value></defaultValue></outcomeDeclaration>`,
    '<outcomeDeclaration identifier="FEEDBACK" cardinality="multiple" baseType="identifier"/>',
    `<itemBody><div><p>${xmlEscape(v.statement)}</p>${givensHtml(v, tex)}</div>\n${interactions}\n<p>Give numbers to at least 3 significant figures.</p></itemBody>`,
    `<responseProcessing>${rp.join('')}</responseProcessing>`,
    ...fb,
    '</assessmentItem>',
    '',
  ].join('\n');
}

/** The QTI 2.1 content package's files: imsmanifest.xml and items/<id>.xml. */
export function qtiPackageFiles(
  variants: readonly Variant[],
  toMathml?: TexToMathml,
): Record<string, string> {
  const files: Record<string, string> = {};
  const res: string[] = [];
  for (const v of variants) {
    const href = `items/${itemId(v)}.xml`;
    files[href] = qtiItem(v, toMathml);
    res.push(
      `    <resource identifier="RES-${itemId(v)}" type="imsqti_item_xmlv2p1" href="${href}"><file href="${href}"/></resource>`,
    );
  }
  files['imsmanifest.xml'] = [
    '<?xml version="1.0" encoding="UTF-8"?>',
    '<manifest xmlns="http://www.imsglobal.org/xsd/imscp_v1p1" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" identifier="MANIFEST-render-math-lab-qti" xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 http://www.imsglobal.org/xsd/qti/qtiv2p1/qtiv2p1_imscpv1p2_v1p0.xsd">',
    '  <metadata><schema>QTIv2.1 Package</schema><schemaversion>1.0.0</schemaversion></metadata>',
    '  <organizations/>',
    '  <resources>',
    ...res,
    '  </resources>',
    '</manifest>',
    '',
  ].join('\n');
  return files;
}
