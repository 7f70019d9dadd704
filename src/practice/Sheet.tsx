/**
 * `#/practice/sheet?seed=…&q=1,3,5&count=…&solutions=1`: the worksheet as a teacher prints it. Each
 * variant on its own page, with answer space sized to the answer (a line for a number, a box for a
 * formula, the options to tick for a choice), the variant's absolute link and a QR code to its
 * online self-check; then the answer key in typeset mathematics; then (with `solutions=1`) a page of
 * worked solutions per variant.
 */
import { Superscripted } from '../ui/Superscripted';
import { useEffect, useState } from 'react';
import { MathTex } from '../ui/MathTex';
import type { ShellFlags } from '../kit/shell';
import { shareBase } from '../kit/shareLink';
import { expectedText } from './check';
import { SolutionSteps } from './SolutionSteps';
import { formatSignificant } from '../ui/format';
import type { AnswerSpec, Variant } from './model';
import { parseSheetParams } from './params';
import { questionInfo } from './questions';
import { sheetSeed } from './questionList';
import { qrPath, type QrPath } from '../ui/qr';
import { practiceSlot } from './extensions';
import { ParamNotice } from './ParamNotice';

/** The absolute address of a variant's online page (works from any host and from file://). */
export function variantUrl(v: Pick<Variant, 'question' | 'seed'>, base = window.location.href): string {
  return `${shareBase(base)}#/practice/${v.question}?seed=${v.seed}`;
}

/**
 * The same address as a link that stays clickable in a PDF: a browser prints a link to its own
 * document (only the #fragment differs) as an internal jump, and drops it when no element has that
 * id. A `utm_source` query makes it another document; the service worker ignores utm_ parameters, so
 * the link still opens offline.
 */
export function variantHref(v: Pick<Variant, 'question' | 'seed'>, base = window.location.href): string {
  return `${shareBase(base)}?utm_source=worksheet#/practice/${v.question}?seed=${v.seed}`;
}

/** The expected answer in typeset form (the key's TeX, else the number or the formula text). */
export function answerTex(a: AnswerSpec): string {
  if (a.tex) return a.tex;
  if (a.kind === 'number')
    return a.expected === null ? '\\text{none}' : formatSignificant(a.expected, 6, 'e');
  return `\\texttt{${expectedText(a).replace(/[\\{}#$%&_^~]/g, ' ')}}`;
}

function QrCode({ text }: { text: string }) {
  const [qr, setQr] = useState<QrPath | null>(null);
  const [error, setError] = useState<string | null>(null);
  useEffect(() => {
    let alive = true;
    qrPath(text).then(
      (q) => alive && setQr(q),
      (e: unknown) => alive && setError(e instanceof Error ? e.message : String(e)),
    );
    return () => {
      alive = false;
    };
  }, [text]);
  if (error) return <span className="muted">(QR code unavailable: {error})</span>;
  if (!qr)
    return <span className="sheet-qr sheet-qr-pending" data-testid="sheet-qr-pending" aria-hidden="true" />;
  return (
    <svg
      className="sheet-qr"
      data-testid="sheet-qr"
      data-url={text}
      viewBox={`0 0 ${qr.size} ${qr.size}`}
      role="img"
      aria-label={`QR code of ${text}`}
      shapeRendering="crispEdges"
    >
      <rect width={qr.size} height={qr.size} fill="#fff" />
      <path d={qr.d} fill="#000" />
    </svg>
  );
}

function AnswerSpace({ a }: { a: AnswerSpec }) {
  if (a.kind === 'choice')
    return (
      <p className="sheet-blank sheet-choice">
        <span className="sheet-label">
          <Superscripted text={a.label} />:
        </span>{' '}
        {a.options.map((o) => (
          <span key={o} className="sheet-option">
            <span className="tick-box" aria-hidden="true" /> {o}
          </span>
        ))}
      </p>
    );
  if (a.kind === 'formula')
    return (
      <div className="sheet-blank sheet-formula">
        <span className="sheet-label">
          <Superscripted text={a.label} /> =
        </span>
        <span className="blank-box" aria-hidden="true" />
      </div>
    );
  return (
    <p className="sheet-blank">
      <span className="sheet-label">
        <Superscripted text={a.label} /> =
      </span>{' '}
      <span className="blank-line" aria-hidden="true" />
    </p>
  );
}

function Givens({ v }: { v: Variant }) {
  return (
    <dl className="givens sheet-givens">
      {v.givens.map((g) => (
        <div key={g.name} className={`given given-${g.name}`}>
          <dt>
            <Superscripted text={g.label} />
          </dt>
          <dd>{g.tex ? <MathTex tex={g.tex} /> : <Superscripted text={g.display} />}</dd>
        </div>
      ))}
    </dl>
  );
}

