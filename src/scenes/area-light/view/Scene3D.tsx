/**
 * The 3D view of #/area-light (z-up): the floor and shading point p with its normal, the unit
 * hemisphere around p, the emitter (bright front, dark back), the optional occluder, the drawn
 * samples (on the light and their directions on the hemisphere, or cosine directions), and the
 * Q6(a) patch with its projection onto the unit sphere. Built once; objects are updated in place
 * when the model changes (no React state per frame, renders on demand).
 */
import { useEffect, useRef } from 'react';
import type * as THREE from 'three';
import { Viewport, type ViewportContext } from '../../../three';
import type { ThreeModule } from '../../../three/engine';
import type { LightStrategy, Vec3 } from '../../../core/lights';
import type { AreaLightModel } from '../model';
import type { PatchModel } from '../patch';

export interface Scene3DProps {
  model: AreaLightModel;
  strategy: LightStrategy;
  /** Sample points (on the light) or unit directions (cosine), xyz per sample. */
  samples: Float64Array;
  /** Estimator term per sample (0 = the sample contributes nothing). */
  terms: Float64Array;
  patch: PatchModel | null;
  /** Pixels, or a CSS length (classroom mode: '100%' of the stage). */
  height: number | string;
  dark: boolean;
  /** Samples arrived so far (the animation's position): the first `count` are drawn, rays to the newest. */
  count?: number;
  /** Set to a function that shows another count directly (per animation frame, without a React render). */
  countRef?: { current: ((count: number) => void) | null };
}

/** The view's accessible name. */
const VIEW_LABEL =
  '3D view: the floor, the shading point with its unit hemisphere, the rectangular light, the samples and the Q6(a) patch';

const MAX_SAMPLES = 1024;
const RAYS = 24;

/** The view's objects (from createParts), its context, and the draw-range bookkeeping. */
type Objects = ReturnType<typeof createParts> & {
  ctx: ViewportContext;
  /** hitsBefore[k] = how many of the first k samples contribute (for the draw ranges). */
  hitsBefore: Int32Array;
};

function setQuad(mesh: THREE.Mesh | THREE.LineLoop, c: readonly Vec3[], order: readonly number[]) {
  const pos = mesh.geometry.getAttribute('position') as THREE.BufferAttribute;
  order.forEach((k, i) => pos.setXYZ(i, c[k][0], c[k][1], c[k][2]));
  pos.needsUpdate = true;
  mesh.geometry.computeBoundingSphere();
}

function frame(o: Objects, m: AreaLightModel) {
  const [px, py, pz] = m.p;
  const tx = (px + m.lc[0]) / 2,
    ty = (py + m.lc[1]) / 2,
    tz = (pz + m.lc[2]) / 2;
  const span = Math.max(2.5, Math.hypot(m.lc[0] - px, m.lc[1] - py, m.lc[2] - pz) + Math.max(m.w, m.h));
  const cam = o.ctx.camera;
  // Low, from the side: the emitting underside of a ceiling light is in view.
  cam.position.set(tx + 0.8 * span, ty - 1.3 * span, pz + 0.25 * span);
  cam.far = Math.max(1000, span * 20);
  cam.updateProjectionMatrix();
  o.ctx.controls.target.set(tx, ty, tz);
  o.ctx.controls.update();
  o.ctx.invalidate();
}

/** What the view shows: the props that the drawing functions read. */
type Shown = Pick<Scene3DProps, 'model' | 'strategy' | 'samples' | 'terms' | 'patch' | 'dark' | 'count'>;

/** The animated part: how many samples are drawn, and rays from p to the RAYS newest (cheap: per frame). */
function applyCount(o: Objects, s: Shown) {
  const { model: m, strategy: st, samples: smp, terms: tm, count: cnt } = s;
  const n = Math.min(MAX_SAMPLES, tm.length, cnt ?? tm.length);
  const [px, py, pz] = m.p;
  const rayPos = o.rays.geometry.getAttribute('position') as THREE.BufferAttribute;
  const first = Math.max(0, n - RAYS);
  for (let i = first; i < n; i++) {
    const j = i - first;
    const ex = st === 'cosine' ? px + smp[3 * i] : smp[3 * i];
    const ey = st === 'cosine' ? py + smp[3 * i + 1] : smp[3 * i + 1];
    const ez = st === 'cosine' ? pz + smp[3 * i + 2] : smp[3 * i + 2];
    rayPos.setXYZ(2 * j, px, py, pz);
    rayPos.setXYZ(2 * j + 1, ex, ey, ez);
  }
  rayPos.needsUpdate = true;
  const hits = o.hitsBefore[n] ?? 0;
  o.samplesOn.geometry.setDrawRange(0, st === 'cosine' ? 0 : hits);
  o.samplesOnMiss.geometry.setDrawRange(0, st === 'cosine' ? 0 : n - hits);
  o.samplesDir.geometry.setDrawRange(0, hits);
  o.samplesDirMiss.geometry.setDrawRange(0, n - hits);
  o.rays.geometry.setDrawRange(0, 2 * (n - first));
  o.rays.geometry.computeBoundingSphere();
  o.ctx.invalidate();
}

