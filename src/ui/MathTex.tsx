import { useEffect, useRef, useState } from 'react';
import { flushSync } from 'react-dom';
import { flushMathForPrint, scheduleMath } from './mathQueue';

type Katex = typeof import('katex');
let katexPromise: Promise<Katex> | null = null;

/** Load KaTeX (and its stylesheet) once, on first use. */
export function loadKatex(): Promise<Katex> {
  if (!katexPromise) {
    katexPromise = Promise.all([import('katex'), import('katex/dist/katex.min.css')]).then(([m]) => (m as unknown as { default?: Katex }).default ?? m);
  }
  return katexPromise;
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

let printHooked = false;
/** Before printing, every formula still waiting for idle time is typeset (and committed) at once. */
function hookPrint(): void {
  if (printHooked || typeof window === 'undefined') return;
  printHooked = true;
  window.addEventListener('beforeprint', () => flushSync(() => flushMathForPrint()));
}

/**
 * TeX rendered by KaTeX (HTML + MathML for screen readers). KaTeX loads lazily; until then, and if
 * the TeX is invalid, the source is shown as code. Never throws.
 */
export function MathTex({ tex, display = false, className }: { tex: string; display?: boolean; className?: string }) {
  const key = `${display ? 'D' : 'I'}${tex}`;
  const [html, setHtml] = useState<string | null>(() => cached(key) ?? null);
  const ref = useRef<HTMLElement>(null);
  useEffect(() => {
    const hit = cached(key);
    if (hit !== undefined) {
      setHtml(hit);
      return;
    }
    let alive = true;
    let cancel = () => {};
    hookPrint();
    loadKatex()
      .then((k) => {
        if (!alive) return;
        // Each formula renders in its own slot: at once (sliced with the others) when it is near
        // the screen, else in idle time (./mathQueue). When KaTeX arrives, a scene's dozens of
        // formulas would otherwise all render in one long task.
        cancel = scheduleMath(ref.current, () => {
          if (!alive) return;
          try {
            const out = k.renderToString(tex, { displayMode: display, throwOnError: false, strict: 'ignore', output: 'htmlAndMathml' });
            remember(key, out);
            setHtml(out);
          } catch {
            setHtml(null);
          }
        });
      })
      .catch(() => {});
    return () => {
      alive = false;
      cancel();
    };
  }, [key, tex, display]);
  const Tag = display ? 'div' : 'span';
  if (html === null) {
    return (
      <Tag ref={ref as React.RefObject<HTMLDivElement>} className={`math math-pending${display ? ' math-display' : ''}${className ? ` ${className}` : ''}`}>
        <code>{tex}</code>
      </Tag>
    );
  }
  return <Tag ref={ref as React.RefObject<HTMLDivElement>} className={`math${display ? ' math-display' : ''}${className ? ` ${className}` : ''}`} dangerouslySetInnerHTML={{ __html: html }} />;
}
