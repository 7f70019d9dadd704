/**
 * The render lab's Welch fold outside the browser: what it asks its worker for comes from the link
 * (the page's strategy and bias, the other strategy from `vs`), and a strategy whose runs are too
 * far from normal for the test gets a notice instead of a run and a verdict. The run itself and
 * its verdict on a biased estimator are tests/core/render/welchCompare.test.ts; the fold's run in
 * its worker, in the page, is tests/e2e/render.spec.ts.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { parseParams } from '../../src/kit/params';
import { schema, welchOther } from '../../src/scenes/render/params';
import { buildRenderModel } from '../../src/scenes/render/model';
import { welchArgs } from '../../src/scenes/render/jobArgs';
import { Welch } from '../../src/scenes/render/view/Welch';

const model = (query: string) => {
  const p = parseParams(schema, query).values;
  return { m: buildRenderModel(p), vs: p.vs };
};

describe('the Welch fold', () => {
  it('compares the link’s estimator, its bias included, with the strategy `vs` names', () => {
    const { m, vs } = model('strategy=area&bias=no-cos-l&vs=solid-angle&res=32&spp=1');
    const other = welchOther(vs, m.trace.strategy);
    expect(other).toBe('solid-angle');
    const a = welchArgs(m, other);
    expect(a.trace.strategy).toBe('area');
    expect(a.trace.bias).toBe('no-cos-l');
    expect(a.other).toBe('solid-angle');
    // and the fold shows that choice
    const html = renderToStaticMarkup(<Welch m={m} vs={vs} onVs={() => {}} />);
    expect(html).toMatch(/<option value="solid-angle" selected="">/);
  });

  it('says why a strategy that rarely finds the light is not tested, and starts no run', () => {
    for (const strategy of ['cosine', 'uniform', 'bsdf']) {
      const { m, vs } = model(`strategy=${strategy}&open=welch&res=32&spp=1`);
      const html = renderToStaticMarkup(<Welch m={m} vs={vs} onVs={() => {}} />);
      expect(html, strategy).toContain('data-testid="welch-not-testable"');
      expect(html, strategy).not.toContain('data-testid="welch-verdict"');
      expect(html, strategy).not.toContain('data-testid="welch-status"');
    }
    const { m, vs } = model('strategy=mis-power&open=welch&res=32&spp=1');
    const html = renderToStaticMarkup(<Welch m={m} vs={vs} onVs={() => {}} />);
    expect(html).not.toContain('welch-not-testable');
    expect(html).toContain('data-testid="welch-status"');
  });
});
