import { useEffect, useMemo, useRef, useState } from 'react';
import { KATEX_OPTIONS } from './katexOptions';
import { flushMathForPrint, insertTypeset, scheduleMath } from './mathQueue';
import { afterPaint } from './afterPaint';
import { previewLabel, texPreview, texPreviewParts, type PreviewPart } from './texPreview';
import { keepParenthesesTogether } from './texBreaks';
import { katexWorker, typesetInWorker } from './katexJobs';
import './math.css';

type Katex = typeof import('katex');
let katexPromise: Promise<Katex> | null = null;
let cssPromise: Promise<unknown> | null = null;

/**
 * KaTeX's stylesheet (loaded once, on first use: every typeset formula needs it), less its
 * @font-face rules, which the shell's stylesheet declares (src/app/main.tsx, scripts/katexCss.ts).
 */
function loadKatexCss(): Promise<unknown> {
  if (!cssPromise) cssPromise = import('katex/dist/katex.min.css?rules');
  return cssPromise;
}

/** KaTeX itself on the main thread (and its stylesheet): only where no worker can be started. */
export function loadKatex(): Promise<Katex> {
  if (!katexPromise) {
    katexPromise = Promise.all([import('katex'), loadKatexCss()]).then(
      ([m]) => (m as unknown as { default?: Katex }).default ?? m,
    );
  }
  return katexPromise;
}

/** Start the worker and the stylesheet together (a page is about to show formulas). */
function prepareMath(): void {
  void loadKatexCss().catch(() => undefined);
  katexWorker();
}

let started: Promise<void> | null = null;
/**
 * The first formula to typeset starts the worker and the stylesheet, but only once the frame that
 * shows the page's text (formulas still as TeX source) has been painted: on a phone, downloading
 * them earlier delays that first paint (Lighthouse's LCP). Later formulas go at once.
 */
function mathStarted(): Promise<void> {
  if (!started) started = afterPaint().then(prepareMath);
  return started;
}

/** HTML for `tex` (null if KaTeX fails on it), typeset in the worker when there is one. */
function typeset(tex: string, display: boolean): Promise<string | null> {
  return mathStarted().then(() => typesetNow(tex, display));
}

function typesetNow(source: string, display: boolean): Promise<string | null> {
  // a long formula wraps only at operators outside parentheses (./texBreaks)
  const tex = keepParenthesesTogether(source);
  const w = katexWorker();
  const onMain = () =>
    Promise.all([loadKatex(), import('./mathmlSpeech')]).then(([k, m]) =>
      m.speakableMathml(k.renderToString(tex, { ...KATEX_OPTIONS, displayMode: display })),
    );
  if (!w) return onMain();
  return typesetInWorker(tex, display).then(
    // the HTML goes in only with its stylesheet
    (html) => loadKatexCss().then(() => html),
    () => onMain(),
  );
}

/**
 * Rendered formulas, most recently used last: an animation that loops (or steps back and forth)
 * shows the same formulas again, and KaTeX costs far more than a frame.
 */
const CACHE = new Map<string, string>();
const CACHE_MAX = 256;
function cached(key: string): string | undefined {
  const v = CACHE.get(key);
  if (v !== undefined) {
    CACHE.delete(key);
    CACHE.set(key, v);
  }
  return v;
}
function remember(key: string, html: string): void {
  CACHE.set(key, html);
  if (CACHE.size > CACHE_MAX) CACHE.delete(CACHE.keys().next().value!);
}

/**
 * Typeset `tex` ahead of showing it: once this resolves, a MathTex given `tex` shows the typeset
 * formula in the render that gives it (from the cache), with no frame of the previous formula.
 * For views whose formula and the numbers beside it must change together (an animation's worked
 * steps). Resolves (never rejects) also when KaTeX cannot typeset it.
 */