/** Everything else: the light, occluder, point, floor, all samples' positions and colours, the patch. */
function apply(o: Objects, s: Shown, framedFor: { current: string }) {
  const { model: m, strategy: st, samples: smp, terms: tm, patch: pt, dark: dk } = s;
  const T = o.ctx.THREE;
  const c = m.light.corners;
  // Corners are counter-clockwise about ex × ey = −n_l; seen from the emitting side that is
  // clockwise, so the front triangles use the reversed order.
  setQuad(o.lightFront, c, [0, 2, 1, 0, 3, 2]);
  setQuad(o.lightBack, c, [0, 2, 1, 0, 3, 2]);
  setQuad(o.lightEdge, c, [0, 1, 2, 3]);
  o.occluder.visible = !!m.occluder;
  if (m.occluder) setQuad(o.occluder, m.occluder.corners, [0, 1, 2, 0, 2, 3]);
  const [px, py, pz] = m.p;
  o.point.position.set(px, py, pz);
  o.normal.position.set(px, py, pz);
  o.hemi.position.set(px, py, pz);
  const span = Math.max(4, 2.5 * Math.hypot(m.lc[0] - px, m.lc[1] - py), Math.max(m.w, m.h) * 3);
  o.floor.position.set(px, py, pz - 1e-3);
  o.floor.scale.set(span, span, 1);
  o.grid.position.set(Math.round(px), Math.round(py), pz);
  const gs = Math.max(1, Math.ceil(span / 8));
  o.grid.scale.set(gs, 1, gs);
  (o.grid.material as THREE.Material).opacity = dk ? 0.35 : 0.5;

  // Samples: points on the light (light strategies) and the unit directions from p, those that
  // contribute and the wasted ones in separate buffers, each in the order they arrive.
  const n = Math.min(MAX_SAMPLES, tm.length);
  const pos = (p: THREE.Points) => p.geometry.getAttribute('position') as THREE.BufferAttribute;
  const onPos = [pos(o.samplesOnMiss), pos(o.samplesOn)];
  const dirPos = [pos(o.samplesDirMiss), pos(o.samplesDir)];
  (o.samplesOn.material as THREE.PointsMaterial).color.set(dk ? 0x7ee787 : 0x1d7a3a);
  (o.samplesDir.material as THREE.PointsMaterial).color.set(dk ? 0x7ee787 : 0x1d7a3a);
  (o.samplesOnMiss.material as THREE.PointsMaterial).color.set(dk ? 0xf47067 : 0xc0392b);
  (o.samplesDirMiss.material as THREE.PointsMaterial).color.set(dk ? 0xf47067 : 0xc0392b);
  // the point, its normal and the rays to the newest samples: the series blue of the theme (≥ 3 : 1
  // on the view's background in both)
  const blue = dk ? 0x79b8ff : 0x1f5fa8;
  for (const obj of [o.point, o.normal, o.rays]) obj.material.color.set(blue);
  const next = [0, 0]; // next index in the wasted (0) and contributing (1) buffers
  o.hitsBefore[0] = 0;
  for (let i = 0; i < n; i++) {
    const h = tm[i] > 0 ? 1 : 0;
    const j = next[h]++;
    o.hitsBefore[i + 1] = o.hitsBefore[i] + h;
    let dx: number, dy: number, dz: number;
    if (st === 'cosine') {
      dx = smp[3 * i];
      dy = smp[3 * i + 1];
      dz = smp[3 * i + 2];
    } else {
      onPos[h].setXYZ(j, smp[3 * i], smp[3 * i + 1], smp[3 * i + 2]);
      dx = smp[3 * i] - px;
      dy = smp[3 * i + 1] - py;
      dz = smp[3 * i + 2] - pz;
      const len = Math.hypot(dx, dy, dz) || 1;
      dx /= len;
      dy /= len;
      dz /= len;
    }
    dirPos[h].setXYZ(j, px + dx, py + dy, pz + dz);
  }
  o.samplesOn.visible = o.samplesOnMiss.visible = st !== 'cosine';
  for (const a of [...onPos, ...dirPos]) a.needsUpdate = true;
  for (const p of [o.samplesOn, o.samplesOnMiss, o.samplesDir, o.samplesDirMiss])
    p.geometry.computeBoundingSphere();
  applyCount(o, s);

  // Q6(a) patch and its projection onto the unit sphere around p.
  o.patch.visible = o.patchRays.visible = o.patchProj.visible = !!pt;
  if (pt) {
    setQuad(o.patch, pt.corners, [0, 1, 2, 0, 2, 3]);
    setQuad(o.patchProj, pt.projected, [0, 1, 2, 0, 2, 3]);
    const rp = o.patchRays.geometry.getAttribute('position') as THREE.BufferAttribute;
    pt.corners.forEach((q, i) => {
      rp.setXYZ(2 * i, px, py, pz);
      rp.setXYZ(2 * i + 1, q[0], q[1], q[2]);
    });
    rp.needsUpdate = true;
    o.patchRays.geometry.computeBoundingSphere();
  }
  // Re-frame on the first draw, and whenever the point or a corner of the light has left the
  // view (e.g. after a preset moved the light far away); otherwise keep the user's camera.
  const cam = o.ctx.camera;
  cam.updateMatrixWorld();
  const fr = new T.Frustum().setFromProjectionMatrix(
    new T.Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse),
  );
  const visible = [m.p, ...c].every((q) => fr.containsPoint(new T.Vector3(q[0], q[1], q[2])));
  if (framedFor.current === '' || !visible) {
    framedFor.current = 'framed';
    frame(o, m);
  }
  o.ctx.invalidate();
}

