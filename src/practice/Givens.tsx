import { MathTex } from '../ui/MathTex';
import { Superscripted } from '../ui/Superscripted';
import { GridTable } from './GridTable';
import type { Given } from './model';

/** The question's givens (contract: `given-NAME` with the full-precision `data-value`). */
export function Givens({ givens }: { givens: readonly Given[] }) {
  return (
    <dl className="givens">
      {givens.map((g) => (
        <div key={g.name} className={`given given-${g.name}`}>
          <dt>
            <Superscripted text={g.label} />
          </dt>
          <dd>
            {g.name === 'grid' ? (
              <GridTable text={g.value} testId={`given-${g.name}`} />
            ) : (
              <span data-testid={`given-${g.name}`} data-value={g.value} className="given-value">
                {g.tex ? <MathTex tex={g.tex} /> : <Superscripted text={g.display} />}
              </span>
            )}
          </dd>
        </div>
      ))}
    </dl>
  );
}
