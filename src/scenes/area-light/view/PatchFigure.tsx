/**
 * Q6(a) in cross-section, after the key's Figure 1 and its similar-triangles argument: the shading
 * point p, the unit circle around it, the patch dA at distance r tilted by θ_l (normal n_l), its
 * perpendicular projection dA⊥ (side dl), and the arc dω_l that dA⊥ subtends on the unit circle.
 * The two shaded half-triangles are similar: (dω_l/2)/1 = (dl/2)/r.
 *
 * Drawn to scale (one scale for r, the unit radius and the patch) whenever that fits; otherwise the
 * figure says which length is not to scale. The numbers come from the model (PatchModel).
 */
import { superscript } from '../../../ui/axis';
import type { PatchModel } from '../patch';
import { ArrowMarker } from '../../../ui/ArrowMarker';
import './patchFigure.css';

const W = 560;
const H = 260;
const PX = 40;
const PY = 150;
/** Longest drawn distance p → patch and largest drawn unit radius (px). */
const DMAX = 400;
const RMAX = 150;

function fmt(x: number, d = 4): string {
  if (!Number.isFinite(x)) return '—';
  if (x !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e5)) {
    const [m, e] = x.toExponential(d - 1).split('e');
    return `${m}×10${superscript(String(Number(e)))}`;
  }
  return Number(x.toPrecision(d)).toString();
}

/** Layout of the figure in SVG units: pure, so tests can check it (scale, clamps, label boxes). */
export function patchFigureLayout(patch: PatchModel) {
  const thetaL = Math.acos(Math.min(1, Math.max(0, patch.cosThetaL)));
  const r = patch.r > 0 ? patch.r : 1;
  // One scale k (px per unit) for r and the unit radius when both fit.
  let k = Math.min(DMAX / r, RMAX);
  let distanceToScale = true;
  if (k * r < 90 || k < 40) {
    // r ≫ 1 or r ≪ 1: the unit circle and r cannot share a legible scale.
    distanceToScale = false;
    k = RMAX * 0.6;
  }
  const D = distanceToScale ? k * r : DMAX;
  const R = distanceToScale ? k : RMAX * 0.6;
  // The patch's side at the same scale as r (its angular size is what matters), clamped to stay visible.
  const sideTrue = (Math.sqrt(patch.area) / r) * D;
  const s = Math.min(180, Math.max(10, sideTrue));
  const patchToScale = Math.abs(s - sideTrue) < 1e-6;
  return { thetaL, k, D, R, s, distanceToScale, patchToScale };
}

/** Whether (and how) the figure is drawn to scale, in words. */
function scaleNoteOf(patch: PatchModel): string {
  const { distanceToScale, patchToScale, s } = patchFigureLayout(patch);
  return !distanceToScale
    ? `r = ${fmt(patch.r, 3)} and the unit radius are not to scale here`
    : !patchToScale
      ? `to scale, except the patch (${sideTrueWord(s, patch)})`
      : 'drawn to scale';
}

/** The figure in words, with its numbers: its accessible description. */
export function patchFigureText(patch: PatchModel): string {
  const deg = (Math.acos(Math.min(1, Math.max(0, patch.cosThetaL))) * 180) / Math.PI;
  return `Cross-section of Q6(a), ${scaleNoteOf(patch)}: the patch of area ${fmt(patch.area)} at distance r = ${fmt(patch.r)}, tilted by θₗ = ${fmt(deg, 3)} degrees from facing the point. Its perpendicular projection dA⊥ has side dl = ${fmt(Math.sqrt(patch.area * patch.cosThetaL))}; the similar triangles give dωₗ = dl / r, so dω = dA cos θₗ / r² = ${fmt(patch.approx)} sr (exactly ${fmt(patch.exact)} sr).`;
}

