/**
 * The shared three.js viewport engine: one renderer, a perspective camera with z up, orbit
 * controls, rendering on demand. Loaded lazily by {@link ../three/Viewport} only when a viewport
 * comes on screen, so three.js never sits in a chunk that does not draw 3D.
 */
import type * as Three from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import * as THREE from './threeSubset';
import { nextTask, SLICE_MS } from '../ui/chunked';
import { probeWebGL, takeSpare, webglAvailable } from './webglProbe';
import type { Vec3 } from '../core/vec3';

/**
 * The part of three.js the scenes' 3D views use (./threeSubset.ts), handed to them as `ctx.THREE`
 * (they must not import three themselves, or it would load with the scene instead of with the
 * first viewport).
 */
export type ThreeModule = typeof THREE;

export interface ViewportContext {
  THREE: ThreeModule;
  scene: Three.Scene;
  camera: Three.PerspectiveCamera;
  renderer: Three.WebGLRenderer;
  controls: OrbitControls;
  /** Request one render (coalesced into the next animation frame). */
  invalidate: () => void;
  /**
   * Remember the current camera (position, target, zoom) as the home view that "Reset view" and
   * the Home key return to. The viewport saves it after the scene's first setup; call this after
   * re-fitting the camera (e.g. when a preset moves everything far away).
   */
  saveHomeView: () => void;
  /**
   * Register a per-frame callback (dt in seconds, capped at 0.1). Frames keep coming while any
   * callback returns true; return false to stop asking. Returns an unregister function.
   */
  onFrame: (cb: (dt: number) => boolean) => () => void;
}

/** Screen directions of the world axes, for the axis triad (x right, y up; z towards the viewer). */
export interface AxisDirs {
  x: Vec3;
  y: Vec3;
  z: Vec3;
  /** Distance from the camera to the orbit target. */
  distance: number;
}

export interface Engine {
  ctx: ViewportContext;
  /** Orbit the camera about the controls' target (radians; polar > 0 moves towards the top). */
  orbitBy: (azimuth: number, polar: number) => void;
  /** Move the camera towards (factor < 1) or away from (factor > 1) the target. */
  zoomBy: (factor: number) => void;
  /** Back to the saved home view (the camera after the scene's first setup, or the last saveHomeView). */
  resetView: () => void;
  /** Remember the current camera as the home view. */
  saveHomeView: () => void;
  /** Called after every render with the world axes' directions on screen. Returns an unregister function. */
  onAfterRender: (cb: (axes: AxisDirs) => void) => () => void;
  /** Visible on screen and tab not hidden: frames run only then. */
  setVisible: (v: boolean) => void;
  /**
   * Compile the shaders of everything in the scene now, in short tasks that yield (call it after
   * the scene's setup). Resolves when every program is linked and checked, or when the engine is
   * disposed. No frame is drawn before {@link Engine.start}.
   */
  warmUp: () => Promise<void>;
  /** Allow frames: the first one is drawn as soon as the view is on screen. */
  start: () => void;
  dispose: () => void;
}

/** Shortest time between two frames on a software WebGL (ms): 10 frames per second at most. */
const SOFTWARE_FRAME_MS = 100;

/**
 * Wait before checking each compiled program (ms): the GPU side compiles meanwhile, and the check
 * (a synchronous round trip) then finds it done instead of blocking the page.
 */
const COMPILE_WAIT_MS = 16;

/** Longest wait for the GPU side to finish the warm-up's draws before the first frame (ms). */
const FENCE_MAX_MS = 3000;

/** A promise of the next task (so that the work after it is a task of its own). */
const yieldTask = () => new Promise<void>((resolve) => nextTask(resolve));

/**
 * Start an engine in separate tasks, yielding in between (a phone counts every task over 50 ms
 * as blocking): the WebGL probe (its context creation), the renderer, then camera and controls.
 * Resolves to null when WebGL is missing, or when `alive()` turns false meanwhile (nothing is left
 * behind then). Throws what three.js throws when the renderer cannot be created.
 */
export async function startEngine(
  container: HTMLElement,
  ariaLabel: string,
  alive: () => boolean,
): Promise<Engine | null> {
  await yieldTask();
  if (!alive()) return null;
  if (!webglAvailable()) return null;
  await yieldTask();
  if (!alive()) return null;
  const made = createRenderer();
  await yieldTask();
  if (!alive()) {
    made.renderer.dispose();
    return null;
  }
  return createEngine(container, ariaLabel, made);
}

/**
 * The renderer: on a software WebGL the probe's context if still unused (./webglProbe).
 * Its own task at start: three's context set-up (extensions, capabilities, state) alone is tens
 * of ms on a phone.
 */