export function preloadMath(tex: string, display = false): Promise<void> {
  const key = `${display ? 'D' : 'I'}${tex}`;
  if (CACHE.has(key)) return Promise.resolve();
  return typeset(tex, display).then(
    (out) => {
      if (out !== null) remember(key, out);
    },
    () => undefined,
  );
}

let printHooked = false;
/**
 * Before printing, every formula still waiting for idle time is sent to be typeset at once. The
 * worker answers within moments, but a print started in the first seconds after opening a page
 * can still show some formulas as TeX source.
 */
function hookPrint(): void {
  if (printHooked || typeof window === 'undefined') return;
  printHooked = true;
  window.addEventListener('beforeprint', () => flushMathForPrint());
}

/**
 * TeX rendered by KaTeX (HTML + MathML for screen readers), typeset in a worker. Until then it is
 * shown as plain text (./texPreview: "p(ω) = k cos θ eᵠ"); if KaTeX cannot be run, the source is
 * shown as code. Never throws.
 */
export function MathTex({
  tex,
  display = false,
  className,
}: {
  tex: string;
  display?: boolean;
  className?: string;
}) {
  const key = `${display ? 'D' : 'I'}${tex}`;
  // undefined: not typeset yet; null: KaTeX could not be run
  const [typesetHtml, setHtml] = useState<string | null | undefined>(() => cached(key));
  const ref = useRef<HTMLElement>(null);
  useEffect(() => {
    const hit = cached(key);
    if (hit !== undefined) {
      setHtml(hit);
      return;
    }
    // (a formula that changes keeps showing the old one until the new one is typeset)
    let alive = true;
    hookPrint();
    // Each formula is typeset in its own slot: at once when it is near the screen, else in idle
    // time (./mathQueue), so the formulas on screen come first; its HTML goes in with at most a few
    // others per frame (insertTypeset), so the HTML of a screenful is never inserted in one go.
    const cancel = scheduleMath(ref.current, () => {
      typeset(tex, display)
        .then((out) => {
          if (out !== null) remember(key, out);
          insertTypeset(out?.length ?? 0, () => {
            if (alive) setHtml(out);
          });
        })
        .catch(() => {
          if (alive) setHtml(null);
        });
    });
    return () => {
      alive = false;
      cancel();
    };
  }, [key, tex, display]);
  // a formula already typeset shows at once, in the render that changes it (see preloadMath)
  const html = CACHE.get(key) ?? typesetHtml;
  const preview = useMemo(
    () =>
      html === undefined
        ? { parts: texPreviewParts(tex, display), label: previewLabel(texPreview(tex, display)) }
        : null,
    [html, tex, display],
  );
  const Tag = display ? 'div' : 'span';
  const cls = `math${display ? ' math-display' : ''}${className ? ` ${className}` : ''}`;
  if (html === undefined) {
    return (
      <Tag ref={ref as React.RefObject<HTMLDivElement>} className={`${cls} math-pending`}>
        <span className="math-preview" role="math" aria-label={preview?.label}>
          {preview ? <PreviewText parts={preview.parts} /> : null}
        </span>
      </Tag>
    );
  }
  if (html === null) {
    return (
      <Tag ref={ref as React.RefObject<HTMLDivElement>} className={`${cls} math-failed`}>
        <code>{tex}</code>
      </Tag>
    );
  }
  return (
    <Tag
      ref={ref as React.RefObject<HTMLDivElement>}
      className={cls}
      dangerouslySetInnerHTML={{ __html: html }}
    />
  );
}

/** The plain-text reading, its scripts that Unicode cannot write set as <sup> / <sub>. */
function PreviewText({ parts }: { parts: PreviewPart[] }) {
  return parts.map((p, k) =>
    typeof p === 'string' ? (
      p
    ) : p.tag === 'sup' ? (
      <sup key={k}>
        <PreviewText parts={p.parts} />
      </sup>
    ) : (
      <sub key={k}>
        <PreviewText parts={p.parts} />
      </sub>
    ),
  );
}
