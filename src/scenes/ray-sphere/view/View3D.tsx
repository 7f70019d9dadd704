/**
 * The 3D view: the sphere, the ray (solid ahead, dashed behind), its origin and direction, and the
 * roots. Objects are built once; parameter changes only move them and request one render.
 * Coordinates are shifted and scaled in double precision before they reach three.js (Float32), so
 * a sphere 10⁸ radii away still draws cleanly (the view then centres on the sphere).
 */
import { useEffect, useRef } from 'react';
import type * as THREE from 'three';
import { Viewport, type ViewportContext } from '../../../three';
import { intersectRaySphere } from '../../../core/geometry';
import { FAR_RATIO } from '../model';
import type { Vec3 } from '../../../core/vec3';
import type { RayState } from './CrossSection';

/**
 * The 3D view's colours per theme: those of the cross-section (its CSS variables --accent for the
 * ray and the hit, --accent-2 for the roots and the sphere's wireframe, --muted for what lies
 * behind the origin, --fg for the origin), as three.js takes them; each ≥ 3 : 1 on the viewport
 * (tests/scenes/ray-sphere/palette.test.ts checks both).
 */
export const VIEW3D_COLOURS = {
  light: { ray: 0xa13f00, root: 0x1f5fa8, behind: 0x555a63, origin: 0x1c1d21 },
  dark: { ray: 0xffa657, root: 0x79b8ff, behind: 0xa9b0bc, origin: 0xeceff4 },
} as const;

export interface View3DProps extends RayState {
  height?: number;
  dark?: boolean;
  /** More points to keep in view (the ends of a sweep), so the view does not rescale while animating. */
  fitExtra?: readonly Vec3[];
}

interface Objects {
  ctx: ViewportContext;
  sphere: THREE.Mesh;
  wire: THREE.LineSegments;
  ray: THREE.Line;
  back: THREE.Line;
  origin: THREE.Mesh;
  arrow: THREE.ArrowHelper;
  roots: THREE.Mesh[];
}

