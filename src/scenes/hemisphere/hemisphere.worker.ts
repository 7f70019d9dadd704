/**
 * Worker for the hemisphere scene's big runs: drawing n samples (up to 10⁶), the χ² test, the
 * histograms and the Q2 estimators; and the "repeat many times" runs. Pure model code; the user
 * expressions are compiled here again (closures cannot cross the worker boundary).
 */
import { exposeTasks } from '../../workers/expose';
import { compileExpression } from '../../core/expr';
import { tabulateHemisphereDensity } from '../../core/sampling';
import type { SequenceKind } from '../../core/random';
import { computeDrawStats, makeLobe, repeatEstimates, type Integrand, type Lobe } from './model';
import type { LobeId } from './params';

export interface StatsArgs {
  lobe: LobeId;
  exponent: number;
  pdf: string;
  f: string;
  points: SequenceKind;
  seed: number;
  n: number;
  /** false when the key's inverted Jacobian is selected: no lobe can be sampled. */
  sampleLobe: boolean;
}

export interface RepeatArgs extends StatsArgs {
  runs: number;
  perRun: number;
}

async function prepare(a: StatsArgs): Promise<{ lobe: Lobe | null; f: Integrand | null }> {
  const fc = await compileExpression(a.f, ['theta', 'phi']);
  const f = fc.ok ? (t: number, p: number) => fc.fn(t, p) : null;
  let lobe: Lobe | null = null;
  if (a.sampleLobe) {
    if (a.lobe === 'custom') {
      const pc = await compileExpression(a.pdf, ['theta', 'phi']);
      if (pc.ok) {
        const tab = tabulateHemisphereDensity((t, p) => pc.fn(t, p));
        if (tab.ok) lobe = makeLobe('custom', a.exponent, tab.lobe);
      }
    } else lobe = makeLobe(a.lobe, a.exponent);
  }
  return { lobe, f };
}

exposeTasks({
  stats: async (a: StatsArgs) => {
    const { lobe, f } = await prepare(a);
    return computeDrawStats(lobe, f, a.points, a.seed, a.n);
  },
  repeat: async (a: RepeatArgs, progress) => {
    const { lobe, f } = await prepare(a);
    if (!f) throw new Error('the integrand does not compile');
    return repeatEstimates(lobe, f, a.points, a.seed, a.runs, a.perRun, (x) => progress(x));
  },
});
