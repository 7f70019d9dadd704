import { Superscripted } from '../ui/Superscripted';
import { formatPlain } from '../ui/format';
import type { Verdict as CheckVerdict } from './check';
import { roundTo } from './model';

function verdictTag(value: string): string {
  if (value === 'correct') return '✓ correct';
  if (value === 'consistent') return '≈ follow-through';
  if (value.startsWith('mistake:')) return `✗ ${value}`;
  if (value === 'invalid') return '? not graded';
  return '✗ incorrect';
}

/** The class suffix of a verdict: correct, consistent, incorrect, invalid or mistake. */
export function verdictKind(value: string): string {
  return value.startsWith('mistake:') ? 'mistake' : value;
}

/** One answer's verdict (contract: `verdict-NAME` with its data-value), with the credit it earned. */
export function Verdict({ name, verdict, credit }: { name: string; verdict: CheckVerdict; credit: number }) {
  const earned =
    verdict.value !== 'invalid' && verdict.value !== 'incorrect' && !verdict.value.startsWith('mistake:');
  return (
    <p
      className={`verdict verdict-${verdictKind(verdict.value)}`}
      id={`verdict-${name}`}
      data-testid={`verdict-${name}`}
      data-value={verdict.value}
      data-credit={credit}
    >
      <span className="verdict-tag">{verdictTag(verdict.value)}</span>{' '}
      <Superscripted text={verdict.message} />
      {earned ? <span className="verdict-credit"> (+{formatPlain(roundTo(credit, 2))} mark)</span> : null}
    </p>
  );
}
