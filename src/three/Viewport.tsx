import { useEffect, useEffectEvent, useId, useRef, useState } from 'react';
import type { AxisDirs, Engine, ViewportContext } from './engine';
import { observeVisibility, touchOnly, useSeenOnce } from '../ui/useInView';
import { afterPaint } from '../ui/afterPaint';
import { usePresent } from '../ui/pageKeys';
import { useKeyHelp, type KeyHelp } from '../ui/shortcuts';
import { viewportKey } from './viewMoves';
import { ViewControls } from './ViewControls';
import './viewport.css';

export type { ViewportContext } from './engine';

export interface ViewportProps {
  /** What the 3D view shows, for screen readers. */
  ariaLabel: string;
  height?: number | string;
  /**
   * Build the scene once the engine exists. Return a cleanup. Keep the ctx in a ref to update
   * objects later and call ctx.invalidate() after each change.
   */
  setup: (ctx: ViewportContext) => (() => void) | void;
  testId?: string;
  /**
   * Mark +x as the azimuth origin (φ = 0) in the axis triad. On by default: every scene that uses
   * spherical angles measures φ from +x with z up. Pass false where φ means nothing.
   */
  phiZero?: boolean;
  /**
   * Where the orbit and zoom buttons stand: the bottom-right corner (the default), or the top-right
   * under "Reset view" for a view whose own overlay (a legend) takes the bottom.
   */
  toolsAt?: 'bottom' | 'top';
  children?: React.ReactNode;
}

const ON_VIEW = 'On a focused 3D view';
/** The view's keys, for the `?` list: to start it (touch screens), then to move its camera. */
const START_KEY: readonly KeyHelp[] = [{ keys: 'Enter', label: 'start the 3D view', where: ON_VIEW }];
const VIEW_KEYS: readonly KeyHelp[] = [
  { keys: '← → ↑ ↓', label: 'orbit (with Shift: finer)', where: ON_VIEW },
  { keys: '+ / −', label: 'zoom in / out', where: ON_VIEW },
  { keys: 'Home', label: 'back to the opening view', where: ON_VIEW },
];

/**
 * A three.js viewport: three.js is imported only when the viewport scrolls near the screen;
 * renders on demand; pauses while off screen or while the tab is hidden. Drag to orbit, scroll
 * to zoom; focus it and use the arrow keys to orbit, + / − to zoom, Home (or "Reset view") to go
 * back to the scene's opening camera. A small triad labels the world axes (and φ = 0).
 */