function createRenderer(): { renderer: Three.WebGLRenderer; software: boolean } {
  // On a software WebGL (no usable GPU) every frame is drawn by the CPU and, with software
  // compositing, read back synchronously on the main thread: at device pixel ratio 1.75–2 with 4×
  // multisampling that is tens of ms per frame, and an animation of a few seconds blocks the page
  // for seconds (measured: Lighthouse mobile, hemisphere). There, draw at 1 CSS px per pixel and
  // without multisampling: several times fewer pixels to shade and read back.
  const software = probeWebGL().software;
  const adopted = software ? takeSpare() : null;
  const renderer = adopted
    ? new THREE.WebGLRenderer({
        canvas: adopted.canvas,
        context: adopted.gl,
        antialias: false,
        alpha: true,
        powerPreference: 'low-power',
      })
    : new THREE.WebGLRenderer({ antialias: !software, alpha: true, powerPreference: 'low-power' });
  renderer.setPixelRatio(software ? 1 : Math.min(window.devicePixelRatio || 1, 2));
  renderer.setClearColor(0x000000, 0);
  return { renderer, software };
}

export function createEngine(
  container: HTMLElement,
  ariaLabel: string,
  made: { renderer: Three.WebGLRenderer; software: boolean } = createRenderer(),
): Engine {
  const { renderer, software } = made;
  const canvas = renderer.domElement;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', ariaLabel);
  // the canvas joins the page in start(): a canvas outside the document is never composited, so the
  // warm-up's draws cost no synchronous read-back (with software compositing, every presented
  // WebGL frame is read back on the main thread, waiting for the GPU side to finish it)

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  camera.position.set(2.6, -3.2, 2.2);
  camera.lookAt(0, 0, 0);
  scene.add(new THREE.AmbientLight(0xffffff, 0.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(2, -3, 5);
  scene.add(sun);

  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  // keyboard orbit/zoom is handled by the Viewport (arrows orbit, +/− zoom), not OrbitControls' pan keys

  let visible = false;
  /** No frame before start() (after warmUp): the first render would compile every shader in one task. */
  let started = false;
  let disposed = false;
  let needsRender = true;
  let raf = 0;
  let last = 0;
  const frameCbs = new Set<(dt: number) => boolean>();
  const renderCbs = new Set<(axes: AxisDirs) => void>();
  let animating = false;

  // Software WebGL: at most one frame per SOFTWARE_FRAME_MS, each followed by idle time (every
  // frame there is a synchronous readback; an animation at 60 fps would leave no time for input).
  const minFrameMs = software ? SOFTWARE_FRAME_MS : 0;
  let lastFrame = -Infinity;
  let timer = 0;

  const frame = (now: number) => {
    raf = 0;
    if (!visible) return;
    lastFrame = performance.now();
    const dt = last ? Math.min((now - last) / 1000, 0.1) : 1 / 60;
    last = now;
    animating = false;
    for (const cb of [...frameCbs]) {
      if (cb(dt)) animating = true;
    }
    renderer.render(scene, camera);
    needsRender = false;
    if (renderCbs.size) {
      const e = camera.matrixWorld.elements; // column j = camera axis j in world space; row i = world axis i in camera space
      const axes: AxisDirs = {
        x: [e[0], e[4], e[8]],
        y: [e[1], e[5], e[9]],
        z: [e[2], e[6], e[10]],
        distance: camera.position.distanceTo(controls.target),
      };
      for (const cb of renderCbs) cb(axes);
    }
    if (animating) schedule();
    else last = 0;
  };
  const schedule = () => {
    if (raf || timer || !visible || !started) return;
    const wait = lastFrame + minFrameMs - performance.now();
    if (wait > 0) {
      timer = window.setTimeout(() => {
        timer = 0;
        if (!raf && visible) raf = requestAnimationFrame(frame);
      }, wait);
    } else raf = requestAnimationFrame(frame);
  };
  const invalidate = () => {
    needsRender = true;
    schedule();
  };
  controls.addEventListener('change', invalidate);

  const resize = () => {
    const w = Math.max(1, container.clientWidth);
    const h = Math.max(1, container.clientHeight);
    renderer.setSize(w, h, true);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    invalidate();
  };
  const ro = new ResizeObserver(resize);
  ro.observe(container);
  resize();

  const saveHomeView = () => controls.saveState();
  const tmp = new THREE.Vector3();
  const orbitBy = (azimuth: number, polar: number) => {
    // z is up: spherical coordinates of the camera about the target
    const off = tmp.copy(camera.position).sub(controls.target);
    const rho = off.length();
    if (!(rho > 0)) return;
    let az = Math.atan2(off.y, off.x) + azimuth;
    const eps = 1e-3;
    const minP = Math.max(eps, controls.minPolarAngle);
    const maxP = Math.min(Math.PI - eps, controls.maxPolarAngle);
    let pol = Math.acos(Math.max(-1, Math.min(1, off.z / rho))) - polar;
    pol = Math.max(minP, Math.min(maxP, pol));
    if (Number.isFinite(controls.minAzimuthAngle) || Number.isFinite(controls.maxAzimuthAngle)) {
      az = Math.max(controls.minAzimuthAngle, Math.min(controls.maxAzimuthAngle, az));
    }
    camera.position.set(
      controls.target.x + rho * Math.sin(pol) * Math.cos(az),
      controls.target.y + rho * Math.sin(pol) * Math.sin(az),
      controls.target.z + rho * Math.cos(pol),
    );
    camera.lookAt(controls.target);
    controls.update();
    invalidate();
  };
  const zoomBy = (factor: number) => {
    const off = tmp.copy(camera.position).sub(controls.target);
    const rho = off.length();
    if (!(rho > 0) || !(factor > 0)) return;
    const next = Math.max(controls.minDistance, Math.min(controls.maxDistance, rho * factor));
    camera.position.copy(controls.target).addScaledVector(off, next / rho);
    controls.update();
    invalidate();
  };

  // Shader programs are compiled and linked by the GPU process (or thread) while the page goes on;
  // only checking them (three does that on a program's first use) waits for it. The GPU pipelines
  // (SwiftShader compiles each at its first draw) are built when a draw is executed, and waited for
  // when the frame is presented. Without KHR_parallel_shader_compile (SwiftShader has none) all of
  // that fell into the first frame: one long task of hundreds of ms on a phone. Here, each step is a
  // task of its own: the programs issued a few objects at a time; each program checked after a short
  // wait (the GPU side compiles meanwhile); each object drawn alone into the canvas while it is not
  // in the document (buffers uploaded, pipelines built, nothing presented); then a fence, polled
  // (never waited on), until the GPU side has done it all.
  const renderables = () => {
    const out: Three.Object3D[] = [];
    scene.traverse((o) => {
      const m = o as Three.Object3D & {
        isMesh?: boolean;
        isPoints?: boolean;
        isLine?: boolean;
        isSprite?: boolean;
      };
      if (m.isMesh || m.isPoints || m.isLine || m.isSprite) out.push(o);
    });
    return out;
  };
  /** Render the scene with only `o` (and its ancestors) visible; the visibilities are restored. */
  const drawAlone = (o: Three.Object3D, all: Three.Object3D[]) => {
    const was = new Map<Three.Object3D, boolean>();
    for (const x of all) {
      was.set(x, x.visible);
      x.visible = false;
    }
    for (let a: Three.Object3D | null = o; a && a !== scene; a = a.parent) {
      if (!was.has(a)) was.set(a, a.visible);
      a.visible = true;
    }
    try {
      renderer.render(scene, camera);
    } finally {
      for (const [x, v] of was) x.visible = v;
    }
  };
  const pause = (ms: number) => new Promise((r) => setTimeout(r, ms));
  const warmUp = async () => {
    await yieldTask();
    if (disposed) return;
    const objects = renderables();
    const gl = renderer.getContext();
    let t0 = performance.now();
    for (const o of objects) {
      renderer.compile(o, camera, scene);
      if (performance.now() - t0 >= SLICE_MS) {
        gl.flush();
        await yieldTask();
        if (disposed) return;
        t0 = performance.now();
      }
    }
    gl.flush();
    for (const program of renderer.info.programs ?? []) {
      await pause(COMPILE_WAIT_MS);
      if (disposed) return;
      program.getUniforms(); // the first use: link status, uniforms and attributes
    }
    if (canvas.isConnected) return; // started already: frames do the rest
    for (const o of objects) {
      await yieldTask();
      if (disposed || canvas.isConnected) return;
      if (o.parent) drawAlone(o, objects);
    }
    if (!(gl instanceof WebGL2RenderingContext)) return;
    const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    const until = performance.now() + FENCE_MAX_MS;
    try {
      while (sync && gl.getSyncParameter(sync, gl.SYNC_STATUS) !== gl.SIGNALED && performance.now() < until) {
        await pause(COMPILE_WAIT_MS);
        if (disposed) return;
      }
    } finally {
      if (!disposed && sync) gl.deleteSync(sync);
    }
  };

  const ctx: ViewportContext = {
    THREE,
    scene,
    camera,
    renderer,
    controls,
    invalidate,
    saveHomeView,
    onFrame: (cb) => {
      frameCbs.add(cb);
      invalidate();
      return () => frameCbs.delete(cb);
    },
  };

  return {
    ctx,
    orbitBy,
    zoomBy,
    saveHomeView,
    resetView: () => {
      controls.reset(); // restores the saved target/position/zoom and dispatches 'change'
      invalidate();
    },
    onAfterRender: (cb) => {
      renderCbs.add(cb);
      invalidate();
      return () => renderCbs.delete(cb);
    },
    warmUp,
    start: () => {
      if (started || disposed) return;
      started = true;
      container.prepend(canvas); // under the triad and the buttons, as when it was added at creation
      needsRender = true;
      schedule();
    },
    setVisible: (v) => {
      visible = v;
      if (v && (needsRender || frameCbs.size)) schedule();
      if (!v && (raf || timer)) {
        cancelAnimationFrame(raf);
        clearTimeout(timer);
        raf = 0;
        timer = 0;
        last = 0;
      }
    },
    dispose: () => {
      disposed = true;
      if (raf) cancelAnimationFrame(raf);
      clearTimeout(timer);
      ro.disconnect();
      controls.dispose();
      scene.traverse((o) => {
        const m = o as Three.Mesh;
        m.geometry?.dispose?.();
        const mat = m.material as Three.Material | Three.Material[] | undefined;
        if (Array.isArray(mat)) mat.forEach((x) => x.dispose());
        else mat?.dispose?.();
      });
      renderer.dispose();
      canvas.remove();
    },
  };
}
