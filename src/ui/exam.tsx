/**
 * Exam-first page structure, shared by every scene. A scene lays out each exam question
 * in this order:
 *
 *   <ExamQuestion n={1}>                (its title comes from the catalogue)
 *     <ExamPart id="1a" asks={<>Normalize p(ω) over the hemisphere …</>}>
 *       <Derivation>…the steps the key awards marks for, with live numbers…</Derivation>
 *       <LiveAnswer>…readouts computed by the core…</LiveAnswer>
 *     </ExamPart>
 *     …
 *   </ExamQuestion>
 *   <ExploreFurther>…stability, QMC, run time, robust forms…</ExploreFurther>
 *
 * `part=1a` in a link lands on `<ExamPart id="1a">` (the shell scrolls to `#part-1a`). Each question
 * ends with its "Practise this" links; the shell adds previous / next question links under the
 * scene (./QuestionNav).
 *
 * A part's heading and question are drawn with the page; its body (derivation, answer, figures)
 * mounts when it comes near the screen or in idle time (./Deferred): the first screen of a phone
 * is interactive before the rest of the page exists. What is beyond the exam is folded (./Fold)
 * and mounts only when opened.
 */
import type { ReactNode } from 'react';
import { Deferred } from './Deferred';
import { questionInfo } from '../kit/catalogue';
import './exam.css';

/** One exam question: its number and title (the catalogue's unless given), and its parts in order. */
export function ExamQuestion({
  n,
  title = questionInfo(n)?.title ?? '',
  intro,
  children,
}: {
  n: number;
  title?: string;
  intro?: ReactNode;
  children: ReactNode;
}) {
  return (
    <section
      className="exam-question"
      id={`question-${n}`}
      aria-labelledby={`question-${n}-title`}
      data-testid={`question-${n}`}
    >
      <h2 id={`question-${n}-title`} className="exam-question-title">
        Exam question {n}
        <span className="exam-question-sub"> · {title}</span>
      </h2>
      {intro ? <div className="exam-intro">{intro}</div> : null}
      {children}
      <PractiseLinks n={n} />
    </section>
  );
}

/**
 * One sub-question: what the exam asks (quoted), then the scene's derivation and live answer
 * (children). `id` is the part, e.g. '1a'; the element's id is `part-1a`.
 */
export function ExamPart({
  id,
  title,
  asks,
  children,
}: {
  id: string;
  title?: string;
  asks: ReactNode;
  children: ReactNode;
}) {
  const letter = id.replace(/^\d+/, '');
  return (
    <section
      className="exam-part"
      id={`part-${id}`}
      tabIndex={-1}
      aria-labelledby={`part-${id}-title`}
      data-testid={`part-${id}`}
    >
      <h3 id={`part-${id}-title`} className="exam-part-title">
        {letter ? `(${letter})` : `Q${id}`}
        {title ? ` ${title}` : ''}
      </h3>
      <div className="exam-asks">
        <span className="exam-asks-label">The exam asks</span>
        <div className="exam-asks-text">{asks}</div>
      </div>
      <Deferred>{children}</Deferred>
    </section>
  );
}

/** The variant of each question that "Practise this" opens (the same for everyone, so it can be discussed). */
export const PRACTISE_SEED = 1;

/**
 * "Practise this", once per question, after its parts: the practice page of the question (a fixed
 * variant, and a fresh one drawn at random), so a student revising it can try it with other numbers.
 */
export function PractiseLinks({ n }: { n: number }) {
  if (!(n >= 1 && n <= 6)) return null;
  return (
    <p className="exam-practise" data-testid={`practise-${n}`}>
      <a href={`#/practice/q${n}?seed=${PRACTISE_SEED}`} data-testid={`practise-link-${n}`}>
        Practise question {n} with new numbers
      </a>{' '}
      ·{' '}
      <a href={`#/practice/q${n}`} data-testid={`practise-fresh-${n}`}>
        a fresh variant
      </a>
    </p>
  );
}

/** A titled block of an exam part (derivation, live answer). */
function ExamBlock({
  className,
  title,
  children,
  testId,
}: {
  className: string;
  title: string;
  children: ReactNode;
  testId?: string;
}) {
  return (
    <div className={className} data-testid={testId}>
      <h4 className="exam-block-title">{title}</h4>
      {children}
    </div>
  );
}

type BlockProps = { title?: string; children: ReactNode; testId?: string };

/** The written derivation: the steps the key awards marks for (with live numbers where they have numbers). */
export function Derivation({ title = 'Derivation', ...rest }: BlockProps) {
  return <ExamBlock className="exam-derivation" title={title} {...rest} />;
}

/** The answer, computed live by the math core (readouts go here). */
export function LiveAnswer({ title = 'Answer, computed live', ...rest }: BlockProps) {
  return <ExamBlock className="exam-answer" title={title} {...rest} />;
}

/** A note on where the key's printed figure or wording differs from the computation. */
export function KeyNote({ children, testId }: { children: ReactNode; testId?: string }) {
  return (
    <p className="exam-keynote" data-testid={testId}>
      <span className="exam-keynote-label">About the answer key:</span> {children}
    </p>
  );
}

/**
 * Everything beyond the exam, clearly marked as such (stability, QMC, run time, robust forms): a
 * heading, a line saying what is there, and its panels, each a fold (./Fold) that mounts only when
 * opened.
 */
export function ExploreFurther({ children, intro }: { children: ReactNode; intro?: ReactNode }) {
  return (
    <section
      className="explore-further"
      aria-labelledby="explore-further-title"
      data-testid="explore-further"
    >
      <h2 id="explore-further-title">
        Explore further <span className="explore-badge">beyond the exam</span>
      </h2>
      {intro ? <p className="explore-intro">{intro}</p> : null}
      {children}
    </section>
  );
}