export function Viewport({
  ariaLabel,
  height = 360,
  setup,
  testId,
  phiZero = true,
  toolsAt = 'bottom',
  children,
}: ViewportProps) {
  const hintId = useId();
  const triad = useRef<SVGSVGElement>(null);
  const box = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  // On a phone or tablet the 3D view starts when asked (a tap on its button, or Enter on the
  // focused view): three.js on a phone's CPU is the heaviest part of a scene's load, and
  // an idle view does not capture the swipes that scroll the page. Elsewhere it starts on sight.
  const [wanted, setWanted] = useState(() => !touchOnly());
  const [engine, setEngine] = useState<Engine | null>(null);
  const [status, setStatus] = useState<'loading' | 'ready' | 'no-webgl'>('loading');
  const idle = !wanted;
  const setupRef = useRef(setup);
  setupRef.current = setup;
  // ariaLabel is applied at creation (the latest one); later changes are applied by the effect below
  const labelNow = useEffectEvent(() => ariaLabel);

  useEffect(() => {
    if (!seen || !wanted || !box.current) return;
    let alive = true;
    let eng: Engine | null = null;
    let stopVis = () => {};
    const container = box.current;
    // The start is split into tasks that yield (on a phone each was a long task): the
    // probe, the renderer, the scene's setup (effect below), the shaders (warmUp), the first frame.
    // after the frame in progress has painted: the page's first content does not wait for three.js
    afterPaint()
      .then(() => import('./engine'))
      .then((m) => m.startEngine(container, labelNow(), () => alive))
      .then(
        (created) => {
          if (!alive) {
            created?.dispose();
            return;
          }
          if (!created) {
            setStatus('no-webgl');
            return;
          }
          eng = created;
          let onScreen = false;
          const update = () => eng?.setVisible(onScreen && !document.hidden);
          const stopIO = observeVisibility(container, (v) => {
            onScreen = v;
            update();
          });
          document.addEventListener('visibilitychange', update);
          stopVis = () => {
            stopIO();
            document.removeEventListener('visibilitychange', update);
          };
          setEngine(created);
        },
        () => {
          if (alive) setStatus('no-webgl');
        },
      );
    return () => {
      alive = false;
      stopVis();
      eng?.dispose();
      setEngine(null);
    };
  }, [seen, wanted]);

  useEffect(() => {
    engine?.ctx.renderer.domElement.setAttribute('aria-label', ariaLabel);
  }, [engine, ariaLabel]);

  // setup runs once per engine; a scene changes its objects later through the ctx (kept in a ref).
  // The first setup places the scene's camera: that is the home view "Reset view" returns to
  const homeSaved = useRef<Engine | null>(null);
  useEffect(() => {
    if (!engine) return;
    const cleanup = setupRef.current(engine.ctx);
    if (homeSaved.current !== engine) {
      homeSaved.current = engine;
      engine.saveHomeView();
    }
    engine.ctx.invalidate();
    return () => {
      if (typeof cleanup === 'function') cleanup();
      engine.ctx.invalidate();
    };
  }, [engine]);

  // after the first setup: the shaders, compiled in short tasks; until then the placeholder stays
  useEffect(() => {
    if (!engine) return;
    let alive = true;
    engine.warmUp().then(
      () => {
        if (alive) setStatus('ready');
      },
      () => {
        if (alive) setStatus('ready'); // the first frame compiles what is left (and reports any error)
      },
    );
    return () => {
      alive = false;
    };
  }, [engine]);

  // the first frame once ready (the triad and the reset button are in the DOM by then)
  useEffect(() => {
    if (engine && status === 'ready') engine.start();
  }, [engine, status]);

  // the axis triad follows the camera after every render (direct DOM writes: no React render);
  // in classroom mode it is drawn larger, its labels at the classroom's 18 px
  const present = usePresent();
  const scale = present ? TRIAD_PRESENT_SCALE : 1;
  const scaleRef = useRef(scale);
  scaleRef.current = scale;
  useEffect(() => {
    if (!engine) return;
    return engine.onAfterRender((axes) => drawTriad(triad.current, axes, scaleRef.current));
  }, [engine]);
  useEffect(() => engine?.ctx.invalidate(), [engine, scale]);

  const onKeyDown = (e: React.KeyboardEvent<HTMLDivElement>) => {
    if (idle && e.target === e.currentTarget && (e.key === 'Enter' || e.key === ' ')) {
      e.preventDefault();
      setWanted(true);
      return;
    }
    if (!engine || e.ctrlKey || e.metaKey || e.altKey) return;
    const tag = (e.target as HTMLElement).tagName;
    if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA') return;
    if (viewportKey(engine, e)) e.preventDefault(); // no page scroll; classroom shortcuts skip handled keys
  };

  const ready = status === 'ready';
  useKeyHelp(idle ? START_KEY : ready ? VIEW_KEYS : null);
  return (
    <div className="viewport-wrap">
      <div
        className={idle ? 'viewport viewport-idle' : 'viewport'}
        ref={box}
        style={{ height }}
        tabIndex={0}
        data-testid={testId}
        data-status={idle ? 'idle' : status}
        aria-label={
          idle
            ? `${ariaLabel} (3D view not started: press Enter to start it)`
            : `${ariaLabel} (drag, the buttons or arrow keys to orbit, scroll, the buttons or + / − to zoom, Home to reset the view)`
        }
        aria-describedby={hintId}
        role="group"
        onKeyDown={onKeyDown}
      >
        {idle ? (
          <div className="viewport-msg viewport-poster">
            <p>{ariaLabel}</p>
            <button
              type="button"
              className="viewport-start"
              onClick={() => {
                setWanted(true);
                box.current?.focus(); // the button goes away: keep the keyboard's place on the view
              }}
              data-testid={testId ? `${testId}-start` : undefined}
            >
              Show the 3D view
            </button>
            <p className="viewport-poster-note">
              On phones and tablets the 3D view starts when you ask for it.
            </p>
          </div>
        ) : status === 'loading' ? (
          <p className="viewport-msg">Loading 3D view…</p>
        ) : null}
        {status === 'no-webgl' ? (
          <p className="viewport-msg">
            This browser cannot create a WebGL context, so the 3D view is off; every number on the page still
            works.
          </p>
        ) : null}
        {ready ? (
          <svg
            className="viewport-triad"
            ref={triad}
            viewBox={`${-TRIAD_HALF * scale} ${-TRIAD_HALF * scale} ${2 * TRIAD_HALF * scale} ${2 * TRIAD_HALF * scale}`}
            aria-hidden="true"
            data-testid={testId ? `${testId}-axes` : undefined}
          >
            {(['x', 'y', 'z'] as const).map((k) => (
              <g key={k} className={`axis-${k}`} data-axis={k}>
                <line x1="0" y1="0" x2="0" y2="0" />
                <text x="0" y="0" textAnchor="middle" dominantBaseline="central">
                  {k}
                </text>
                {k === 'x' && phiZero ? (
                  <text className="phi0" x="0" y="0" textAnchor="middle" dominantBaseline="central">
                    φ = 0
                  </text>
                ) : null}
              </g>
            ))}
          </svg>
        ) : null}
        {ready ? (
          <button
            type="button"
            className="viewport-reset"
            onClick={() => engine?.resetView()}
            data-testid={testId ? `${testId}-reset` : undefined}
          >
            Reset view
          </button>
        ) : null}
        {ready && engine ? <ViewControls engine={engine} testId={testId} at={toolsAt} /> : null}
        {/* the scene's overlays act on the view: not shown before it starts */}
        {idle ? null : children}
      </div>
      <p className="viewport-hint" id={hintId}>
        Drag to orbit, scroll to zoom, or use the buttons in the corner. Keyboard: focus the view, then ← → ↑
        ↓ orbit (Shift: finer), + / − zoom, Home resets.
      </p>
    </div>
  );
}

