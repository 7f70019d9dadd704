/**
 * The 3D view's point buffers: one Float32 position attribute (the directions), one Uint8 colour
 * attribute and one Float32 (ξ₁, ξ₂) attribute, preallocated for n points and filled as the worker
 * streams them, with how far they are filled and uploaded.
 */
import type { ViewportContext } from '../../../three';
import { MAX_N } from '../params';

/** How far the buffers are filled, uploaded and wanted. */
export interface Fill {
  /** Points whose direction, colour and (ξ₁, ξ₂) are in the buffers: [0, filled). */
  filled: number;
  /** Of those, the points marked for upload to the GPU (drawn from the next render): [0, uploaded). */
  uploaded: number;
  /** Points the current frame wants drawn. */
  target: number;
}

/**
 * Buffers sized for n points, rounded up to a power of two (at least 4096, at most MAX_N): sized
 * for 10⁶ from the start, the first upload of ~23 MB cost a phone's main thread hundreds of ms on
 * load, though the exam's default shows 512 points.
 */
export function capacityFor(n: number): number {
  let c = 4096;
  while (c < n && c < MAX_N) c *= 2;
  return Math.min(c, MAX_N);
}

export function pointBuffers(T: ViewportContext['THREE'], cap: number) {
  const geom = new T.BufferGeometry();
  const pos = new T.BufferAttribute(new Float32Array(3 * cap), 3);
  pos.setUsage(T.DynamicDrawUsage);
  const col = new T.BufferAttribute(new Uint8Array(3 * cap), 3, true);
  col.setUsage(T.DynamicDrawUsage);
  const xi = new T.BufferAttribute(new Float32Array(2 * cap), 2);
  xi.setUsage(T.DynamicDrawUsage);
  geom.setAttribute('position', pos);
  geom.setAttribute('color', col);
  geom.setAttribute('xi', xi);
  geom.setDrawRange(0, 0);
  geom.boundingSphere = new T.Sphere(new T.Vector3(0, 0, 0.5), 1.6);
  return { geom, pos, col, xi };
}