/**
 * The view's objects, in the order they are added to the scene. Samples that contribute are drawn
 * as large dots and wasted ones as small dots, so that they are not told apart by colour alone.
 */
function createParts(T: ThreeModule) {
  const quadGeo = (verts: number) => {
    const g = new T.BufferGeometry();
    g.setAttribute('position', new T.BufferAttribute(new Float32Array(verts * 3), 3));
    return g;
  };
  const lightGeo = quadGeo(6);
  const lightFront = new T.Mesh(lightGeo, new T.MeshBasicMaterial({ color: 0xffd35a, side: T.FrontSide }));
  const lightBack = new T.Mesh(lightGeo, new T.MeshBasicMaterial({ color: 0x3b3b3b, side: T.BackSide }));
  const lightEdge = new T.LineLoop(quadGeo(4), new T.LineBasicMaterial({ color: 0xb34700 }));
  const occluder = new T.Mesh(quadGeo(6), new T.MeshLambertMaterial({ color: 0x6b6f78, side: T.DoubleSide }));
  const point = new T.Mesh(new T.SphereGeometry(0.035, 16, 12), new T.MeshBasicMaterial({ color: 0x1f5fa8 }));
  const nGeo = new T.BufferGeometry();
  nGeo.setAttribute('position', new T.Float32BufferAttribute([0, 0, 0, 0, 0, 0.5], 3));
  const normal = new T.Line(nGeo, new T.LineBasicMaterial({ color: 0x1f5fa8 }));
  // Unit hemisphere wireframe: 6 meridians and 3 parallels.
  const hv: number[] = [];
  const seg = 48;
  for (let k = 0; k < 6; k++) {
    const ph = (k * Math.PI) / 6;
    for (let s = 0; s < seg; s++) {
      const a = (s / seg) * Math.PI,
        b = ((s + 1) / seg) * Math.PI;
      hv.push(Math.cos(a) * Math.cos(ph), Math.cos(a) * Math.sin(ph), Math.sin(a));
      hv.push(Math.cos(b) * Math.cos(ph), Math.cos(b) * Math.sin(ph), Math.sin(b));
    }
  }
  for (const th of [0, Math.PI / 6, Math.PI / 3]) {
    for (let s = 0; s < 2 * seg; s++) {
      const a = (s / (2 * seg)) * 2 * Math.PI,
        b = ((s + 1) / (2 * seg)) * 2 * Math.PI;
      hv.push(Math.cos(th) * Math.cos(a), Math.cos(th) * Math.sin(a), Math.sin(th));
      hv.push(Math.cos(th) * Math.cos(b), Math.cos(th) * Math.sin(b), Math.sin(th));
    }
  }
  const hemiGeo = new T.BufferGeometry();
  hemiGeo.setAttribute('position', new T.Float32BufferAttribute(hv, 3));
  const hemi = new T.LineSegments(
    hemiGeo,
    new T.LineBasicMaterial({ color: 0x8a8f98, transparent: true, opacity: 0.45 }),
  );
  const floor = new T.Mesh(
    new T.PlaneGeometry(1, 1),
    new T.MeshLambertMaterial({ color: 0xcfc9b8, transparent: true, opacity: 0.55, side: T.DoubleSide }),
  );
  const grid = new T.GridHelper(8, 8, 0x888888, 0xaaaaaa);
  grid.rotation.x = Math.PI / 2; // GridHelper lies in xz; make it the z = 0 floor
  (grid.material as THREE.Material).transparent = true;

  const pts = (size: number) => {
    const g = new T.BufferGeometry();
    g.setAttribute('position', new T.BufferAttribute(new Float32Array(MAX_SAMPLES * 3), 3));
    return new T.Points(g, new T.PointsMaterial({ size, sizeAttenuation: false }));
  };
  // contributing samples large, wasted ones small (and a different colour)
  const samplesOn = pts(5);
  const samplesOnMiss = pts(2.5);
  const samplesDir = pts(4);
  const samplesDirMiss = pts(2);
  const rayGeo = new T.BufferGeometry();
  rayGeo.setAttribute('position', new T.BufferAttribute(new Float32Array(RAYS * 6), 3));
  const rays = new T.LineSegments(
    rayGeo,
    new T.LineBasicMaterial({ color: 0x1f5fa8, transparent: true, opacity: 0.35 }),
  );
  const patch = new T.Mesh(
    quadGeo(6),
    new T.MeshBasicMaterial({
      color: 0xe4572e,
      side: T.DoubleSide,
      polygonOffset: true,
      polygonOffsetFactor: -2,
      polygonOffsetUnits: -2,
    }),
  );
  const patchRays = new T.LineSegments(quadGeo(8), new T.LineBasicMaterial({ color: 0xe4572e }));
  const patchProj = new T.Mesh(quadGeo(6), new T.MeshBasicMaterial({ color: 0xe4572e, side: T.DoubleSide }));
  // in the order they are added to the scene
  return {
    floor,
    grid,
    lightFront,
    lightBack,
    lightEdge,
    occluder,
    point,
    normal,
    hemi,
    samplesOn,
    samplesOnMiss,
    samplesDir,
    samplesDirMiss,
    rays,
    patch,
    patchRays,
    patchProj,
  };
}

