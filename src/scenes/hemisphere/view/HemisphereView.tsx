/**
 * The 3D hemisphere: samples appear, animated, from 1 up to n (≤ 10⁶), with play / pause / step /
 * reset (and the classroom shortcuts). One preallocated Float32Array position attribute (and one
 * Uint8 colour attribute) is filled in place, batch by batch, and only the new range is uploaded;
 * setDrawRange shows the first `shown` points. Nothing renders once the growth has finished
 * unless the camera moves. The warped (ξ₁, ξ₂) grid is drawn on the hemisphere.
 */
import { useEffect, useEffectEvent, useRef, useState } from 'react';
import type * as THREE from 'three';
import { Viewport, type ViewportContext } from '../../../three';
import { Toggle, Transport, useShortcuts } from '../../../ui';
import { fillSequence2D, type SequenceKind } from '../../../core/random';
import type { Lobe } from '../model';
import { MAX_N } from '../params';
import { xiColor } from './colors';

const BATCH = 1 << 15;
/** At most this many new points per animation frame, so no frame does more than a few ms of work. */
const MAX_PER_FRAME = 1 << 16;
/** While the camera is being dragged, draw at most this many points (level of detail). */
const ORBIT_LOD = 200_000;
/** Seconds per decade of growth. */
const DECADE_SECONDS = 0.7;
const GRID_LINES = 8;
const GRID_SEGMENTS = 48;

interface Anim {
  playing: boolean;
  shown: number;
  target: number;
  /** Wall-clock time (ms) of the last growth step; growth follows real time, not frame count. */
  last: number;
  /** When paused: fill up to this count, MAX_PER_FRAME points per frame (0 = nothing to fill). */
  fillTo: number;
  /** Measured generation speed (points per ms, running average) and the last frame's length (ms). */
  pointsPerMs: number;
  frameMs: number;
}

/**
 * New points allowed this frame: MAX_PER_FRAME, or more when frames are slow anyway (software
 * rendering): generation may take up to a quarter of the last frame's length.
 */
function perFrame(a: Anim): number {
  if (!a.pointsPerMs) return MAX_PER_FRAME;
  return Math.max(MAX_PER_FRAME, Math.floor(a.pointsPerMs * 0.25 * Math.min(a.frameMs, 4000)));
}

export interface HemisphereViewProps {
  lobe: Lobe | null;
  kind: SequenceKind;
  seed: number;
  n: number;
  /** Frame-time probe for tests and the report: last frame durations (ms). */
  height?: number;
}

