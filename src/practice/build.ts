/** Small builders shared by the question generators (pure). */
import { separateFormulas, separateNumbers } from './check';
import type {
  ChoiceAnswer,
  ChoiceMistake,
  FormulaAnswer,
  FormulaAlternative,
  FormulaMistake,
  Fn,
  NumberAlternative,
  NumberAnswer,
} from './model';
import { Rng } from '../core/random';

export function numberAnswer(
  name: string,
  label: string,
  expected: number | null,
  alternatives: NumberAlternative[],
  mistakes: { id: string; value: number | null; message: string }[],
): NumberAnswer {
  return { kind: 'number', name, label, expected, ...separateNumbers(expected, alternatives, mistakes) };
}

export function formulaAnswer(
  name: string,
  label: string,
  variable: string,
  domain: readonly [number, number],
  expected: Fn,
  expectedText: string,
  alternatives: FormulaAlternative[],
  mistakes: FormulaMistake[],
): FormulaAnswer {
  const d = [domain] as const;
  return {
    kind: 'formula',
    name,
    label,
    variables: [variable],
    domain: d,
    expected,
    expectedText,
    ...separateFormulas(expected, d, alternatives, mistakes),
  };
}

export function choiceAnswer(
  name: string,
  label: string,
  options: readonly string[],
  expected: string,
  mistakes: ChoiceMistake[],
  why: string,
): ChoiceAnswer {
  return {
    kind: 'choice',
    name,
    label,
    options,
    expected,
    mistakes: mistakes.filter((m) => m.value !== expected),
    why,
  };
}

/** One element of a list, drawn uniformly. */
export function pick<T>(rng: Rng, xs: readonly T[]): T {
  return xs[rng.nextInt(xs.length)];
}

/** A uniform integer in [lo, hi]. */
export function intIn(rng: Rng, lo: number, hi: number): number {
  return lo + rng.nextInt(hi - lo + 1);
}

/** Query string from entries (values URI-encoded, commas kept readable). */
export function query(entries: Record<string, string | number>): string {
  return Object.entries(entries)
    .map(([k, v]) => `${k}=${encodeURIComponent(String(v)).replace(/%2C/g, ',').replace(/%3B/g, ';')}`)
    .join('&');
}
