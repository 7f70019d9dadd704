/**
 * Small pieces the exam parts share: TeX formatting of live numbers, a sideways-scrolling block for
 * wide formulas, the key's note on the index of its sum, and the frame of a worked answer (the
 * derivation beside its answer).
 */
import type { ReactNode } from 'react';
import {
  Derivation,
  formatNumber,
  keepTextParenthesesTogether,
  KeyNote,
  LiveAnswer,
  MathTex,
  Revealed,
} from '../../../ui';

/** A number for TeX (six significant digits), or a dash when it is not finite. */
export const n4 = (x: number) => (Number.isFinite(x) ? formatNumber(x, 6) : '\\text{—}');

/** k when 3v is (nearly) the integer k and v is no integer, else null. */
function thirdsOf(v: number): number | null {
  const k = Math.round(v * 3);
  return Math.abs(v * 3 - k) < 1e-9 * Math.max(1, Math.abs(k)) && k % 3 !== 0 ? k : null;
}

/** v as "p/3" (TeX) when 3v is (nearly) an integer, else its decimal. */
export function thirds(v: number): string {
  const k = thirdsOf(v);
  return k === null ? n4(v) : `\\frac{${k}}{3}`;
}

/** v as plain text: "56/3" when 3v is (nearly) an integer, else its decimal (six significant digits). */
export function thirdsText(v: number): string {
  const k = thirdsOf(v);
  return k === null ? formatNumber(v, 6) : `${k}/3`;
}

/** x + c as TeX. */
export const shifted = (c: number) => (c === 0 ? 'x' : `x ${c > 0 ? '+' : '-'} ${n4(Math.abs(c))}`);

/** (x + c)² at a number, as TeX. */
export const squareAt = (x: number, c: number) => `(${n4(x)} ${c >= 0 ? '+' : '-'} ${n4(Math.abs(c))})^2`;

/** Terms of a sum for an aligned block, two per row (a long sum would not fit a phone's width). */
export function sumRows(terms: string[]): string {
  const rows: string[] = [];
  for (let i = 0; i < terms.length; i += 2) rows.push(terms.slice(i, i + 2).join(' + '));
  return rows.join(String.raw` \\ &\qquad + `);
}

/** A block of display formulas that scrolls sideways when wider than the screen. */
export function MathBlock({
  children,
  label = 'derivation (scrolls sideways when wider than the screen)',
  testId,
}: {
  children: ReactNode;
  label?: string;
  testId?: string;
}) {
  return (
    <div className="mc-math" data-testid={testId} tabIndex={0} role="group" aria-label={label}>
      {children}
    </div>
  );
}

/** The key's Σ from i = 0 to 4 with the factor 1/4 (Q4 b and c). */
export function SumIndexNote({ part }: { part: string }) {
  return (
    <KeyNote testId={`key-sum-${part}`}>
      the key writes <MathTex tex={String.raw`\tfrac14\sum_{i=0}^{4}`} />: that is five terms{' '}
      {keepTextParenthesesTogether('(i = 0, 1, 2, 3, 4)')} divided by 4. The four samples are x₁ … x₄, so the
      sum runs from i = 1 to 4 (
      <MathTex tex={String.raw`\tfrac14\sum_{i=1}^{4}`} />
      ), as its own arithmetic (four values added) does.
    </KeyNote>
  );
}

/** A part's derivation and its live answer, side by side on a wide screen (one column on a narrow one). */
export function Worked({ children }: { children: ReactNode }) {
  return <div className="mc-worked">{children}</div>;
}

/**
 * A Q4 part's worked answer, hidden under ask=1 until revealed: the derivation (`children`) beside
 * the live answer (its headline readout, then `answer`) with the key's note on its sum under it,
 * then `after`. Test ids
 * `derivation-${part}` and `answer-${part}`.
 */
export function WorkedAnswer({
  part,
  ask,
  headline,
  answer,
  after,
  children,
}: {
  part: '4b' | '4c';
  ask: boolean;
  headline: ReactNode;
  answer?: ReactNode;
  after?: ReactNode;
  children: ReactNode;
}) {
  return (
    <Revealed ask={ask} what="the derivation and the answer">
      <Worked>
        <Derivation testId={`derivation-${part}`}>{children}</Derivation>
        <div>
          <LiveAnswer testId={`answer-${part}`}>
            <div className="readouts mc-headline">{headline}</div>
            {answer}
          </LiveAnswer>
          <SumIndexNote part={part} />
        </div>
      </Worked>
      {after}
    </Revealed>
  );
}
