/**
 * The 3D hemisphere, driven by the shared timeline (src/ui/timeline.ts): what it draws at position
 * t is ../animation's `animFrame` (a pure function of the parameters, the seed and t).
 *
 * - Warp morph (`anim=warp`): every sample and the (ξ₁, ξ₂) grid travel from the unit square (laid
 *   in the base plane, [−1, 1]²) to their directions on the hemisphere as t goes 0 → 1. The points'
 *   mix is done in the vertex shader (one uniform per frame, no per-point work on the CPU); the
 *   grid is mixed on the CPU with `morphPoint` (a few thousand vertices).
 * - Growth (`anim=grow`): the first `growCount(n, t)` samples are drawn (geometric, 0 → n).
 *
 * The preallocated buffers (./pointBuffers) receive the points as the worker streams them
 * (../pointStream: the main thread only copies each chunk in), and at most UPLOAD_PER_FRAME new
 * points go to the GPU per frame; filled points are kept, so scrubbing back and forth costs
 * nothing. Nothing renders while the timeline is paused and the buffers are filled, unless the
 * camera moves.
 */
import { formatCount } from '../../../ui/format';
import { useEffect, useRef } from 'react';
import type * as THREE from 'three';
import { Viewport, type ViewportContext } from '../../../three';
import type { SequenceKind } from '../../../core/random';
import { squarePoint, warpedGrid, type AnimFrame } from '../animation';
import type { Lobe } from '../lobe';
import type { PointsArgs, PointsChunk } from '../jobs';
import { streamPoints } from '../pointStream';
import { capacityFor, pointBuffers, type Fill } from './pointBuffers';
import { pointShade, xiColor } from './colors';
import type { Cell } from '../stratum';
import { patchStratumShader, stratumLayer, stratumUniforms, type StratumLayer } from './stratum3d';
import { nextTask } from '../../../ui/chunked';

/** New points sent to the GPU per frame (3 MB of buffers): one frame never uploads all of 10⁶. */
const UPLOAD_PER_FRAME = 1 << 17;
/** While the camera is being dragged, draw at most this many points (level of detail). */
const ORBIT_LOD = 200_000;
const GRID_SEGMENTS = 48;
/** A change of the point set restarts the stream after this much quiet (a storm of changes starts one). */
const RESTART_MS = 40;

/** The warped grid recedes while a stratum is followed, so the stratum's outline stands out. */
const gridOpacity = (cell: Cell | null) => (cell ? 0.35 : 0.9);

export interface HemisphereViewProps {
  lobe: Lobe;
  /** What the points depend on (../jobs pointsArgsOf): the worker draws them from these. */
  points: PointsArgs;
  kind: SequenceKind;
  seed: number;
  n: number;
  /** The model's frame at the timeline's position (how many points, how far the morph has gone). */
  frame: AnimFrame;
  showPoints: boolean;
  showGrid: boolean;
  /** The followed stratum (its samples marked, its patch and outline drawn), or null. */
  cell?: Cell | null;
  /** Height of the 3D viewport: CSS pixels, or a CSS length (the classroom stage sizes it to the screen). */
  height?: number | string;
  /** The dark theme: the points and grid at full brightness (shaded on the light theme, ./colors). */
  dark?: boolean;
  /**
   * Set to a function that shows another frame directly (per animation frame, without a React
   * render); `frame` is then the frame of the component's last render.
   */
  drawRef?: { current: ((frame: AnimFrame) => void) | null };
}