export function View3D({
  o,
  d,
  c,
  r,
  res,
  distanceRatio,
  height = 320,
  dark = false,
  fitExtra = [],
}: View3DProps) {
  const objs = useRef<Objects | null>(null);
  const latest = useRef({ o, d, c, r, res, distanceRatio, dark, fitExtra });
  latest.current = { o, d, c, r, res, distanceRatio, dark, fitExtra };

  const update = () => {
    const ob = objs.current;
    if (!ob) return;
    const { o, d, c, r, res, distanceRatio, dark, fitExtra } = latest.current;
    const far = distanceRatio > FAR_RATIO;
    // view centre and scale (in doubles)
    let centre: Vec3;
    let extent: number;
    if (far) {
      centre = c;
      extent = 2.5 * r;
    } else {
      const pts: Vec3[] = [o, c, ...fitExtra];
      if (res && res.t1 !== null)
        pts.push([o[0] + res.t1 * d[0], o[1] + res.t1 * d[1], o[2] + res.t1 * d[2]]);
      const lo = [0, 1, 2].map((i) => Math.min(...pts.map((p) => p[i]), c[i] - r));
      const hi = [0, 1, 2].map((i) => Math.max(...pts.map((p) => p[i]), c[i] + r));
      centre = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
      extent = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2 || 1;
    }
    const s = 1.05 / extent;
    const map = (p: readonly number[]): [number, number, number] => [
      (p[0] - centre[0]) * s,
      (p[1] - centre[1]) * s,
      (p[2] - centre[2]) * s,
    ];
    const dl = Math.hypot(d[0], d[1], d[2]);
    const dh: Vec3 = [d[0] / dl, d[1] / dl, d[2] / dl];

    ob.sphere.position.set(...map(c));
    ob.sphere.scale.setScalar(r * s);
    ob.wire.position.copy(ob.sphere.position);
    ob.wire.scale.copy(ob.sphere.scale);

    // the ray's line clipped to a ball of radius 6 around the view centre (robust intersection!)
    const om = map(o);
    const clip = intersectRaySphere(om, dh, [0, 0, 0], 6, 'stable');
    const setLine = (line: THREE.Line, a: number, b: number) => {
      const pos = line.geometry.getAttribute('position') as THREE.BufferAttribute;
      pos.setXYZ(0, om[0] + a * dh[0], om[1] + a * dh[1], om[2] + a * dh[2]);
      pos.setXYZ(1, om[0] + b * dh[0], om[1] + b * dh[1], om[2] + b * dh[2]);
      pos.needsUpdate = true;
      line.geometry.computeBoundingSphere();
      line.computeLineDistances();
      line.visible = b > a;
    };
    if (clip.ok && clip.t0 !== null) {
      setLine(ob.ray, Math.max(0, clip.t0), Math.max(0, clip.t1!));
      setLine(ob.back, Math.min(0, clip.t0), Math.min(0, clip.t1!));
    } else {
      ob.ray.visible = false;
      ob.back.visible = false;
    }
    const inView = Math.hypot(...om) < 6;
    ob.origin.visible = inView;
    ob.origin.position.set(...om);
    const pal = VIEW3D_COLOURS[dark ? 'dark' : 'light'];
    (ob.origin.material as THREE.MeshBasicMaterial).color.set(pal.origin);
    (ob.ray.material as THREE.LineBasicMaterial).color.set(pal.ray);
    (ob.back.material as THREE.LineDashedMaterial).color.set(pal.behind);
    (ob.wire.material as THREE.LineBasicMaterial).color.set(pal.root);
    ob.arrow.setColor(pal.ray);
    ob.arrow.visible = inView && !far;
    ob.arrow.position.set(...om);
    ob.arrow.setDirection(new ob.ctx.THREE.Vector3(...dh));
    const roots = res && res.t0 !== null ? [res.t0, res.t1!] : [];
    ob.roots.forEach((m, i) => {
      const t = roots[i];
      m.visible = t !== undefined;
      if (t === undefined) return;
      // root position relative to the view centre, formed in doubles
      m.position.set(...map([o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]));
      const isHit = res!.tHit === t;
      (m.material as THREE.MeshBasicMaterial).color.set(isHit ? pal.ray : t < 0 ? pal.behind : pal.root);
      m.scale.setScalar(isHit ? 1.4 : 1);
    });
    ob.ctx.invalidate();
  };

  useEffect(update);

  const setup = (ctx: ViewportContext) => {
    const T = ctx.THREE;
    const sphere = new T.Mesh(
      new T.SphereGeometry(1, 48, 32),
      new T.MeshStandardMaterial({
        color: 0x6f9fd8,
        transparent: true,
        opacity: 0.42,
        roughness: 0.6,
        depthWrite: false,
      }),
    );
    const wire = new T.LineSegments(
      new T.WireframeGeometry(new T.SphereGeometry(1, 18, 12)),
      new T.LineBasicMaterial({ transparent: true, opacity: 0.25 }),
    );
    const lineGeom = () => {
      const g = new T.BufferGeometry();
      g.setAttribute('position', new T.BufferAttribute(new Float32Array(6), 3));
      return g;
    };
    // colours are set by update(), for the theme
    const ray = new T.Line(lineGeom(), new T.LineBasicMaterial());
    const back = new T.Line(lineGeom(), new T.LineDashedMaterial({ dashSize: 0.08, gapSize: 0.06 }));
    const origin = new T.Mesh(new T.SphereGeometry(0.05, 16, 12), new T.MeshBasicMaterial());
    const arrow = new T.ArrowHelper(new T.Vector3(1, 0, 0), new T.Vector3(), 0.6, undefined, 0.14, 0.08);
    const roots = [0, 1].map(
      () => new T.Mesh(new T.SphereGeometry(0.045, 16, 12), new T.MeshBasicMaterial()),
    );
    ctx.scene.add(sphere, wire, ray, back, origin, arrow, ...roots);
    objs.current = { ctx, sphere, wire, ray, back, origin, arrow, roots };
    update();
    return () => {
      objs.current = null;
      ctx.scene.remove(sphere, wire, ray, back, origin, arrow, ...roots);
      for (const m of [sphere, wire, ray, back, origin, ...roots]) {
        m.geometry.dispose();
        (m.material as THREE.Material).dispose();
      }
      arrow.dispose();
    };
  };

  return (
    <Viewport
      ariaLabel="3D view of the ray and the sphere"
      height={height}
      setup={setup}
      testId="view-3d"
      phiZero={false}
    >
      {distanceRatio > FAR_RATIO ? (
        <p className="rs-3d-note">
          Centred on the sphere; the origin is {distanceRatio.toPrecision(3)} radii away.
        </p>
      ) : null}
    </Viewport>
  );
}
