/**
 * Q6(a) drawn in cross-section (after the key's Figure 1): the shading point p, the unit circle
 * around it, the patch dA at distance r tilted by θ_l (its normal n_l against the direction back
 * to p), its foreshortened projection dA cos θ_l perpendicular to the ray, and the arc dω it
 * subtends on the unit circle. The tilt is drawn at the patch's real θ_l and the patch at its real
 * angular size (clamped to stay visible); the numbers come from the model.
 */
import type { PatchModel } from '../model';

const W = 560;
const H = 250;
const PX = 46;
const PY = 135;
const D = 390; // drawn distance p → patch centre
const R = 120; // drawn unit circle radius
const C70 = Math.cos((70 * Math.PI) / 180);
const S70 = Math.sin((70 * Math.PI) / 180);

function fmt(x: number, d = 4): string {
  if (!Number.isFinite(x)) return '—';
  if (x !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e5)) return x.toExponential(d - 1).replace('e', '×10^');
  return Number(x.toPrecision(d)).toString();
}

export function PatchFigure({ patch }: { patch: PatchModel }) {
  const thetaL = Math.acos(Math.min(1, Math.max(0, patch.cosThetaL)));
  const ang = patch.r > 0 ? Math.sqrt(patch.area) / patch.r : 0; // angular size, radians
  const s = Math.min(170, Math.max(6, D * ang));
  const cx = PX + D, cy = PY;
  // The patch: a segment through the centre, turned θ_l from the perpendicular to the ray.
  const ux = Math.sin(thetaL), uy = Math.cos(thetaL);
  const a = { x: cx - (s / 2) * ux, y: cy - (s / 2) * uy };
  const b = { x: cx + (s / 2) * ux, y: cy + (s / 2) * uy };
  // Its projection perpendicular to the ray: length s cos θ_l, centred on the ray.
  const sp = s * Math.cos(thetaL);
  const pa = { x: cx, y: cy - sp / 2 }, pb = { x: cx, y: cy + sp / 2 };
  // Where the cone p → patch meets the unit circle.
  const onCircle = (q: { x: number; y: number }) => {
    const dx = q.x - PX, dy = q.y - PY, l = Math.hypot(dx, dy) || 1;
    return { x: PX + (R * dx) / l, y: PY + (R * dy) / l };
  };
  const ca = onCircle(a), cb = onCircle(b);
  // Patch normal n_l (pointing back towards p's side) and the θ_l arc between n_l and −ray.
  const nx = -Math.cos(thetaL), ny = Math.sin(thetaL);
  const nLen = 58;
  const arcR = 34;
  const arcEnd = { x: cx + arcR * nx, y: cy + arcR * ny };
  return (
    <svg className="al-patch-fig" viewBox={`0 0 ${W} ${H}`} role="img" aria-label={`Cross-section of Q6(a): the patch of area ${fmt(patch.area)} at distance r = ${fmt(patch.r)}, tilted by θ_l = ${fmt((thetaL * 180) / Math.PI, 3)} degrees, subtends dω ≈ dA cos θ_l / r² = ${fmt(patch.approx)} sr; exactly ${fmt(patch.exact)} sr.`}>
      <defs>
        <marker id="al-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse">
          <path d="M0,0 L10,5 L0,10 z" fill="currentColor" />
        </marker>
      </defs>
      {/* unit circle (arc) around p */}
      <path d={`M ${PX + R * C70} ${PY - R * S70} A ${R} ${R} 0 0 1 ${PX + R * C70} ${PY + R * S70}`} className="al-fig-circle" />
      <text x={PX + R * 0.5} y={PY - R * 0.9} className="al-fig-muted">unit sphere around p</text>
      {/* the cone from p to the patch ends */}
      <line x1={PX} y1={PY} x2={a.x} y2={a.y} className="al-fig-cone" />
      <line x1={PX} y1={PY} x2={b.x} y2={b.y} className="al-fig-cone" />
      <line x1={PX} y1={PY} x2={cx} y2={cy} className="al-fig-ray" />
      <text x={(PX + cx) / 2} y={PY + 16} className="al-fig-label">r = {fmt(patch.r)}</text>
      {/* dω on the unit circle */}
      <path d={`M ${ca.x} ${ca.y} A ${R} ${R} 0 0 1 ${cb.x} ${cb.y}`} className="al-fig-domega" />
      <text x={Math.max(ca.x, cb.x) + 6} y={PY - 8} className="al-fig-accent">dω</text>
      {/* projection dA cos θ_l */}
      <line x1={pa.x} y1={pa.y} x2={pb.x} y2={pb.y} className="al-fig-perp" />
      <text x={cx - 8} y={Math.min(pa.y, a.y) - 10} textAnchor="end" className="al-fig-muted">dA cos θ_l</text>
      {/* the patch and its normal */}
      <line x1={a.x} y1={a.y} x2={b.x} y2={b.y} className="al-fig-patch" />
      <text x={Math.max(a.x, b.x) + 8} y={Math.max(a.y, b.y) + 4} className="al-fig-accent">dA</text>
      <line x1={cx} y1={cy} x2={cx + nLen * nx} y2={cy + nLen * ny} className="al-fig-normal" markerEnd="url(#al-arrow)" />
      <text x={cx + nLen * nx - 4} y={cy + nLen * ny + 16} className="al-fig-muted">n_l</text>
      {thetaL > 0.02 ? (
        <>
          <path d={`M ${cx - arcR} ${cy} A ${arcR} ${arcR} 0 0 0 ${arcEnd.x} ${arcEnd.y}`} className="al-fig-theta" />
          <text x={cx - arcR - 30} y={cy + 22} className="al-fig-label">θ_l</text>
        </>
      ) : null}
      <circle cx={PX} cy={PY} r={4} className="al-fig-point" />
      <text x={PX - 6} y={PY + 22} className="al-fig-label">p</text>
      <text x={12} y={H - 14} className="al-fig-label al-fig-summary">
        dA = {fmt(patch.area)}, θ_l = {fmt((thetaL * 180) / Math.PI, 3)}°: dA cos θ_l / r² = {fmt(patch.approx)} sr, exact {fmt(patch.exact)} sr
      </text>
    </svg>
  );
}
