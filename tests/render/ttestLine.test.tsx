/**
 * The t-test line under an estimate (Q4's integral, Q6's irradiance), rendered in Node: an estimate
 * within its noise of the exact value passes, one off by many standard errors fails, and without
 * two samples there is no test; the p shown is Student's two-sided p for t = (mean − exact)/(s/√N)
 * with N − 1 degrees of freedom, computed here independently of the component.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { TTestLine } from '../../src/ui/TTestLine';
import { studentTTwoSided } from '../../src/core/verify/studentT';

const verdict = (html: string) => /data-testid="ttest" data-value="(\w+)"/.exec(html)?.[1];
const pValue = (html: string) => Number(/data-testid="ttest-p"[^>]*data-value="([^"]+)"/.exec(html)?.[1]);

describe('TTestLine', () => {
  it('passes an estimate within its noise and fails one far outside it', () => {
    const ok = renderToStaticMarkup(
      <TTestLine estimate={18.7} stderr={0.05} n={10000} exact={56 / 3} against="the exact integral" />,
    );
    expect(verdict(ok)).toBe('pass');
    const t = (18.7 - 56 / 3) / 0.05;
    expect(pValue(ok)).toBeCloseTo(studentTTwoSided(t, 9999), 12);
    const off = renderToStaticMarkup(
      <TTestLine estimate={19.2} stderr={0.05} n={10000} exact={56 / 3} against="the exact integral" />,
    );
    expect(verdict(off)).toBe('fail');
    expect(pValue(off)).toBeLessThan(0.01);
  });

  it('runs no test without two samples or an exact value', () => {
    expect(
      verdict(renderToStaticMarkup(<TTestLine estimate={1} stderr={NaN} n={1} exact={1} against="x" />)),
    ).toBe('none');
    expect(
      verdict(renderToStaticMarkup(<TTestLine estimate={1} stderr={0.1} n={50} exact={NaN} against="x" />)),
    ).toBe('none');
  });
});