export function PatchFigure({ patch }: { patch: PatchModel }) {
  const { thetaL, D, R, s, distanceToScale, patchToScale } = patchFigureLayout(patch);
  const cx = PX + D,
    cy = PY;
  // The patch: a segment through its centre, turned θ_l from the perpendicular to the ray.
  const ux = Math.sin(thetaL),
    uy = Math.cos(thetaL);
  const a = { x: cx - (s / 2) * ux, y: cy - (s / 2) * uy };
  const b = { x: cx + (s / 2) * ux, y: cy + (s / 2) * uy };
  // dA⊥: perpendicular to the ray, side dl = s cos θ_l (in this cross-section).
  const dl = s * Math.cos(thetaL);
  const pa = { x: cx, y: cy - dl / 2 },
    pb = { x: cx, y: cy + dl / 2 };
  // The point at distance `len` from p towards q.
  const along = (q: { x: number; y: number }, len: number) => {
    const dx = q.x - PX,
      dy = q.y - PY,
      l = Math.hypot(dx, dy) || 1;
    return { x: PX + (len * dx) / l, y: PY + (len * dy) / l };
  };
  // Where the cone p → dA⊥ meets the unit circle (the ends of dω_l), and the cone's edges drawn past it.
  const ca = along(pa, R),
    cbb = along(pb, R);
  const far = Math.max(D, R) + 24;
  const ea = along(pa, far),
    eb = along(pb, far);
  // Patch normal n_l (towards p's side) and the θ_l arc between n_l and the direction back to p.
  const nx = -Math.cos(thetaL),
    ny = Math.sin(thetaL);
  const nLen = 56;
  const arcR = 30;
  const arcEnd = { x: cx + arcR * nx, y: cy + arcR * ny };
  const C70 = Math.cos((62 * Math.PI) / 180),
    S70 = Math.sin((62 * Math.PI) / 180);
  const scaleNote = scaleNoteOf(patch);
  return (
    <svg
      className="al-patch-fig"
      viewBox={`0 0 ${W} ${H}`}
      data-testid="al-patch-figure"
      data-to-scale={distanceToScale && patchToScale ? '1' : '0'}
      aria-hidden="true"
    >
      <defs>
        <ArrowMarker id="al-arrow" />
      </defs>
      {/* the two similar half-triangles: (p, C, top of dA⊥) and (p, axis ∩ circle, top of dω_l) */}
      <path d={`M ${PX} ${PY} L ${cx} ${cy} L ${pa.x} ${pa.y} Z`} className="al-fig-tri-big" />
      <path d={`M ${PX} ${PY} L ${PX + R} ${PY} L ${ca.x} ${ca.y} Z`} className="al-fig-tri-small" />
      {/* unit circle (arc) around p */}
      <path
        d={`M ${PX + R * C70} ${PY - R * S70} A ${R} ${R} 0 0 1 ${PX + R * C70} ${PY + R * S70}`}
        className="al-fig-circle"
      />
      {/* the cone from p through the ends of dA⊥ */}
      <line x1={PX} y1={PY} x2={ea.x} y2={ea.y} className="al-fig-cone" />
      <line x1={PX} y1={PY} x2={eb.x} y2={eb.y} className="al-fig-cone" />
      <line x1={PX} y1={PY} x2={cx} y2={cy} className="al-fig-ray" />
      <text
        x={PX + Math.max(R + 14, R + 0.3 * (D - R))}
        y={PY + 22}
        textAnchor="middle"
        className="al-fig-label"
      >
        r
      </text>
      <text x={PX + R / 2} y={PY + 22} textAnchor="middle" className="al-fig-label">
        1
      </text>
      {/* dω_l on the unit circle */}
      <path d={`M ${ca.x} ${ca.y} A ${R} ${R} 0 0 1 ${cbb.x} ${cbb.y}`} className="al-fig-domega" />
      <text x={ca.x - 6} y={Math.min(ca.y, PY - 12) - 8} textAnchor="end" className="al-fig-accent">
        dω
        <tspan className="al-fig-sub" dy="0.3em">
          l
        </tspan>
      </text>
      {/* dA⊥ with side dl */}
      <line x1={pa.x} y1={pa.y} x2={pb.x} y2={pb.y} className="al-fig-perp" />
      <text x={cx} y={Math.min(pa.y, a.y) - 18} textAnchor="middle" className="al-fig-perp-label">
        dA⊥ (side dl)
      </text>
      {/* the patch dA and its normal */}
      <line x1={a.x} y1={a.y} x2={b.x} y2={b.y} className="al-fig-patch" />
      <text x={Math.max(a.x, b.x) + 8} y={Math.max(a.y, b.y) + 6} className="al-fig-accent">
        dA
      </text>
      <line
        x1={cx}
        y1={cy}
        x2={cx + nLen * nx}
        y2={cy + nLen * ny}
        className="al-fig-normal"
        markerEnd="url(#al-arrow)"
      />
      <text x={cx + nLen * nx - 4} y={cy + nLen * ny + 24} textAnchor="end" className="al-fig-muted">
        n
        <tspan className="al-fig-sub" dy="0.3em">
          l
        </tspan>
      </text>
      {thetaL > 0.02 ? (
        <>
          <path
            d={`M ${cx - arcR} ${cy} A ${arcR} ${arcR} 0 0 0 ${arcEnd.x} ${arcEnd.y}`}
            className="al-fig-theta"
          />
          {/* a small angle leaves no room inside it: the label goes below, clear of n_l */}
          <text
            x={thetaL < 0.35 ? cx - 14 : cx - (arcR + 14) * Math.cos(thetaL / 2)}
            y={thetaL < 0.35 ? cy + 56 : cy + (arcR + 14) * Math.sin(thetaL / 2) + 6}
            textAnchor="end"
            className="al-fig-label"
          >
            θ
            <tspan className="al-fig-sub" dy="0.3em">
              l
            </tspan>
          </text>
        </>
      ) : null}
      <circle cx={PX} cy={PY} r={4} className="al-fig-point" />
      <text x={PX - 8} y={PY + 5} textAnchor="end" className="al-fig-label">
        p
      </text>
      <text x={W - 6} y={16} textAnchor="end" className="al-fig-muted" data-testid="al-patch-scale">
        {scaleNote}
      </text>
    </svg>
  );
}

function sideTrueWord(s: number, patch: PatchModel): string {
  return s <= 10
    ? `drawn larger than its ${fmt(Math.sqrt(patch.area), 2)}`
    : `drawn smaller than its ${fmt(Math.sqrt(patch.area), 2)}`;
}