export function HemisphereView({
  lobe,
  points: pointArgs,
  kind,
  seed,
  n,
  frame,
  showPoints,
  showGrid,
  height = 380,
  drawRef,
  cell = null,
  dark = false,
}: HemisphereViewProps) {
  const ctxRef = useRef<ViewportContext | null>(null);
  const objs = useRef<{
    geom: THREE.BufferGeometry;
    pos: THREE.BufferAttribute;
    col: THREE.BufferAttribute;
    xi: THREE.BufferAttribute;
    points: THREE.Points;
    material: THREE.PointsMaterial;
    morph: { value: number };
    grid: THREE.LineSegments<THREE.BufferGeometry, THREE.LineBasicMaterial> | null;
    /** The grid's vertices in the square (s = 0) and on the hemisphere (s = 1), for `lobe`. */
    gridEnds: { a: Float64Array; b: Float64Array; lobe: Lobe } | null;
    stratum: StratumLayer;
  } | null>(null);
  const fill = useRef<Fill>({ filled: 0, uploaded: 0, target: frame.shown });
  const cfg = useRef({ lobe, pointArgs, kind, seed, n, frame, showPoints, showGrid, cell, dark });
  cfg.current = { lobe, pointArgs, kind, seed, n, frame, showPoints, showGrid, cell, dark };
  const label = useRef<HTMLSpanElement>(null);
  /** Stops the stream in flight (or the pending restart). */
  const stopStream = useRef<() => void>(() => {});

  const drawn = () => Math.min(fill.current.uploaded, fill.current.target);
  const updateLabel = () => {
    const v = drawn();
    // per frame while the warp morph plays: write only on a change (toLocaleString is slow)
    if (label.current && label.current.dataset.value !== String(v)) {
      label.current.textContent = formatCount(v);
      label.current.dataset.value = String(v);
    }
  };

  /**
   * Copy a chunk of the stream into the buffers (the GPU gets it over the next frames). The points
   * of the previous parameters stay drawn until the new stream's first chunk replaces them.
   */
  const receive = (c: PointsChunk) => {
    const o = objs.current;
    const a = fill.current;
    if (!o || c.start + c.count > o.pos.count) return;
    if (c.start === 0) a.filled = a.uploaded = 0;
    if (c.start !== a.filled) return;
    const t0 = performance.now();
    (o.pos.array as Float32Array).set(c.pos, 3 * c.start);
    (o.col.array as Uint8Array).set(c.col, 3 * c.start);
    (o.xi.array as Float32Array).set(c.xi, 2 * c.start);
    a.filled = c.start + c.count;
    // the main thread's cost per chunk, readable with performance.getEntriesByName('hemisphere-grow')
    try {
      performance.measure('hemisphere-grow', { start: t0, end: performance.now(), detail: c.count });
    } catch {
      /* older engines without measure options: the probe is optional */
    }
    ctxRef.current?.invalidate();
  };

  /** Mark up to UPLOAD_PER_FRAME more of the filled points for upload; true while some are left. */
  const upload = (): boolean => {
    const o = objs.current;
    const a = fill.current;
    if (!o) return false;
    const end = Math.min(a.filled, a.target, a.uploaded + UPLOAD_PER_FRAME);
    if (end > a.uploaded) {
      for (const [attr, w] of [
        [o.pos, 3],
        [o.col, 3],
        [o.xi, 2],
      ] as const) {
        // ranges add up until the next render uploads them (three merges and clears them then)
        attr.addUpdateRange(w * a.uploaded, w * (end - a.uploaded));
        attr.needsUpdate = true;
      }
      a.uploaded = end;
    }
    return a.uploaded < Math.min(a.filled, a.target);
  };

  /** Start the stream of the current parameters from point 0 (after `delayMs`). */
  const restartStream = (delayMs: number) => {
    stopStream.current();
    const { pointArgs: args, lobe: lb } = cfg.current;
    let stop: (() => void) | null = null;
    const go = () => {
      stop = streamPoints(args, lb, receive);
    };
    const timer = delayMs > 0 ? window.setTimeout(go, delayMs) : (go(), 0);
    stopStream.current = () => {
      window.clearTimeout(timer);
      stop?.();
    };
  };

  /** The draw range, the point size and the count at what is drawn (within a frame: no new frame). */
  const showDrawn = () => {
    const o = objs.current;
    if (!o) return;
    const v = drawn();
    o.geom.setDrawRange(0, v);
    // bigger dots while there are few of them
    o.material.size = Math.max(1.5, Math.min(7, 9 / Math.pow(Math.max(1, v), 0.18)));
    updateLabel();
  };

  /** Show what the current frame asks for: the draw range, the point size, the morph. */
  const apply = () => {
    const o = objs.current;
    if (!o) return;
    showDrawn();
    const s = cfg.current.frame.s;
    o.morph.value = s;
    if (o.grid && o.gridEnds) {
      const p = o.grid.geometry.getAttribute('position') as THREE.BufferAttribute;
      const arr = p.array as Float32Array;
      const { a, b } = o.gridEnds;
      const r = 1 - s;
      for (let i = 0; i < arr.length; i++) arr[i] = a[i] * r + b[i] * s; // the model's morphPoint, unrolled
      p.needsUpdate = true;
    }
    o.stratum.morph(s);
    ctxRef.current?.invalidate();
  };

  const buildGrid = () => {
    const ctx = ctxRef.current;
    const o = objs.current;
    if (!ctx || !o) return;
    if (o.grid) {
      ctx.scene.remove(o.grid);
      o.grid.geometry.dispose();
      o.grid.material.dispose();
      o.grid = null;
    }
    const T = ctx.THREE;
    const g0 = warpedGrid(cfg.current.lobe, 0, GRID_SEGMENTS);
    const g1 = warpedGrid(cfg.current.lobe, 1, GRID_SEGMENTS);
    const lift = 1.003; // just above the sphere so the lines are not hidden by the shell
    for (let i = 0; i < g1.pos.length; i++) g1.pos[i] *= lift;
    const verts = g0.xi.length / 2;
    const c = new Float32Array(3 * verts);
    const rgb = [0, 0, 0];
    for (let k = 0; k < verts; k++) {
      xiColor(g0.xi[2 * k], g0.xi[2 * k + 1], rgb);
      c[3 * k] = rgb[0] / 255;
      c[3 * k + 1] = rgb[1] / 255;
      c[3 * k + 2] = rgb[2] / 255;
    }
    const g = new T.BufferGeometry();
    g.setAttribute('position', new T.BufferAttribute(new Float32Array(3 * verts), 3));
    g.setAttribute('color', new T.BufferAttribute(c, 3));
    const lines = new T.LineSegments(
      g,
      new T.LineBasicMaterial({
        vertexColors: true,
        color: new T.Color().setScalar(pointShade(cfg.current.dark)),
        transparent: true,
        opacity: gridOpacity(cfg.current.cell),
      }),
    );
    lines.frustumCulled = false;
    lines.visible = cfg.current.showGrid;
    ctx.scene.add(lines);
    o.grid = lines;
    o.gridEnds = { a: g0.pos, b: g1.pos, lobe: cfg.current.lobe };
  };

  const setup = (ctx: ViewportContext) => {
    ctxRef.current = ctx;
    const T = ctx.THREE;
    const { geom, pos, col, xi } = pointBuffers(T, capacityFor(cfg.current.n));
    const material = new T.PointsMaterial({ size: 3, sizeAttenuation: false, vertexColors: true });
    material.color.setScalar(pointShade(cfg.current.dark));
    const morph = { value: cfg.current.frame.s };
    const strata = stratumUniforms(T);
    // the warp morph on the GPU: mix(square point of (ξ₁, ξ₂), direction, s), as the model's morphPoint
    material.onBeforeCompile = (shader) => {
      shader.uniforms.uMorph = morph;
      shader.vertexShader = shader.vertexShader
        .replace('#include <common>', '#include <common>\nattribute vec2 xi;\nuniform float uMorph;')
        .replace(
          '#include <begin_vertex>',
          'vec3 transformed = mix(vec3(2.0 * xi.x - 1.0, 2.0 * xi.y - 1.0, 0.0), vec3(position), uMorph);',
        );
      patchStratumShader(shader, strata);
    };
    material.customProgramCacheKey = () => 'hemisphere-morph';
    const points = new T.Points(geom, material);
    points.frustumCulled = false;
    points.visible = cfg.current.showPoints;
    ctx.scene.add(points);

    // the hemisphere shell, its rim, the outline of the unit square in the base plane, and the axes
    const shellGeom = new T.SphereGeometry(1, 48, 24, 0, 2 * Math.PI, 0, Math.PI / 2);
    const shell = new T.Mesh(
      shellGeom,
      new T.MeshBasicMaterial({
        color: 0x8899aa,
        transparent: true,
        opacity: 0.07,
        depthWrite: false,
        side: T.DoubleSide,
      }),
    );
    shell.rotation.x = Math.PI / 2; // the cap from y up to z up (on the object: rotating the geometry's vertices cost a phone ~30 ms)
    ctx.scene.add(shell);
    const rimPts: number[] = [];
    for (let i = 0; i <= 96; i++) {
      const a = (i / 96) * 2 * Math.PI;
      rimPts.push(Math.cos(a), Math.sin(a), 0);
    }
    const rimGeom = new T.BufferGeometry();
    rimGeom.setAttribute('position', new T.Float32BufferAttribute(rimPts, 3));
    ctx.scene.add(new T.Line(rimGeom, new T.LineBasicMaterial({ color: 0x778899 })));
    const sq: number[] = [];
    for (const [a, b] of [
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
      [0, 0],
    ] as const)
      sq.push(...(squarePoint(a, b) as number[]));
    const sqGeom = new T.BufferGeometry();
    sqGeom.setAttribute('position', new T.Float32BufferAttribute(sq, 3));
    ctx.scene.add(
      new T.Line(sqGeom, new T.LineBasicMaterial({ color: 0x99a3ad, transparent: true, opacity: 0.6 })),
    );
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

    const stratum = stratumLayer(ctx, strata);
    stratum.set(cfg.current.lobe, cfg.current.cell);
    objs.current = { geom, pos, col, xi, points, material, morph, grid: null, gridEnds: null, stratum };
    // level of detail while orbiting: the sets are prefixes of well-spread sequences (except the
    // stratified set, whose prefix fills rows in order, so it is always drawn in full)
    const onStart = () => {
      if (cfg.current.kind !== 'stratified' && drawn() > ORBIT_LOD)
        objs.current?.geom.setDrawRange(0, ORBIT_LOD);
    };
    const onEnd = () => {
      objs.current?.geom.setDrawRange(0, drawn());
      ctx.invalidate();
    };
    ctx.controls.addEventListener('start', onStart);
    ctx.controls.addEventListener('end', onEnd);
    fill.current.filled = fill.current.uploaded = 0;
    fill.current.target = cfg.current.frame.shown;
    restartStream(0);
    apply();
    // the grid in a task of its own (before the engine's shader warm-up, which queues after it)
    nextTask(() => {
      if (objs.current === null || ctxRef.current !== ctx) return;
      buildGrid();
      apply();
    });

    // each frame: the next points of the stream to the GPU, up to what the frame needs; frames
    // are requested only while there is something left to upload
    const stop = ctx.onFrame(() => {
      const before = fill.current.uploaded;
      const more = upload();
      if (fill.current.uploaded !== before) showDrawn();
      return more;
    });
    return () => {
      stopStream.current();
      stop();
      ctx.controls.removeEventListener('start', onStart);
      ctx.controls.removeEventListener('end', onEnd);
      stratum.dispose();
      objs.current = null;
      ctxRef.current = null;
    };
  };

  // the point set changed: the buffers start over; the grid (the lobe's alone) stays for a new seed
  const onPointsChange = useRef(() => {});
  onPointsChange.current = () => {
    const o = objs.current;
    const ctx = ctxRef.current;
    if (!o || !ctx) return;
    // the buffers hold n points (rounded up to a power of two): a new geometry when that changes
    const cap = capacityFor(n);
    if (cap !== o.pos.count) {
      const b = pointBuffers(ctx.THREE, cap);
      o.points.geometry = b.geom;
      o.geom.dispose();
      Object.assign(o, b);
      fill.current.filled = fill.current.uploaded = 0;
    }
    if (o.gridEnds?.lobe !== lobe) buildGrid();
    performance.clearMeasures?.('hemisphere-grow');
    restartStream(RESTART_MS);
    apply();
  };
  const pointsKey = JSON.stringify(pointArgs);
  useEffect(() => onPointsChange.current(), [lobe, pointsKey]);

  // the followed stratum: its patch and outline for this lobe, its samples marked by the shader
  const onCellChange = useRef(() => {});
  onCellChange.current = () => {
    const o = objs.current;
    if (!o) return;
    o.stratum.set(lobe, cell);
    if (o.grid) o.grid.material.opacity = gridOpacity(cell);
    apply();
  };
  useEffect(() => onCellChange.current(), [lobe, cell]);

  // every timeline position: the new target and morph (the fill loop runs only if points are missing)
  const onFrameChange = useRef(() => {});
  onFrameChange.current = () => {
    fill.current.target = frame.shown;
    if (!objs.current) return;
    apply();
  };
  useEffect(() => onFrameChange.current(), [frame]);
  if (drawRef) {
    drawRef.current = (f: AnimFrame) => {
      cfg.current.frame = f;
      fill.current.target = f.shown;
      if (objs.current) apply();
    };
  }

  useEffect(() => {
    const o = objs.current;
    if (!o) return;
    o.points.visible = showPoints;
    if (o.grid) o.grid.visible = showGrid;
    ctxRef.current?.invalidate();
  }, [showPoints, showGrid]);

  // a theme switch: the vertex colours are multiplied by the materials' colour
  useEffect(() => {
    const o = objs.current;
    if (!o) return;
    o.material.color.setScalar(pointShade(dark));
    o.grid?.material.color.setScalar(pointShade(dark));
    ctxRef.current?.invalidate();
  }, [dark]);

  return (
    <div className="hemi-3d">
      <Viewport
        ariaLabel={`3D view: ${formatCount(n)} samples of p(ω) = ${lobe.label}, (ξ₁, ξ₂) points and grid travelling from the unit square to their directions on the upper hemisphere${cell ? `; stratum (${cell.i}, ${cell.j}) marked` : ''}`}
        height={height}
        setup={setup}
        testId="hemisphere-3d"
      />
      <p className="hemi-shown">
        showing{' '}
        <span ref={label} data-testid="shown-count" data-value="0">
          0
        </span>{' '}
        of {formatCount(n)} points
      </p>
    </div>
  );
}
