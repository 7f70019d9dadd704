/**
 * Previous / next exam question links under every scene. Its own module, apart from the exam page
 * parts (./exam.tsx), because the shell draws it in the entry chunk and the parts load with scenes.
 */
import { questionStart, type PageInfo } from '../kit/catalogue';
import type { ShellFlags } from '../kit/shell';
import './exam.css';

function flagQuery(flags: Pick<ShellFlags, 'present' | 'theme'>): string {
  return `${flags.present ? '&present=1' : ''}${flags.theme ? `&theme=${flags.theme}` : ''}`;
}

/** Link to the start of exam question q (its scene, in the exam's configuration, at its first part). */
export function questionHref(q: number, flags: Pick<ShellFlags, 'present' | 'theme'>): string | null {
  const start = questionStart(q);
  if (!start) return null;
  const base = start.scene.examQuery ? `${start.scene.examQuery}&` : '';
  return `#${start.scene.path}?${base}part=${start.part}${flagQuery(flags)}`;
}

/** Previous / next exam question links, under every scene (not in embeds; none under a lab). */
export function QuestionNav({
  info,
  flags,
}: {
  info: PageInfo;
  flags: Pick<ShellFlags, 'present' | 'theme'>;
}) {
  const qs = [...new Set(info.parts.map((p) => Number.parseInt(p, 10)))];
  if (qs.length === 0) return null; // a lab: it teaches no one question
  const first = Math.min(...qs);
  const last = Math.max(...qs);
  const prev = first > 1 ? questionHref(first - 1, flags) : null;
  const next = last < 6 ? questionHref(last + 1, flags) : null;
  return (
    <nav className="question-nav" aria-label="Exam questions">
      {prev ? (
        <a href={prev} rel="prev" data-testid="prev-question">
          ← Question {first - 1}
        </a>
      ) : (
        <span />
      )}
      {next ? (
        <a href={next} rel="next" data-testid="next-question">
          Question {last + 1} →
        </a>
      ) : (
        <span />
      )}
    </nav>
  );
}
