/**
 * Where the bilinear reconstruction of a texture creases: the pieces of node lines across which its
 * slope jumps.
 */
import {
  bilinear,
  cellSize,
  gridRange,
  nodeCoord,
  type LookupOptions,
  type TextureGrid,
} from '../../core/texture';

/** A crease of the bilinear reconstruction: a piece of a node line across which the slope jumps. */
export interface Crease {
  /** 'u': the line u = const (slope in u jumps); 'v': the line v = const. In the texture frame. */
  axis: 'u' | 'v';
  at: number;
  from: number;
  to: number;
}

/**
 * Where the bilinear reconstruction over [0, 1]² (texture frame, no flip) has creases: pieces of
 * node lines across which the slope perpendicular to the line jumps. Bilinear is linear along u
 * between node lines, so the jump across the line u = uᵢ is the second difference of the values
 * (over Δ), interpolated linearly between rows: a grid whose values continue linearly across a
 * node line (the exam's 21 − 5j + i everywhere) has no crease there.
 */
export function creases(
  grid: TextureGrid,
  opts: LookupOptions,
): { list: Crease[]; lines: number; creased: number } {
  const o = { ...opts, vflip: false };
  const range = gridRange(grid);
  const scale = Math.max(1, Math.abs(range.max), Math.abs(range.min), range.max - range.min);
  const list: Crease[] = [];
  let lines = 0;
  let creased = 0;
  for (const axis of ['u', 'v'] as const) {
    const n = axis === 'u' ? grid.width : grid.height; // node lines across this axis
    const m = axis === 'u' ? grid.height : grid.width; // nodes along the line
    const d = cellSize(n, o.align);
    const h = d / 64;
    const along = [
      0,
      ...Array.from({ length: m }, (_, k) => nodeCoord(k, m, o.align)).filter((x) => x > 0 && x < 1),
      1,
    ];
    const first = o.align === 'corner' ? 1 : 0;
    const last = o.align === 'corner' ? n - 2 : n - 1;
    for (let k = first; k <= last; k++) {
      const c = nodeCoord(k, n, o.align);
      if (c - 2 * h < 0 || c + 2 * h > 1) continue;
      lines++;
      const f = (x: number, y: number) => (axis === 'u' ? bilinear(grid, x, y, o) : bilinear(grid, y, x, o));
      const jumpAt = (y: number) => {
        const f0 = f(c, y);
        const sl = (3 * f0 - 4 * f(c - h, y) + f(c - 2 * h, y)) / (2 * h);
        const sr = (-3 * f0 + 4 * f(c + h, y) - f(c + 2 * h, y)) / (2 * h);
        return Math.abs(sl - sr) > 1e-7 * (scale / d);
      };
      let any = false;
      for (let s = 0; s + 1 < along.length; s++) {
        const y0 = along[s];
        const y1 = along[s + 1];
        if (jumpAt(y0 + (y1 - y0) / 3) || jumpAt(y0 + (2 * (y1 - y0)) / 3)) {
          any = true;
          const prev = list[list.length - 1];
          if (prev && prev.axis === axis && prev.at === c && prev.to === y0) prev.to = y1;
          else list.push({ axis, at: c, from: y0, to: y1 });
        }
      }
      if (any) creased++;
    }
  }
  return { list, lines, creased };
}
