import type { Variant } from './model';
import { partDone, SCORING, type Session } from './session';

/** What the student could do next: the parts to retry, with the hint or answer on offer. */
export function nextSteps(v: Variant, s: Session): string[] {
  const out: string[] = [];
  for (const p of v.parts) {
    const st = s.parts[p.id];
    const tried = p.answers.filter((a) => s.answers[a.name].verdict);
    const wrong = tried.filter((a) => s.answers[a.name].verdict!.value !== 'correct');
    const name = `(${p.id})`;
    if (wrong.length) {
      const labels = wrong.map((a) => a.label).join(', ');
      out.push(
        st.revealed
          ? `${name} ${labels}: compare with the answer shown under the part.`
          : `${name} ${labels}: read the message, ${st.hint ? 'use the hint, ' : 'take the hint, '}and check again (${SCORING.revealAfter - st.wrong} wrong ${SCORING.revealAfter - st.wrong === 1 ? 'attempt' : 'attempts'} left before the answer is shown).`,
      );
    } else if (tried.length && tried.length < p.answers.length)
      out.push(`${name} The rest of this part is not answered yet.`);
  }
  const untouched = v.parts.filter((p) => p.answers.every((a) => !s.answers[a.name].verdict));
  if (untouched.length && untouched.length < v.parts.length)
    out.push(`Not answered yet: ${untouched.map((p) => `(${p.id})`).join(', ')}.`);
  if (!out.length && v.parts.every((p) => partDone(p, s)))
    out.push('Every answer is right. Try a new variant, or open the scene to see it move.');
  return out;
}
