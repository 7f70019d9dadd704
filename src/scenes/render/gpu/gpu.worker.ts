/**
 * The GPU renderer's worker: it owns the WebGL2 context and runs the frames (./gpuRenderer), so
 * the page's thread never waits for the shader to compile or for the GPU to finish a frame. One
 * sample per pixel per animation frame while the page asks it to run, the sums read back at 1, 2,
 * 4 … samples per pixel and at the target (./gpuProtocol).
 */
import { createGpuRenderer, renderContext, type GpuRenderer } from './gpuRenderer';
import { isCheckpoint, type FromGpuWorker, type ToGpuWorker } from './gpuProtocol';

const scope = self as unknown as {
  postMessage(m: FromGpuWorker, transfer?: Transferable[]): void;
  onmessage: ((e: MessageEvent<ToGpuWorker>) => void) | null;
  requestAnimationFrame?: (f: () => void) => number;
};
const post = (m: FromGpuWorker, transfer: Transferable[] = []) => scope.postMessage(m, transfer);
// a canvas on the page: its animation frames; none (the comparison's): as fast as the GPU takes them
let shown = false;
const nextFrame = (f: () => void) =>
  shown && scope.requestAnimationFrame ? scope.requestAnimationFrame(f) : setTimeout(f, shown ? 16 : 0);

let renderer: GpuRenderer | null = null;
let pending: ToGpuWorker[] = [];
let target = 0;
let looping = false;
let image = 0;
let runStart = 0;
let runFrom = 0;
let pixels = 0;

function read(count: number, id: number): void {
  void renderer?.readBack().then((rgba) => {
    if (rgba && id === image) post({ kind: 'sums', id, count, rgba }, [rgba.buffer]);
  });
}

function frame(): void {
  const r = renderer;
  if (!r || r.count >= target || r.gl.isContextLost()) {
    looping = false;
    return;
  }
  r.step();
  r.display();
  const n = r.count;
  post({
    kind: 'frame',
    id: image,
    count: n,
    samplesPerSecond: (pixels * (n - runFrom)) / ((performance.now() - runStart) / 1000),
  });
  if (isCheckpoint(n, target)) read(n, image);
  nextFrame(frame);
}

function handle(m: ToGpuWorker): void {
  if (!renderer) {
    pending.push(m);
    return;
  }
  if (m.kind === 'load') {
    image = m.id;
    renderer.load(m.uniforms, m.seed);
    renderer.display();
    target = 0;
  } else if (m.kind === 'run') {
    target = m.target;
    runStart = performance.now();
    runFrom = renderer.count;
    if (renderer.count >= target) {
      if (renderer.count > target) post({ kind: 'held', id: image, count: renderer.count });
      if (renderer.count > 0) read(renderer.count, image);
    } else if (!looping) {
      looping = true;
      nextFrame(frame);
    }
  }
}

scope.onmessage = (e) => {
  const m = e.data;
  if (m.kind !== 'init') return handle(m);
  shown = m.canvas !== null;
  const canvas = m.canvas ?? new OffscreenCanvas(1, 1);
  pixels = m.res * m.res;
  canvas.addEventListener('webglcontextlost', () =>
    post({ kind: 'failed', why: 'the WebGL context was lost' }),
  );
  const gl = renderContext(canvas);
  if (!gl) {
    const probe = canvas.getContext('webgl2');
    post({
      kind: 'failed',
      why: probe
        ? 'WebGL2 here lacks EXT_color_buffer_float, so it cannot sum samples in a float target'
        : 'this browser gives no WebGL2 context to a worker',
    });
    return;
  }
  void createGpuRenderer(gl, m.res).then((r) => {
    if (typeof r === 'string') return post({ kind: 'failed', why: r });
    renderer = r;
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    post({
      kind: 'ready',
      renderer: `${String(gl.getParameter(gl.RENDERER) ?? '')} ${dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) ?? '') : ''}`,
    });
    const queued = pending;
    pending = [];
    queued.forEach(handle);
  });
};
