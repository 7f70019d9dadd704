/**
 * `#/accessibility`: the accessibility statement (what a reader with a screen reader, the keyboard
 * only, low vision or colour-vision deficiency can do here, and how) and a small worked example of
 * the described figures, audio traces and tables every scene uses. Its own lazy chunk.
 */
import { lazy, Suspense, useEffect, useMemo, useState } from 'react';
import type { ShellFlags } from '../kit/shell';
import { RouteNotice } from '../ui/RouteNotice';
import { keepTextParenthesesTogether } from '../ui/texBreaks';
import { DescribedFigure } from '../ui/describe';
import { AudioTrace } from '../ui/audioTrace';
import { ShowAsTable } from '../ui/DataTable';
import { summarizeSeries } from '../ui/summary';
import { DEMO_B, DEMO_T, demoCurve, describeDemo } from './accessibilityDemo';
import './a11y-view.css';

const A11yView = lazy(() => import('./A11yView'));

const W = 320;
const H = 160;

function DemoFigure({ r }: { r: number }) {
  const { ts, gs, roots } = useMemo(() => demoCurve(r), [r]);
  const gLo = -2.5;
  const gHi = 4.5;
  const x = (t: number) => ((t - DEMO_T[0]) / (DEMO_T[1] - DEMO_T[0])) * (W - 20) + 10;
  const y = (g: number) => H - 10 - ((Math.min(gHi, Math.max(gLo, g)) - gLo) / (gHi - gLo)) * (H - 20);
  const points = ts.map((t, i) => `${x(t).toFixed(1)},${y(gs[i]!).toFixed(1)}`).join(' ');
  return (
    <svg viewBox={`0 0 ${W} ${H}`} className="a11y-demo-plot" aria-hidden="true" focusable="false">
      <line x1={10} x2={W - 10} y1={y(0)} y2={y(0)} className="a11y-demo-zero" />
      <polyline points={points} className="a11y-demo-curve" />
      {roots.map((t) => (
        <circle key={t} cx={x(t)} cy={y(0)} r={4} className="a11y-demo-root" />
      ))}
      <text x={W - 12} y={y(0) - 4} textAnchor="end" className="a11y-demo-label">
        g = 0
      </text>
    </svg>
  );
}

export default function AccessibilityPage({ flags, query = '' }: { flags: ShellFlags; query?: string }) {
  useEffect(() => {
    document.title = 'Accessibility — Render Math Lab';
  }, []);
  const [r, setR] = useState(1);
  const curve = useMemo(() => demoCurve(r), [r]);
  const events = curve.roots.map((t) => ({
    x: t,
    kind: curve.roots.length === 1 ? ('tangent' as const) : ('root' as const),
  }));
  const home = flags.present ? '#/?present=1' : '#/';
  return (
    <main id="main" className="page accessibility" tabIndex={-1}>
      <div className="scene-header">
        <h1>Accessibility</h1>
        <a className="back-link" href={home}>
          ← All scenes
        </a>
      </div>
      <RouteNotice flags={flags} query={query} />
      {flags.a11y ? (
        <Suspense fallback={null}>
          <A11yView />
        </Suspense>
      ) : null}
      <p>
        Render Math Lab aims at WCAG 2.2 level AA on every page: every scene can be used with the keyboard
        alone, with a screen reader, zoomed to 400 % or at 320 CSS pixels wide, with the text spacing a reader
        sets, and in light or dark colours whose lines and focus rings keep a 3 : 1 contrast.
      </p>
      <h2>What a screen reader hears</h2>
      <ul>
        <li>
          Every figure has a name and a description that says what it shows now, with its numbers; it is kept
          current as you change a parameter, and announced once the change settles (while an animation plays,
          on pause). Press <kbd>d</kbd> with the focus in a figure to hear it again.
        </li>
        <li>
          Every plot says its trend, extremes, last value and, on log–log axes, its slope, and has{' '}
          <em>Show as table</em> with its data.
        </li>
        <li>
          Curves can be heard: focus an audio trace and press <kbd>Enter</kbd> or <kbd>p</kbd> to play it left
          to right (the pitch follows the value), <kbd>←</kbd> <kbd>→</kbd> to step point by point. Sound
          stays off until you ask for it.
        </li>
        <li>Formulas are typeset with MathML, which screen readers speak and let you explore.</li>
        <li>
          Teachers: add <code>a11y=1</code> to a scene&rsquo;s link to see, beside the scene, the text a
          screen reader receives of it (the A11y view).
        </li>
      </ul>
      <h2>Try it</h2>
      <p>
        A ray passes a sphere&rsquo;s centre at distance {DEMO_B}: along the ray, g(t) ={' '}
        {keepTextParenthesesTogether('(t − 2)²')} + {DEMO_B}² − r² is negative inside the sphere. Change the
        radius and listen.
      </p>
      <div className="a11y-demo">
        <p className="a11y-demo-slider">
          <label htmlFor="demo-r">Radius r</label>{' '}
          <input
            id="demo-r"
            type="range"
            min={0.2}
            max={1.5}
            step={0.05}
            value={r}
            aria-valuetext={r.toFixed(2)}
            data-testid="demo-r"
            onChange={(e) => setR(Number(e.currentTarget.value))}
          />{' '}
          <output htmlFor="demo-r">{r.toFixed(2)}</output>
        </p>
        <DescribedFigure
          label="g(t) along the ray, and where it crosses 0"
          description={describeDemo(r)}
          testId="demo-figure"
        >
          <DemoFigure r={r} />
        </DescribedFigure>
        <p className="small" data-testid="demo-summary">
          {summarizeSeries(curve.ts, curve.gs, { xLabel: 't', yLabel: 'g' })}
        </p>
        <AudioTrace
          label="g(t) along the ray"
          xs={curve.ts}
          ys={curve.gs}
          xLabel="t"
          yLabel="g"
          events={events}
          testId="demo-trace"
        />
        <ShowAsTable
          caption="g(t) along the ray"
          columns={['t', 'g(t)']}
          rows={curve.ts.map((t, i) => [t, curve.gs[i]!])}
          testId="demo-table"
        />
      </div>
      <h2>Known limits</h2>
      <p>
        The 3D views are described in words and can be turned with the keyboard, but their shading is a
        picture. If something does not work for you, please tell the course team that shared the link.
      </p>
    </main>
  );
}