export function HemisphereView({ lobe, kind, seed, n, height = 380 }: HemisphereViewProps) {
  const ctxRef = useRef<ViewportContext | null>(null);
  const objs = useRef<{
    geom: THREE.BufferGeometry;
    pos: THREE.BufferAttribute;
    col: THREE.BufferAttribute;
    points: THREE.Points;
    material: THREE.PointsMaterial;
    grid: THREE.LineSegments | null;
  } | null>(null);
  const anim = useRef<Anim>({ playing: true, shown: 0, target: n, last: 0, fillTo: 0, pointsPerMs: 0, frameMs: 16 });
  const cfg = useRef({ lobe, kind, seed, n });
  cfg.current = { lobe, kind, seed, n };
  const label = useRef<HTMLSpanElement>(null);
  const [playing, setPlaying] = useState(true);
  const [showPoints, setShowPoints] = useState(true);
  const [showGrid, setShowGrid] = useState(true);
  const vis = useRef({ points: true, grid: true });
  vis.current = { points: showPoints, grid: showGrid };
  const scratch = useRef<{ u: Float64Array; d: Float64Array; c: number[] } | null>(null);

  const updateLabel = () => {
    if (label.current) label.current.textContent = anim.current.shown.toLocaleString('en-US');
    if (label.current) label.current.dataset.value = String(anim.current.shown);
  };

  /** Generate points [shown, upTo) into the buffers (in batches) and show them. */
  const grow = (upTo: number) => {
    const o = objs.current;
    const { lobe: lb, kind: kd, seed: sd, n: nn } = cfg.current;
    if (!o || !lb) return;
    const a = anim.current;
    const end = Math.min(nn, upTo);
    if (!scratch.current) scratch.current = { u: new Float64Array(2 * BATCH), d: new Float64Array(3 * BATCH), c: [0, 0, 0] };
    const { u, d } = scratch.current;
    const pos = o.pos.array as Float32Array;
    const col = o.col.array as Uint8Array;
    const start = a.shown;
    const t0 = performance.now();
    for (let s = start; s < end; s += BATCH) {
      const e = Math.min(end, s + BATCH);
      const m = e - s;
      fillSequence2D(kd, sd, nn, u, s, e, 0);
      lb.sampleBatch(u, d, m);
      for (let i = 0; i < m; i++) {
        const j = 3 * (s + i);
        pos[j] = d[3 * i]!;
        pos[j + 1] = d[3 * i + 1]!;
        pos[j + 2] = d[3 * i + 2]!;
        xiColor(u[2 * i]!, u[2 * i + 1]!, col, j);
      }
    }
    if (end > start) {
      // generation cost per batch, readable with performance.getEntriesByName('hemisphere-grow')
      const t1 = performance.now();
      try {
        performance.measure('hemisphere-grow', { start: t0, end: t1, detail: end - start });
      } catch {
        /* older engines without measure options: the probe is optional */
      }
      if (end - start >= 1024 && t1 > t0) {
        const pps = (end - start) / (t1 - t0);
        a.pointsPerMs = a.pointsPerMs ? 0.7 * a.pointsPerMs + 0.3 * pps : pps;
      }
      o.pos.clearUpdateRanges();
      o.pos.addUpdateRange(3 * start, 3 * (end - start));
      o.pos.needsUpdate = true;
      o.col.clearUpdateRanges();
      o.col.addUpdateRange(3 * start, 3 * (end - start));
      o.col.needsUpdate = true;
    }
    a.shown = end;
    o.geom.setDrawRange(0, end);
    // bigger dots while there are few of them
    o.material.size = Math.max(1.5, Math.min(7, 9 / Math.pow(Math.max(1, end), 0.18)));
    updateLabel();
  };

  const restart = () => {
    anim.current.shown = 0;
    anim.current.last = 0;
    performance.clearMeasures?.('hemisphere-grow');
    const o = objs.current;
    if (o) o.geom.setDrawRange(0, 0);
    anim.current.fillTo = anim.current.playing ? 0 : cfg.current.n;
    updateLabel();
    ctxRef.current?.invalidate();
  };

  const buildGrid = () => {
    const ctx = ctxRef.current;
    const o = objs.current;
    if (!ctx || !o) return;
    if (o.grid) {
      ctx.scene.remove(o.grid);
      o.grid.geometry.dispose();
      (o.grid.material as THREE.Material).dispose();
      o.grid = null;
    }
    const lb = cfg.current.lobe;
    if (!lb) return;
    const T = ctx.THREE;
    const segs = 2 * (GRID_LINES + 1) * GRID_SEGMENTS;
    const p = new Float32Array(segs * 2 * 3);
    const c = new Float32Array(segs * 2 * 3);
    const v = [0, 0, 0];
    const rgb = [0, 0, 0];
    let k = 0;
    const put = (a: number, b: number) => {
      lb.sample(Math.min(a, 1 - 2 ** -53), Math.min(b, 1 - 2 ** -53), v, 0);
      const s = 1.003; // just above the sphere so the lines are not hidden by the shell
      p[3 * k] = v[0]! * s;
      p[3 * k + 1] = v[1]! * s;
      p[3 * k + 2] = v[2]! * s;
      xiColor(a, b, rgb);
      c[3 * k] = rgb[0]! / 255;
      c[3 * k + 1] = rgb[1]! / 255;
      c[3 * k + 2] = rgb[2]! / 255;
      k++;
    };
    for (let l = 0; l <= GRID_LINES; l++) {
      const fixed = l / GRID_LINES;
      for (let s = 0; s < GRID_SEGMENTS; s++) {
        const t0 = s / GRID_SEGMENTS;
        const t1 = (s + 1) / GRID_SEGMENTS;
        put(fixed, t0);
        put(fixed, t1);
        put(t0, fixed);
        put(t1, fixed);
      }
    }
    const g = new T.BufferGeometry();
    g.setAttribute('position', new T.BufferAttribute(p, 3));
    g.setAttribute('color', new T.BufferAttribute(c, 3));
    const lines = new T.LineSegments(g, new T.LineBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.9 }));
    lines.visible = vis.current.grid;
    ctx.scene.add(lines);
    o.grid = lines;
  };

  const setup = (ctx: ViewportContext) => {
    ctxRef.current = ctx;
    const T = ctx.THREE;
    const geom = new T.BufferGeometry();
    const pos = new T.BufferAttribute(new Float32Array(3 * MAX_N), 3);
    pos.setUsage(T.DynamicDrawUsage);
    const col = new T.BufferAttribute(new Uint8Array(3 * MAX_N), 3, true);
    col.setUsage(T.DynamicDrawUsage);
    geom.setAttribute('position', pos);
    geom.setAttribute('color', col);
    geom.setDrawRange(0, 0);
    geom.boundingSphere = new T.Sphere(new T.Vector3(0, 0, 0.5), 1.2);
    const material = new T.PointsMaterial({ size: 3, sizeAttenuation: false, vertexColors: true });
    const points = new T.Points(geom, material);
    points.frustumCulled = false;
    points.visible = vis.current.points;
    ctx.scene.add(points);

    // the hemisphere shell, its rim, the base disk and the axes
    const shellGeom = new T.SphereGeometry(1, 48, 24, 0, 2 * Math.PI, 0, Math.PI / 2);
    shellGeom.rotateX(Math.PI / 2);
    const shell = new T.Mesh(shellGeom, new T.MeshBasicMaterial({ color: 0x8899aa, transparent: true, opacity: 0.07, depthWrite: false, side: T.DoubleSide }));
    ctx.scene.add(shell);
    const rimPts: number[] = [];
    for (let i = 0; i <= 96; i++) {
      const a = (i / 96) * 2 * Math.PI;
      rimPts.push(Math.cos(a), Math.sin(a), 0);
    }
    const rimGeom = new T.BufferGeometry();
    rimGeom.setAttribute('position', new T.Float32BufferAttribute(rimPts, 3));
    ctx.scene.add(new T.Line(rimGeom, new T.LineBasicMaterial({ color: 0x778899 })));
    const axes: [number[], number][] = [
      [[1.25, 0, 0], 0xd04040],
      [[0, 1.25, 0], 0x30a050],
      [[0, 0, 1.3], 0x3060d0],
    ];
    for (const [end, color] of axes) {
      const g = new T.BufferGeometry();
      g.setAttribute('position', new T.Float32BufferAttribute([0, 0, 0, ...end], 3));
      ctx.scene.add(new T.Line(g, new T.LineBasicMaterial({ color })));
    }
    ctx.camera.position.set(2.2, -2.6, 2.0);
    ctx.camera.lookAt(0, 0, 0.3);
    ctx.controls.target.set(0, 0, 0.3);
    ctx.controls.update();

    objs.current = { geom, pos, col, points, material, grid: null };
    // level of detail while orbiting: the sets are prefixes of well-spread sequences (except the
    // stratified set, whose prefix fills rows in order, so it is always drawn in full)
    const onStart = () => {
      if (cfg.current.kind !== 'stratified' && anim.current.shown > ORBIT_LOD) geom.setDrawRange(0, ORBIT_LOD);
    };
    const onEnd = () => {
      geom.setDrawRange(0, anim.current.shown);
      ctx.invalidate();
    };
    ctx.controls.addEventListener('start', onStart);
    ctx.controls.addEventListener('end', onEnd);
    if (!cfg.current.lobe) {
      anim.current.playing = false;
      setPlaying(false);
    }
    buildGrid();
    restart();

    const stop = ctx.onFrame(() => {
      const a = anim.current;
      const nn = cfg.current.n;
      if (!a.playing && a.fillTo > a.shown && cfg.current.lobe) {
        grow(Math.min(a.fillTo, a.shown + perFrame(a)));
        if (a.shown < a.fillTo) return true;
        a.fillTo = 0;
        return false;
      }
      if (!a.playing || !cfg.current.lobe) {
        a.last = 0;
        return false;
      }
      if (a.shown >= nn) {
        a.playing = false;
        a.last = 0;
        setPlaying(false);
        return false;
      }
      // one decade per DECADE_SECONDS of wall-clock time (so a slow GPU shows bigger steps, not a slower
      // growth); at most 0.25 s of growth per frame after a stall (tab hidden, off screen)
      const now = performance.now();
      const dt = a.last ? Math.min(0.25, (now - a.last) / 1000) : 1 / 60;
      if (a.last) a.frameMs = now - a.last;
      a.last = now;
      const next = Math.min(a.shown + perFrame(a), Math.max(a.shown + 1, Math.ceil(Math.max(1, a.shown) * Math.pow(10, dt / DECADE_SECONDS))));
      grow(next);
      if (a.shown >= nn) {
        a.playing = false;
        a.last = 0;
        setPlaying(false);
        return false;
      }
      return true;
    });
    return () => {
      stop();
      ctx.controls.removeEventListener('start', onStart);
      ctx.controls.removeEventListener('end', onEnd);
      objs.current = null;
      ctxRef.current = null;
    };
  };

  // parameters changed: rebuild the grid, restart the growth (playing) or redraw at once (paused)
  const onParamsChange = useEffectEvent(() => {
    if (!objs.current) return;
    buildGrid();
    anim.current.playing = !!lobe;
    setPlaying(!!lobe);
    restart();
  });
  useEffect(() => onParamsChange(), [lobe, kind, seed, n]);

  useEffect(() => {
    const o = objs.current;
    if (!o) return;
    o.points.visible = showPoints;
    if (o.grid) o.grid.visible = showGrid;
    ctxRef.current?.invalidate();
  }, [showPoints, showGrid]);

  const playPause = () => {
    const a = anim.current;
    if (a.playing) {
      a.playing = false;
      setPlaying(false);
      return;
    }
    if (a.shown >= cfg.current.n) {
      a.shown = 0;
      objs.current?.geom.setDrawRange(0, 0);
    }
    a.playing = true;
    a.fillTo = 0;
    setPlaying(true);
    ctxRef.current?.invalidate();
  };
  const step = () => {
    const a = anim.current;
    a.playing = false;
    setPlaying(false);
    a.fillTo = Math.min(cfg.current.n, a.shown === 0 ? 1 : 2 * a.shown);
    ctxRef.current?.invalidate();
  };
  const reset = () => {
    anim.current.playing = false;
    anim.current.fillTo = 0;
    setPlaying(false);
    anim.current.shown = 0;
    objs.current?.geom.setDrawRange(0, 0);
    updateLabel();
    ctxRef.current?.invalidate();
  };
  useShortcuts({ playPause, step, reset });

  return (
    <div className="hemi-3d">
      <Viewport ariaLabel="Samples of the chosen density on the upper hemisphere, coloured by their (ξ₁, ξ₂)" height={height} setup={setup} testId="hemisphere-3d" />
      <div className="hemi-transport">
        <Transport playing={playing} onPlayPause={playPause} onStep={step} onReset={reset} />
        <Toggle label="points" checked={showPoints} onChange={setShowPoints} />
        <Toggle label="warped (ξ₁, ξ₂) grid" checked={showGrid} onChange={setShowGrid} />
        <span className="hemi-shown">
          showing <span ref={label} data-testid="shown-count" data-value="0">0</span> of {n.toLocaleString('en-US')} points
        </span>
      </div>
    </div>
  );
}