export default function Sheet({ sp, flags }: { sp: URLSearchParams; flags: ShellFlags }) {
  const P = parseSheetParams(sp);
  const problems = [...flags.problems, ...P.problems];
  const variants = P.qs.flatMap((q) =>
    Array.from({ length: P.count }, (_, k) => questionInfo(q).generate(sheetSeed(P.seed, k))),
  );
  useEffect(() => {
    document.title = `Practice worksheet (seed ${P.seed}) — Render Math Lab`;
  }, [P.seed]);
  // The box shows the reader's click at once; the page follows the address, which a change on the
  // same page re-renders as a transition (src/app/useHashRoute.ts), a moment later.
  const [solutionsShown, setSolutionsShown] = useState(P.solutions);
  useEffect(() => setSolutionsShown(P.solutions), [P.solutions]);
  const toggle = () => {
    const on = !solutionsShown;
    setSolutionsShown(on);
    const next = new URLSearchParams(sp);
    if (on) next.set('solutions', '1');
    else next.delete('solutions');
    window.location.hash = `#/practice/sheet?${next.toString()}`;
  };
  const LmsSlot = practiceSlot('sheet');
  return (
    <main id="main" className="page practice practice-sheet" tabIndex={-1}>
      <div className="no-print">
        <div className="scene-header">
          <h1>Worksheet: seed {P.seed}</h1>
          <a className="back-link" href="#/practice">
            ← All practice questions
          </a>
        </div>
        <ParamNotice problems={problems} />
        <p>
          {variants.length} question page{variants.length === 1 ? '' : 's'}, then the answer key
          {P.solutions ? ', then a page of worked solutions per variant' : ''}.{' '}
          <button type="button" onClick={() => window.print()}>
            Print
          </button>{' '}
          <label className="check-label">
            <input type="checkbox" checked={solutionsShown} onChange={toggle} data-testid="sheet-solutions" />{' '}
            Include worked solutions
          </label>
        </p>
        <p className="muted">
          Each variant’s page carries its own link and QR code: students check their answers online, one part
          at a time.
        </p>
        {LmsSlot ? <LmsSlot questions={P.qs} variants={P.count} seed={P.seed} /> : null}
      </div>
      {variants.map((v, i) => {
        const url = variantUrl(v);
        return (
          <section
            key={`${v.question}-${v.seed}`}
            className="sheet-page"
            data-testid="sheet-page"
            aria-labelledby={`sheet-q-${i}`}
          >
            <h2 id={`sheet-q-${i}`}>
              {i + 1}. Question {questionInfo(v.question).n}: {v.title}{' '}
              <span className="muted">(variant {v.seed})</span>
            </h2>
            <p>
              <Superscripted text={v.statement} />
            </p>
            <Givens v={v} />
            {v.parts.map((p) => (
              <div key={p.id} className="sheet-part">
                <p className="sheet-prompt">
                  <Superscripted text={p.paperPrompt ?? p.prompt} />
                </p>
                {p.answers.map((a) => (
                  <AnswerSpace key={a.name} a={a} />
                ))}
              </div>
            ))}
            <div className="sheet-check">
              <QrCode text={url} />
              <p className="sheet-link">
                Check your answers online (variant {v.seed}):
                <br />
                <a href={variantHref(v)} data-testid="sheet-link" data-url={url}>
                  {url}
                </a>
              </p>
            </div>
          </section>
        );
      })}
      <section className="sheet-key" data-testid="sheet-key" aria-labelledby="sheet-key-title">
        <h2 id="sheet-key-title">Answer key (seed {P.seed})</h2>
        {variants.map((v, i) => (
          <div key={`${v.question}-${v.seed}`} className="key-block">
            <h3>
              {i + 1}. Q{questionInfo(v.question).n} variant {v.seed}
            </h3>
            <ul className="key-answers">
              {v.parts.map((p) => (
                <li key={p.id} className="key-part">
                  <span className="key-part-id">({p.id})</span>{' '}
                  {p.answers.map((a) => (
                    <span
                      key={a.name}
                      className="key-answer"
                      data-testid={`key-${v.question}-${v.seed}-${a.name}`}
                    >
                      <MathTex tex={answerTex(a)} />
                    </span>
                  ))}
                </li>
              ))}
            </ul>
          </div>
        ))}
      </section>
      {P.solutions
        ? variants.map((v, i) => (
            <section
              key={`sol-${v.question}-${v.seed}`}
              className="sheet-solution"
              data-testid="sheet-solution"
              aria-labelledby={`sheet-sol-${i}`}
            >
              <h2 id={`sheet-sol-${i}`}>
                Worked solution {i + 1}: Q{questionInfo(v.question).n} variant {v.seed}
              </h2>
              <SolutionSteps steps={v.solution} />
              {v.notes.map((n) => (
                <p key={n} className="muted">
                  {n}
                </p>
              ))}
            </section>
          ))
        : null}
    </main>
  );
}
