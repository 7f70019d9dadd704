import { MathTex } from '../ui/MathTex';
import { ScrollBox } from '../ui/ScrollBox';
import { Superscripted } from '../ui/Superscripted';
import type { SolutionStep } from './model';

/** The steps of a worked solution or a hint: each a sentence (its powers set as superscripts), a formula, or both. */
export function SolutionSteps({ steps }: { steps: readonly SolutionStep[] }) {
  return (
    <>
      {steps.map((s, i) => (
        <div key={i} className="solution-step">
          {s.text ? (
            <p>
              <Superscripted text={s.text} />
            </p>
          ) : null}
          {s.tex ? (
            // a formula wider than a phone scrolls in its own box, which the keyboard can reach
            <ScrollBox label={`Step ${i + 1}, formula`} className="solution-math">
              <MathTex tex={s.tex} display />
            </ScrollBox>
          ) : null}
        </div>
      ))}
    </>
  );
}
