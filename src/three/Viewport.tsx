import { useEffect, useRef, useState } from 'react';
import type { Engine, ViewportContext } from './engine';
import { observeVisibility, useSeenOnce } from '../ui/useInView';

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
  /** Re-run setup (after cleanup) when these change. */
  deps?: readonly unknown[];
  testId?: string;
  children?: React.ReactNode;
}

/**
 * A three.js viewport: three.js is imported only when the viewport scrolls near the screen;
 * renders on demand; pauses while off screen or while the tab is hidden. Drag to orbit, scroll
 * to zoom; focus it and use the arrow keys to pan.
 */
export function Viewport({ ariaLabel, height = 360, setup, deps = [], testId, children }: ViewportProps) {
  const box = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  const [engine, setEngine] = useState<Engine | null>(null);
  const [status, setStatus] = useState<'loading' | 'ready' | 'no-webgl'>('loading');
  const setupRef = useRef(setup);
  setupRef.current = setup;

  useEffect(() => {
    if (!seen || !box.current) return;
    let alive = true;
    let eng: Engine | null = null;
    let stopVis = () => {};
    const container = box.current;
    import('./engine').then((m) => {
      if (!alive) return;
      if (!m.webglAvailable()) {
        setStatus('no-webgl');
        return;
      }
      try {
        eng = m.createEngine(container, ariaLabel);
      } catch {
        setStatus('no-webgl');
        return;
      }
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
      setEngine(eng);
      setStatus('ready');
    });
    return () => {
      alive = false;
      stopVis();
      eng?.dispose();
      setEngine(null);
    };
    // ariaLabel is applied at creation; later changes are applied below
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [seen]);

  useEffect(() => {
    engine?.ctx.renderer.domElement.setAttribute('aria-label', ariaLabel);
  }, [engine, ariaLabel]);

  useEffect(() => {
    if (!engine) return;
    const cleanup = setupRef.current(engine.ctx);
    engine.ctx.invalidate();
    return () => {
      if (typeof cleanup === 'function') cleanup();
      engine.ctx.invalidate();
    };
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [engine, ...deps]);

  return (
    <div
      className="viewport"
      ref={box}
      style={{ height }}
      tabIndex={0}
      data-testid={testId}
      data-status={status}
      aria-label={`${ariaLabel} (drag to orbit, scroll to zoom, arrow keys to pan)`}
      role="group"
    >
      {status === 'loading' ? <p className="viewport-msg">Loading 3D view…</p> : null}
      {status === 'no-webgl' ? (
        <p className="viewport-msg">This browser cannot create a WebGL context, so the 3D view is off; every number on the page still works.</p>
      ) : null}
      {children}
    </div>
  );
}
