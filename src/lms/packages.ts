/**
 * The LMS packages: SCORM 1.2, SCORM 2004 (4th edition) and cmi5 zips whose launch page is the
 * app (the single-file build, or the static build's files), and the question banks. Pure: the
 * caller hands in the app's files and gets the packages' bytes (the Node script and the practice
 * sheet page share this).
 *
 * The launch page is the app's own index.html with one meta tag added at the top of <head> (after
 * the charset) that declares the package (its kind, questions, seed and mastery score: ./config.ts);
 * the app's entry sees it and loads the LMS runtime (src/lms/launch.ts) before rendering. Without
 * that tag the app never loads any LMS code. The app's Content-Security-Policy stays as built, but for cmi5, whose
 * learning record store is named only at launch: its connect-src admits any http(s) origin.
 */
import { strToU8, zipSync, type Zippable } from 'fflate';
import type { QuestionId } from '../practice/model';
import { questionInfo } from '../practice/questions';
import { bankVariants, moodleXml, qtiPackageFiles, type BankChoice, type TexToMathml } from './banks';
import { xmlEscape } from './gaps';
import { lmsConfigMeta, type LmsConfig, type LmsKind } from './config';

export interface PackageChoice extends BankChoice {
  mastery: number;
  version: string;
}

export const TITLE = 'Render Math Lab practice';

function title(c: Pick<BankChoice, 'questions'>): string {
  return `${TITLE}: ${c.questions.map((q) => `Q${questionInfo(q).n}`).join(', ')}`;
}

/** The launch page: the app's index.html with the LMS configuration in front (and, for cmi5, its LRS allowed). */
export function launchHtml(appHtml: string, config: LmsConfig): string {
  const tag = lmsConfigMeta(config);
  const html =
    config.kind === 'cmi5'
      ? appHtml.replace(
          /(<meta http-equiv="Content-Security-Policy" content="[^"]*connect-src )'self'/i,
          "$1'self' https: http:",
        )
      : appHtml;
  // after the charset (first 1024 bytes) where there is one, else at the top of <head>
  const at = /<meta charset[^>]*>/i.exec(html) ?? /<head[^>]*>/i.exec(html);
  if (!at) return `${tag}${html}`;
  const end = at.index + at[0].length;
  return `${html.slice(0, end)}${tag}${html.slice(end)}`;
}

function fileList(files: readonly string[], indent: string): string {
  return files.map((f) => `${indent}<file href="${xmlEscape(f)}"/>`).join('\n');
}

/** The parts in which the two SCORM versions' manifests differ. */
interface ScormFlavour {
  id: string;
  version: string;
  namespaces: string;
  schemaVersion: string;
  /** What the item carries besides its title (the mastery score, in each version's own form). */
  itemExtra: string;
  /** The attribute naming a resource a SCO (its case differs between the versions). */
  scormTypeAttr: string;
}

function scormManifest(c: PackageChoice, files: readonly string[], f: ScormFlavour): string {
  const t = xmlEscape(title(c));
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="render-math-lab-practice-${f.id}-${c.seed}" version="${f.version}"
${f.namespaces}>
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>${f.schemaVersion}</schemaversion>
  </metadata>
  <organizations default="ORG-1">
    <organization identifier="ORG-1">
      <title>${t}</title>
      <item identifier="ITEM-1" identifierref="SCO-1" isvisible="true">
        <title>${t}</title>
${f.itemExtra}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="SCO-1" type="webcontent" ${f.scormTypeAttr}="sco" href="index.html">
${fileList(files, '      ')}
    </resource>
  </resources>
</manifest>
`;
}

export function scorm12Manifest(c: PackageChoice, files: readonly string[]): string {
  return scormManifest(c, files, {
    id: 'scorm12',
    version: '1.0',
    namespaces: `  xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd"`,
    schemaVersion: '1.2',
    itemExtra: `        <adlcp:masteryscore>${Math.round(c.mastery * 100)}</adlcp:masteryscore>`,
    scormTypeAttr: 'adlcp:scormtype',
  });
}