/** Half the triad's viewBox at scale 1 (88 user units across, drawn 5.5rem wide). */
const TRIAD_HALF = 44;
/**
 * The triad's scale in classroom mode: its labels (13 user units at scale 1) at 18 px, the whole
 * drawing scaled with them so that the labels keep their places beside the axes.
 */
const TRIAD_PRESENT_SCALE = 18 / 13;

/**
 * Place the triad's three axes: world axis k seen from the camera is (axes[k][0], axes[k][1]) on
 * screen. `scale` enlarges the drawing (its viewBox is scaled alike).
 */
function drawTriad(svg: SVGSVGElement | null, axes: AxisDirs, scale: number) {
  if (!svg) return;
  const R = 25 * scale;
  const order = (['x', 'y', 'z'] as const).map((k) => ({ k, v: axes[k] })).sort((a, b) => a.v[2] - b.v[2]);
  for (const { k, v } of order) {
    const g = svg.querySelector<SVGGElement>(`g[data-axis="${k}"]`);
    if (!g) continue;
    const sx = v[0] * R;
    const sy = -v[1] * R;
    const len = Math.hypot(v[0], v[1]);
    const line = g.querySelector('line')!;
    line.setAttribute('x2', sx.toFixed(2));
    line.setAttribute('y2', sy.toFixed(2));
    // an axis pointing away from the viewer is drawn dashed
    line.setAttribute('stroke-dasharray', v[2] < -0.2 ? `${3 * scale} ${2 * scale}` : 'none');
    // labels sit beyond the tip, pushed out further when the axis is seen end-on
    const ux = len > 1e-6 ? v[0] / len : 0.7;
    const uy = len > 1e-6 ? -v[1] / len : -0.7;
    const lx = sx + ux * 8 * scale;
    const ly = sy + uy * 8 * scale;
    const texts = g.querySelectorAll('text');
    texts[0].setAttribute('x', lx.toFixed(2));
    texts[0].setAttribute('y', ly.toFixed(2));
    if (texts[1]) {
      // "φ = 0" under (or above, near the bottom edge) the x label
      texts[1].setAttribute('x', Math.max(-22 * scale, Math.min(22 * scale, lx)).toFixed(2));
      texts[1].setAttribute('y', (ly > 18 * scale ? ly - 12 * scale : ly + 12 * scale).toFixed(2));
    }
    svg.appendChild(g); // nearer axes on top
  }
  // for tests and tools: the camera's distance and the x axis direction, as drawn
  svg.dataset.distance = axes.distance.toPrecision(6);
  svg.dataset.xAxis = axes.x.map((c) => c.toFixed(4)).join(',');
}
