import { useEffect, useMemo, useState } from 'react';
import { queryProblems, type ShellFlags } from '../kit/shell';
import { extensionSeed } from './extensions';
import { MAX_SEED, randomSeed } from './links';
import type { QuestionId } from './model';
import { QuestionPage } from './QuestionPage';
import { questionInfo } from './questions';

/** Parse a seed parameter: an integer in [0, 2³² − 1], else null with a message. */
function parseSeed(raw: string | null): { seed: number | null; problem: string | null } {
  if (raw === null) return { seed: null, problem: null };
  const s = raw.trim();
  if (/^\d{1,10}$/.test(s) && Number(s) <= MAX_SEED) return { seed: Number(s), problem: null };
  return {
    seed: null,
    problem: `seed ${JSON.stringify(s.slice(0, 24))} is not a whole number from 0 to ${MAX_SEED}; a new variant was drawn instead.`,
  };
}

/** `#/practice/qN?seed=…`: the variant the link names (a fresh one, written into the URL, when none). */
export function QuestionRoute({ q, sp, flags }: { q: QuestionId; sp: URLSearchParams; flags: ShellFlags }) {
  const parsed = parseSeed(sp.get('seed'));
  const [fallback] = useState(() => randomSeed());
  // an extension (the LMS runtime in a package) fixes each learner's variant, whatever the link says
  const seed = extensionSeed(q) ?? parsed.seed ?? fallback;
  const problems = [
    ...flags.problems.map((p) => `${p.name} ${p.message}`),
    ...queryProblems(sp.toString(), ['seed']).map((p) => `${p.name} ${p.message}`),
    ...(parsed.problem ? [parsed.problem] : []),
  ];
  // a link without a (valid) seed gets one, so the page's URL names its variant
  useEffect(() => {
    if (parsed.seed !== null) return;
    try {
      const keep = new URLSearchParams(sp);
      keep.set('seed', String(seed));
      window.history.replaceState(window.history.state, '', `#/practice/${q}?${keep.toString()}`);
    } catch {
      /* sandboxed: the seed still lives in the page */
    }
  }, [parsed.seed, seed, q, sp]);
  const variant = useMemo(() => questionInfo(q).generate(seed), [q, seed]);
  return <QuestionPage key={`${q}-${seed}`} variant={variant} flags={flags} problems={problems} />;
}