export function Scene3D({
  model,
  strategy,
  samples,
  terms,
  patch,
  height,
  dark,
  count,
  countRef,
}: Scene3DProps) {
  const objs = useRef<Objects | null>(null);
  const latest = useRef<Shown>({ model, strategy, samples, terms, patch, dark, count });
  latest.current = { model, strategy, samples, terms, patch, dark, count };
  const framedFor = useRef('');

  // The effects read the props through `latest` (set above in this render); their dependencies say
  // when to redraw: everything on a new model or samples, only the draw ranges on a new count.
  useEffect(() => {
    if (objs.current) apply(objs.current, latest.current, framedFor);
  }, [model, strategy, samples, terms, patch, dark]);
  useEffect(() => {
    if (objs.current) applyCount(objs.current, latest.current);
  }, [count]);
  if (countRef) {
    // per animation frame, without a React render: a new count moves the draw ranges and rays
    countRef.current = (k: number) => {
      if (latest.current.count === k) return;
      latest.current.count = k;
      if (objs.current) applyCount(objs.current, latest.current);
    };
  }

  const setup = (ctx: ViewportContext) => {
    const parts = createParts(ctx.THREE);
    for (const obj of Object.values(parts)) {
      obj.frustumCulled = false;
      ctx.scene.add(obj);
    }
    const o: Objects = { ctx, ...parts, hitsBefore: new Int32Array(MAX_SAMPLES + 1) };
    objs.current = o;
    framedFor.current = '';
    apply(o, latest.current, framedFor);
    return () => {
      objs.current = null;
    };
  };

  return (
    <div className="al-viewport">
      <Viewport ariaLabel={VIEW_LABEL} height={height} setup={setup} testId="al-3d">
        <button
          type="button"
          className="al-frame"
          onClick={() => {
            if (objs.current) frame(objs.current, latest.current.model);
          }}
        >
          Frame the scene
        </button>
      </Viewport>
    </div>
  );
}
