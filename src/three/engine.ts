/**
 * The shared three.js viewport engine: one renderer, a perspective camera with z up, orbit
 * controls, rendering on demand. Loaded lazily by {@link ../three/Viewport} only when a viewport
 * comes on screen, so three.js never sits in a chunk that does not draw 3D.
 */
import type * as Three from 'three';
import {
  AmbientLight,
  ArrowHelper,
  AxesHelper,
  BackSide,
  BufferAttribute,
  BufferGeometry,
  ClampToEdgeWrapping,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  DynamicDrawUsage,
  Float32BufferAttribute,
  Frustum,
  FrontSide,
  GridHelper,
  Line,
  LineBasicMaterial,
  LineDashedMaterial,
  LineLoop,
  LineSegments,
  LinearFilter,
  Material,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshStandardMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Points,
  PointsMaterial,
  RGBAFormat,
  Raycaster,
  SRGBColorSpace,
  Scene,
  Sphere,
  SphereGeometry,
  Vector2,
  Vector3,
  WebGLRenderer,
  WireframeGeometry,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

/**
 * The part of three.js the scenes' 3D views use, handed to them as `ctx.THREE` (they must not
 * import three themselves, or it would load with the scene instead of with the first viewport).
 * Named imports rather than `import * as THREE` let the bundler drop the rest of three.js
 * (loaders, animation, most geometries and materials). A view that needs another class adds it here.
 */
const THREE = {
  AmbientLight,
  ArrowHelper,
  AxesHelper,
  BackSide,
  BufferAttribute,
  BufferGeometry,
  ClampToEdgeWrapping,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  DynamicDrawUsage,
  Float32BufferAttribute,
  Frustum,
  FrontSide,
  GridHelper,
  Line,
  LineBasicMaterial,
  LineDashedMaterial,
  LineLoop,
  LineSegments,
  LinearFilter,
  Material,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshStandardMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Points,
  PointsMaterial,
  RGBAFormat,
  Raycaster,
  SRGBColorSpace,
  Scene,
  Sphere,
  SphereGeometry,
  Vector2,
  Vector3,
  WebGLRenderer,
  WireframeGeometry,
} as const;

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
   * Register a per-frame callback (dt in seconds, capped at 0.1). Frames keep coming while any
   * callback returns true; return false to stop asking. Returns an unregister function.
   */
  onFrame: (cb: (dt: number) => boolean) => () => void;
}

export interface Engine {
  ctx: ViewportContext;
  /** Visible on screen and tab not hidden: frames run only then. */
  setVisible: (v: boolean) => void;
  dispose: () => void;
}

/** True when the browser can give a WebGL context (checked without three, so no console error). */
export function webglAvailable(): boolean {
  try {
    const c = document.createElement('canvas');
    return !!(c.getContext('webgl2') ?? c.getContext('webgl'));
  } catch {
    return false;
  }
}

export function createEngine(container: HTMLElement, ariaLabel: string): Engine {
  const renderer = new WebGLRenderer({ antialias: true, alpha: true, powerPreference: 'low-power' });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.setClearColor(0x000000, 0);
  const canvas = renderer.domElement;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', ariaLabel);
  container.appendChild(canvas);

  const scene = new Scene();
  const camera = new PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  camera.position.set(2.6, -3.2, 2.2);
  camera.lookAt(0, 0, 0);
  scene.add(new AmbientLight(0xffffff, 0.6));
  const sun = new DirectionalLight(0xffffff, 1.6);
  sun.position.set(2, -3, 5);
  scene.add(sun);

  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  controls.listenToKeyEvents(container);

  let visible = false;
  let needsRender = true;
  let raf = 0;
  let last = 0;
  const frameCbs = new Set<(dt: number) => boolean>();
  let animating = false;

  const frame = (now: number) => {
    raf = 0;
    if (!visible) return;
    const dt = last ? Math.min((now - last) / 1000, 0.1) : 1 / 60;
    last = now;
    animating = false;
    for (const cb of [...frameCbs]) {
      if (cb(dt)) animating = true;
    }
    renderer.render(scene, camera);
    needsRender = false;
    if (animating) schedule();
    else last = 0;
  };
  const schedule = () => {
    if (!raf && visible) raf = requestAnimationFrame(frame);
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

  const ctx: ViewportContext = {
    THREE,
    scene,
    camera,
    renderer,
    controls,
    invalidate,
    onFrame: (cb) => {
      frameCbs.add(cb);
      invalidate();
      return () => frameCbs.delete(cb);
    },
  };

  return {
    ctx,
    setVisible: (v) => {
      visible = v;
      if (v && (needsRender || frameCbs.size)) schedule();
      if (!v && raf) {
        cancelAnimationFrame(raf);
        raf = 0;
        last = 0;
      }
    },
    dispose: () => {
      if (raf) cancelAnimationFrame(raf);
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
