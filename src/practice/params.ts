/**
 * URL parameters of the practice pages, declared as schemas and read by the kit's parser
 * (src/kit/params.ts), as the scenes read theirs: a question page `#/practice/qN?seed=…` and the
 * printed worksheet `#/practice/sheet?seed=…&q=1,3,5&count=…&solutions=1`. Every value the parser
 * cannot use is named in a notice, with what the page used instead; a parameter the page does not
 * take is named too (shell parameters such as embed and present are the shell's).
 */
import { parseParams, type ParamProblem, type ParamSchema } from '../kit/params';
import { queryProblems } from '../kit/shell';
import { MAX_SEED } from './links';
import { QUESTION_IDS, type QuestionId } from './model';

const SEED = { kind: 'number', min: 0, max: MAX_SEED, integer: true, label: 'variant seed' } as const;

/** A question page's parameters; a link without a usable seed gets `fallbackSeed` (a fresh variant). */
export function questionSchema(fallbackSeed: number) {
  return { seed: { ...SEED, default: fallbackSeed } } as const satisfies ParamSchema;
}

export const SHEET_SCHEMA = {
  seed: { ...SEED, default: 1, label: 'worksheet seed' },
  q: {
    kind: 'list',
    default: [1, 2, 3, 4, 5, 6],
    minItems: 1,
    maxItems: 12,
    min: 1,
    max: 6,
    label: 'questions',
  },
  count: { kind: 'number', default: 1, min: 1, max: 10, integer: true, label: 'variants of each question' },
  solutions: { kind: 'bool', default: false, label: 'with worked solutions' },
} as const satisfies ParamSchema;

/**
 * Parse against a schema: the schema's own parameters by the kit's parser (bad values, repeats),
 * the others named as not taken by this page.
 */
function parsePage<S extends ParamSchema>(schema: S, sp: URLSearchParams) {
  const own = new URLSearchParams([...sp].filter(([k]) => Object.hasOwn(schema, k)));
  const parsed = parseParams(schema, own);
  const others = queryProblems(sp.toString(), Object.keys(schema)).filter(
    (p) => !Object.hasOwn(schema, p.name),
  );
  return { values: parsed.values, problems: [...others, ...parsed.problems] };
}

export interface QuestionParams {
  seed: number;
  /** The link names its variant as it is (else the page writes the seed it used into the URL). */
  seedAsGiven: boolean;
  problems: ParamProblem[];
}

/** Read a question page's link: its seed, or `fallbackSeed` (named in a notice when one was given). */
export function parseQuestionParams(sp: URLSearchParams, fallbackSeed: number): QuestionParams {
  const { values, problems } = parsePage(questionSchema(fallbackSeed), sp);
  return {
    seed: values.seed,
    seedAsGiven: sp.has('seed') && !problems.some((p) => p.name === 'seed'),
    problems,
  };
}

export interface SheetParams {
  seed: number;
  qs: QuestionId[];
  count: number;
  solutions: boolean;
  problems: ParamProblem[];
}

/** Read the worksheet's link; anything unusable is named and replaced. */
export function parseSheetParams(sp: URLSearchParams): SheetParams {
  const { values, problems } = parsePage(SHEET_SCHEMA, sp);
  const ns = values.q ?? [...SHEET_SCHEMA.q.default];
  if (ns.some((n) => !Number.isInteger(n)))
    problems.push({ name: 'q', message: 'should list whole question numbers 1–6; they were rounded' });
  const qs = [...new Set(ns.map((n) => QUESTION_IDS[Math.round(n) - 1]))];
  return { seed: values.seed, qs, count: values.count, solutions: values.solutions, problems };
}
