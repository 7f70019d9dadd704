import { useEffect, useMemo, useState } from 'react';
import type { ShellFlags } from '../kit/shell';
import { extensionSeed } from './extensions';
import { randomSeed } from './links';
import { parseQuestionParams } from './params';
import type { QuestionId } from './model';
import { QuestionPage } from './QuestionPage';
import type { Generate } from './generators';

export interface QuestionRouteProps {
  q: QuestionId;
  sp: URLSearchParams;
  flags: ShellFlags;
}

/**
 * `#/practice/qN?seed=…`: the variant the link names (a fresh one, written into the URL, when none),
 * made by `generate`, question q's generator (./generators.ts).
 */
export function QuestionRoute({ q, sp, flags, generate }: QuestionRouteProps & { generate: Generate }) {
  const [fallback] = useState(() => randomSeed());
  const parsed = parseQuestionParams(sp, fallback);
  // an extension (the LMS runtime in a package) fixes each learner's variant, whatever the link says
  const seed = extensionSeed(q) ?? parsed.seed;
  const problems = [...flags.problems, ...parsed.problems];
  // a link without a (valid) seed gets one, so the page's URL names its variant
  const asGiven = parsed.seedAsGiven;
  useEffect(() => {
    if (asGiven) return;
    try {
      const keep = new URLSearchParams(sp);
      keep.set('seed', String(seed));
      window.history.replaceState(window.history.state, '', `#/practice/${q}?${keep.toString()}`);
    } catch {
      /* sandboxed: the seed still lives in the page */
    }
  }, [asGiven, seed, q, sp]);
  const variant = useMemo(() => generate(seed), [generate, seed]);
  return <QuestionPage key={`${q}-${seed}`} variant={variant} flags={flags} problems={problems} />;
}
