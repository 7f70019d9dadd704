/**
 * The exam's sphere wearing the texture (z-up; u = azimuth from +x, v = polar angle from +z),
 * with the picked point, the seam (φ = 0, where u jumps from just below 1 back to 0) and the pole
 * axis. Click the sphere to pick a point. Built once per viewport; the texture and the marker are
 * updated in place when the inputs change (no React state per frame).
 */
import { useEffect, useRef } from 'react';
import type * as THREE from 'three';
import { Viewport, type ViewportContext } from '../../../three';
import { nodeCoord, type LookupOptions, type TextureGrid } from '../../../core/texture';
import { textureImage } from '../textureImage';
import { keepTextParenthesesTogether } from '../../../ui/texBreaks';
import type { ShownTexture } from '../model';
import './SphereView.css';

const TW = 256;
const TH = 128;
const SEG_U = 96;
const SEG_V = 48;

interface Objects {
  ctx: ViewportContext;
  tex: THREE.DataTexture;
  nodeLines: THREE.LineSegments;
  marker: THREE.Mesh;
  ray: THREE.Line;
}

export interface SphereViewProps extends ShownTexture {
  normalize: boolean;
  /** Unit direction of the picked point, or null when there is none. */
  dir: [number, number, number] | null;
  onPick: (p: [number, number, number]) => void;
  height: number;
}

function imageFor(
  grid: TextureGrid,
  opts: LookupOptions,
  range: { min: number; max: number },
  normalize: boolean,
): Uint8Array {
  // textureImage's row 0 is v = vMax; a DataTexture's row 0 sits at three's uv.y = 0, and the mesh
  // uses uv.y = 1 − θ/π, so uv.y = 0 is θ = π, i.e. v = vMax as well: no flip needed.
  const window = normalize
    ? { uMin: 0, uMax: 1, vMin: 0, vMax: 1 }
    : { uMin: 0, uMax: 2 * Math.PI, vMin: 0, vMax: Math.PI };
  return new Uint8Array(textureImage(grid, opts, 'bilinear', TW, TH, range, window).buffer);
}

/**
 * The grid's node lines on the sphere (meridians at the nodes' u, parallels at their v), as line
 * segments just above the surface; empty for grids larger than 16 per side.
 */
function nodeLinePositions(grid: TextureGrid, opts: LookupOptions, normalize: boolean): Float32Array {
  if (Math.max(grid.width, grid.height) > 16) return new Float32Array(0);
  const su = normalize ? 2 * Math.PI : 1; // φ = su · u
  const sv = normalize ? Math.PI : 1; // θ = sv · v
  const R = 1.004;
  const pts: number[] = [];
  const seg = 48;
  for (let i = 0; i < grid.width; i++) {
    const phi = su * nodeCoord(i, grid.width, opts.align);
    if (phi >= 2 * Math.PI - 1e-9 && normalize) continue; // u = 1 is the seam again
    for (let k = 0; k < seg; k++) {
      for (const t of [k, k + 1]) {
        const th = (Math.PI * t) / seg;
        pts.push(R * Math.sin(th) * Math.cos(phi), R * Math.sin(th) * Math.sin(phi), R * Math.cos(th));
      }
    }
  }
  for (let j = 0; j < grid.height; j++) {
    const vt = nodeCoord(j, grid.height, opts.align);
    const th = sv * (opts.vflip ? 1 - vt : vt);
    if (th <= 1e-9 || th >= Math.PI - 1e-9) continue; // a pole, not a circle
    for (let k = 0; k < 2 * seg; k++) {
      for (const t of [k, k + 1]) {
        const ph = (2 * Math.PI * t) / (2 * seg);
        pts.push(R * Math.sin(th) * Math.cos(ph), R * Math.sin(th) * Math.sin(ph), R * Math.cos(th));
      }
    }
  }
  return new Float32Array(pts);
}

