import { useState } from 'react';
import { IntInput } from '../ui/IntInput';
import type { ShellFlags } from '../kit/shell';
import { flagSuffix, MAX_SEED } from './links';
import { QUESTION_IDS, type QuestionId } from './model';
import { QUESTION_LIST } from './questionList';

/** The form on the practice index that builds a printable worksheet's link. */
export function SheetBuilder({ flags }: { flags: ShellFlags }) {
  const [sheetQs, setSheetQs] = useState<Record<QuestionId, boolean>>(
    () => Object.fromEntries(QUESTION_IDS.map((q) => [q, true])) as Record<QuestionId, boolean>,
  );
  const [count, setCount] = useState(1);
  const [withSolutions, setWithSolutions] = useState(false);
  const [sheetSeedText, setSheetSeedText] = useState('1');
  const chosen = QUESTION_IDS.filter((q) => sheetQs[q]).map((q) => q.slice(1));
  const seedOk = /^\d{1,10}$/.test(sheetSeedText.trim()) && Number(sheetSeedText) <= MAX_SEED;
  const sheetHref = `#/practice/sheet?seed=${seedOk ? Number(sheetSeedText) : 1}&q=${chosen.join(',') || '1'}&count=${count}${withSolutions ? '&solutions=1' : ''}${flagSuffix(flags)}`;
  return (
    <section className="panel sheet-builder" aria-labelledby="sheet-title">
      <h2 id="sheet-title">Worksheet for a class (printable)</h2>
      <fieldset>
        <legend>Questions</legend>
        {QUESTION_LIST.map((q) => (
          <label key={q.id} className="check-label">
            <input
              type="checkbox"
              checked={sheetQs[q.id]}
              onChange={(e) => setSheetQs({ ...sheetQs, [q.id]: e.target.checked })}
            />{' '}
            Q{q.n}
          </label>
        ))}
      </fieldset>
      <label>
        Variants of each <IntInput min={1} max={10} value={count} fallback={1} onChange={setCount} />
      </label>{' '}
      <label>
        Seed{' '}
        <input
          type="text"
          inputMode="numeric"
          value={sheetSeedText}
          onChange={(e) => setSheetSeedText(e.target.value)}
          aria-invalid={!seedOk}
          size={10}
        />
      </label>{' '}
      <label className="check-label">
        <input type="checkbox" checked={withSolutions} onChange={(e) => setWithSolutions(e.target.checked)} />{' '}
        with worked solutions
      </label>{' '}
      <a href={sheetHref}>Open the worksheet</a>
      {!seedOk ? (
        <p className="notice notice-warn">
          The seed must be a whole number from 0 to {MAX_SEED}; the link uses 1.
        </p>
      ) : null}
    </section>
  );
}