export function scorm2004Manifest(c: PackageChoice, files: readonly string[]): string {
  return scormManifest(c, files, {
    id: 'scorm2004',
    version: '1',
    namespaces: `  xmlns="http://www.imsglobal.org/xsd/imscp_v1p1"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3"
  xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3"
  xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3"
  xmlns:imsss="http://www.imsglobal.org/xsd/imsss"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd"`,
    schemaVersion: '2004 4th Edition',
    itemExtra: `        <imsss:sequencing>
          <imsss:objectives>
            <imsss:primaryObjective objectiveID="mastery" satisfiedByMeasure="true">
              <imsss:minNormalizedMeasure>${c.mastery}</imsss:minNormalizedMeasure>
            </imsss:primaryObjective>
          </imsss:objectives>
        </imsss:sequencing>`,
    scormTypeAttr: 'adlcp:scormType',
  });
}

/** The AU of one question: `index.html?rml-au=q3` (the LMS appends its launch parameters). */
export function auUrl(q: QuestionId): string {
  return `index.html?rml-au=${q}`;
}

export function auId(c: Pick<BankChoice, 'seed'>, q: QuestionId): string {
  return `https://render-math-lab.invalid/cmi5/${c.seed}/${q}`;
}

export function cmi5Xml(c: PackageChoice): string {
  const t = xmlEscape(title(c));
  const aus = c.questions.map((q) => {
    const info = questionInfo(q);
    return `  <au id="${auId(c, q)}" moveOn="CompletedAndPassed" masteryScore="${c.mastery}" launchMethod="AnyWindow">
    <title><langstring lang="en-US">${xmlEscape(`Q${info.n} ${info.title}`)}</langstring></title>
    <description><langstring lang="en-US">${xmlEscape(info.blurb)}</langstring></description>
    <url>${xmlEscape(auUrl(q))}</url>
  </au>`;
  });
  return `<?xml version="1.0" encoding="UTF-8"?>
<courseStructure xmlns="https://w3id.org/xapi/profiles/cmi5/v1/CourseStructure.xsd">
  <course id="https://render-math-lab.invalid/cmi5/${c.seed}">
    <title><langstring lang="en-US">${t}</langstring></title>
    <description><langstring lang="en-US">Seeded practice variants of the exam questions; each learner gets their own numbers.</langstring></description>
  </course>
${aus.join('\n')}
</courseStructure>
`;
}

export interface PackageOutputs {
  'practice-scorm12.zip': Uint8Array;
  'practice-scorm2004.zip': Uint8Array;
  'practice-cmi5.zip': Uint8Array;
  'questions-moodle.xml': Uint8Array;
  'questions-qti21.zip': Uint8Array;
}

/**
 * Every package. `app` maps the app's file paths (index.html and, for the static build, its
 * assets) to their bytes; index.html becomes each package's launch page.
 */
export function buildPackages(
  c: PackageChoice,
  app: Readonly<Record<string, Uint8Array>>,
  toMathml?: TexToMathml,
): PackageOutputs {
  const html = new TextDecoder().decode(app['index.html']);
  const names = Object.keys(app).sort();
  const zipOf = (kind: LmsKind, extra: Record<string, string>): Uint8Array => {
    const z: Zippable = {};
    for (const n of names) if (n !== 'index.html') z[n] = app[n];
    const cfg: LmsConfig = {
      kind,
      questions: [...c.questions],
      seed: c.seed,
      mastery: c.mastery,
      version: c.version,
    };
    z['index.html'] = strToU8(launchHtml(html, cfg));
    for (const [k, v] of Object.entries(extra)) z[k] = strToU8(v);
    // already-compressed images are stored; text is deflated
    return zipSync(z, { level: 6, mtime: new Date('2024-01-01T00:00:00Z') });
  };
  const variants = bankVariants(c);
  const qti: Zippable = {};
  for (const [k, v] of Object.entries(qtiPackageFiles(variants, toMathml))) qti[k] = strToU8(v);
  return {
    'practice-scorm12.zip': zipOf('scorm12', { 'imsmanifest.xml': scorm12Manifest(c, names) }),
    'practice-scorm2004.zip': zipOf('scorm2004', { 'imsmanifest.xml': scorm2004Manifest(c, names) }),
    'practice-cmi5.zip': zipOf('cmi5', { 'cmi5.xml': cmi5Xml(c) }),
    'questions-moodle.xml': strToU8(moodleXml(variants, c.version)),
    'questions-qti21.zip': zipSync(qti, { level: 6, mtime: new Date('2024-01-01T00:00:00Z') }),
  };
}