export function SphereView({ grid, opts, range, normalize, dir, onPick, height }: SphereViewProps) {
  const objs = useRef<Objects | null>(null);
  const latest = useRef({ grid, opts, range, normalize, dir, onPick });
  latest.current = { grid, opts, range, normalize, dir, onPick };

  const applyMarker = (o: Objects, d: [number, number, number] | null) => {
    o.marker.visible = !!d;
    o.ray.visible = !!d;
    if (d) {
      o.marker.position.set(d[0], d[1], d[2]);
      const pos = o.ray.geometry.getAttribute('position') as THREE.BufferAttribute;
      pos.setXYZ(1, d[0] * 1.25, d[1] * 1.25, d[2] * 1.25);
      pos.needsUpdate = true;
    }
    o.ctx.invalidate();
  };

  useEffect(() => {
    const o = objs.current;
    if (!o) return;
    o.tex.image.data = imageFor(grid, opts, range, normalize);
    o.tex.needsUpdate = true;
    o.nodeLines.geometry.setAttribute(
      'position',
      new o.ctx.THREE.Float32BufferAttribute(nodeLinePositions(grid, opts, normalize), 3),
    );
    o.ctx.invalidate();
  }, [grid, opts, range, normalize]);

  useEffect(() => {
    if (objs.current) applyMarker(objs.current, dir);
  }, [dir]);

  const setup = (ctx: ViewportContext) => {
    const T = ctx.THREE;
    const L = latest.current;
    // lat-long sphere with our own (u, v): uv.x = φ/2π, uv.y = 1 − θ/π; the seam column is duplicated
    const pos: number[] = [];
    const uv: number[] = [];
    const idx: number[] = [];
    for (let b = 0; b <= SEG_V; b++) {
      const th = (Math.PI * b) / SEG_V;
      for (let a = 0; a <= SEG_U; a++) {
        const ph = (2 * Math.PI * a) / SEG_U;
        pos.push(Math.sin(th) * Math.cos(ph), Math.sin(th) * Math.sin(ph), Math.cos(th));
        uv.push(a / SEG_U, 1 - b / SEG_V);
      }
    }
    const row = SEG_U + 1;
    for (let b = 0; b < SEG_V; b++)
      for (let a = 0; a < SEG_U; a++) {
        const p = b * row + a;
        idx.push(p, p + row, p + 1, p + 1, p + row, p + row + 1);
      }
    const geo = new T.BufferGeometry();
    geo.setAttribute('position', new T.Float32BufferAttribute(pos, 3));
    geo.setAttribute('uv', new T.Float32BufferAttribute(uv, 2));
    geo.setIndex(idx);
    geo.computeVertexNormals();
    const tex = new T.DataTexture(imageFor(L.grid, L.opts, L.range, L.normalize), TW, TH, T.RGBAFormat);
    tex.colorSpace = T.SRGBColorSpace;
    tex.magFilter = T.LinearFilter;
    tex.minFilter = T.LinearFilter;
    tex.wrapS = T.ClampToEdgeWrapping;
    tex.needsUpdate = true;
    const mesh = new T.Mesh(geo, new T.MeshLambertMaterial({ map: tex, side: T.FrontSide }));
    ctx.scene.add(mesh);

    // seam: the meridian φ = 0 (u = 0 ≡ 1), drawn just above the surface
    const seamPts: number[] = [];
    for (let b = 0; b <= 64; b++) {
      const th = (Math.PI * b) / 64;
      seamPts.push(Math.sin(th) * 1.004, 0, Math.cos(th) * 1.004);
    }
    const seamGeo = new T.BufferGeometry();
    seamGeo.setAttribute('position', new T.Float32BufferAttribute(seamPts, 3));
    const seam = new T.Line(seamGeo, new T.LineBasicMaterial({ color: 0xe4572e }));
    ctx.scene.add(seam);
    // pole axis
    const axisGeo = new T.BufferGeometry();
    axisGeo.setAttribute('position', new T.Float32BufferAttribute([0, 0, -1.35, 0, 0, 1.35], 3));
    const axis = new T.Line(axisGeo, new T.LineBasicMaterial({ color: 0x888888 }));
    ctx.scene.add(axis);
    const xGeo = new T.BufferGeometry();
    xGeo.setAttribute('position', new T.Float32BufferAttribute([0, 0, 0, 1.45, 0, 0], 3));
    const xAxis = new T.Line(xGeo, new T.LineBasicMaterial({ color: 0xe4572e }));
    ctx.scene.add(xAxis);

    const nodeGeo = new T.BufferGeometry();
    nodeGeo.setAttribute(
      'position',
      new T.Float32BufferAttribute(nodeLinePositions(L.grid, L.opts, L.normalize), 3),
    );
    const nodeLines = new T.LineSegments(
      nodeGeo,
      new T.LineBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.45 }),
    );
    ctx.scene.add(nodeLines);

    const marker = new T.Mesh(
      new T.SphereGeometry(0.045, 16, 12),
      new T.MeshBasicMaterial({ color: 0xffffff }),
    );
    const ring = new T.Mesh(
      new T.SphereGeometry(0.065, 16, 12),
      new T.MeshBasicMaterial({ color: 0x111111, side: T.BackSide }),
    );
    marker.add(ring);
    ctx.scene.add(marker);
    const rayGeo = new T.BufferGeometry();
    rayGeo.setAttribute('position', new T.Float32BufferAttribute([0, 0, 0, 0, 0, 1], 3));
    const ray = new T.Line(rayGeo, new T.LineBasicMaterial({ color: 0xffffff }));
    ctx.scene.add(ray);

    ctx.camera.position.set(3.1, 0.9, 2.3); // faces the seam and the exam's point (φ = 45°)
    ctx.camera.lookAt(0, 0, 0);
    ctx.controls.target.set(0, 0, 0);
    ctx.controls.update();

    const o: Objects = { ctx, tex, nodeLines, marker, ray };
    objs.current = o;
    applyMarker(o, L.dir);

    // click (not drag) to pick a point on the sphere
    const el = ctx.renderer.domElement;
    let down: { x: number; y: number } | null = null;
    const raycaster = new T.Raycaster();
    const onDown = (e: PointerEvent) => {
      down = { x: e.clientX, y: e.clientY };
    };
    const onUp = (e: PointerEvent) => {
      if (!down) return;
      const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
      down = null;
      if (moved > 4) return;
      const r = el.getBoundingClientRect();
      const ndc = new T.Vector2(
        ((e.clientX - r.left) / r.width) * 2 - 1,
        -((e.clientY - r.top) / r.height) * 2 + 1,
      );
      raycaster.setFromCamera(ndc, ctx.camera);
      const hit = raycaster.intersectObject(mesh, false)[0];
      if (hit) latest.current.onPick([hit.point.x, hit.point.y, hit.point.z]);
    };
    el.addEventListener('pointerdown', onDown);
    el.addEventListener('pointerup', onUp);
    return () => {
      el.removeEventListener('pointerdown', onDown);
      el.removeEventListener('pointerup', onUp);
      objs.current = null;
      for (const obj of [mesh, seam, axis, xAxis, nodeLines, marker, ray]) ctx.scene.remove(obj);
      geo.dispose();
      tex.dispose();
      (mesh.material as THREE.Material).dispose();
      seamGeo.dispose();
      nodeLines.geometry.dispose();
      (nodeLines.material as THREE.Material).dispose();
      axisGeo.dispose();
      xGeo.dispose();
      rayGeo.dispose();
      marker.geometry.dispose();
      ring.geometry.dispose();
    };
  };

  return (
    <Viewport
      ariaLabel="A sphere wearing the texture; click it to pick a point"
      height={height}
      setup={setup}
      testId="sphere-view"
      toolsAt="top"
    >
      <div className="tx-sphere-legend" aria-hidden="true">
        <span className="tx-seam-key" /> seam φ = 0 {keepTextParenthesesTogether('(u = 0 ≡ 1)')} · grey: pole
        axis · white: the grid’s node lines
      </div>
    </Viewport>
  );
}
