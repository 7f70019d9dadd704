/**
 * The scene's figures in words, with the numbers a sighted student reads from them (pure: the
 * texts screen readers receive as the figures' descriptions, and what the live region announces).
 * Coordinates are written with at least two decimals ("u 0.40"), values as the figure's labels
 * (four significant digits).
 */
import { formatRounded } from '../../../core/format';
import { nodeCoord, type LookupOptions, type TextureGrid } from '../../../core/texture';
import { frameAt, type Frame, type QueryPath } from '../path';
import type { Lookup } from '../model';
import type { PathProfile } from '../pathProfile';
import type { SphereModel } from '../sphere';
import type { Preset } from '../params';

/** Up to four significant digits (as the figure's labels). */
export function short(x: number): string {
  return Number.isFinite(x) ? formatRounded(x, 4) : 'undefined';
}

/** A coordinate: two decimals at least ("0.40"), up to four where it has them; −0 is 0. */
export function coord(x: number): string {
  if (!Number.isFinite(x)) return 'undefined';
  const r = Number(x.toFixed(4)) + 0;
  return Number(r.toFixed(2)) === r ? r.toFixed(2) : String(r);
}

const pair = (a: number, b: number) => `(${coord(a)}, ${coord(b)})`;

/** The texture by name: "the exam’s 5 × 5 texture", "an 8 × 8 checkerboard". */
export function textureName(grid: TextureGrid, preset: Preset, isExam: boolean): string {
  const size = `${grid.width} × ${grid.height}`;
  if (isExam) return `the exam’s ${size} texture`;
  const what =
    preset === 'checker'
      ? 'checkerboard'
      : preset === 'gradient'
        ? 'gradient texture'
        : preset === 'random'
          ? 'random texture'
          : 'texture (edited)';
  return `${/^8|^11|^18/.test(size) ? 'an' : 'a'} ${size} ${what}`;
}

/** The conventions in words: "corner nodes, clamp addressing" (and "v flipped"). */
export function conventions(opts: LookupOptions): string {
  return [
    opts.align === 'corner' ? 'corner nodes' : 'texel centres',
    `${opts.wrap} addressing`,
    ...(opts.vflip ? ['v flipped (v′ = 1 − v)'] : []),
  ].join(', ');
}

/**
 * The lookup as the grid figure shows it: the cell, the bilinear value from its four nodes (upper
 * row then lower row, as the grid is printed) with their weights, and the nearest node.
 */
export function describeLookup(q: Lookup, u: number, v: number): string {
  const b = q.bil;
  const n = q.near;
  return (
    `The query point at u ${coord(u)}, v ${coord(v)} lies in cell (${b.i0}, ${b.j0}); ` +
    `bilinear ${short(b.value)} from ${short(b.t01)}, ${short(b.t11)} above and ${short(b.t00)}, ${short(b.t10)} below ` +
    `(weights ${short(b.w01)}, ${short(b.w11)}, ${short(b.w00)}, ${short(b.w10)}); ` +
    `nearest ${short(n.value)}, the node (${n.i}, ${n.j}) at ${pair(n.nodeU, n.nodeV)}.`
  );
}

/** Where the query is on its path: "At t = 0.30 on its path, a line from (0.40, 0.24) to (0.85, 0.80)." */
export function describePath(path: QueryPath, t: number): string {
  const shape =
    path.kind === 'line'
      ? `a line from ${pair(path.a[0], path.a[1])} to ${pair(path.b[0], path.b[1])}`
      : `a circle through ${pair(path.a[0], path.a[1])} and ${pair(path.b[0], path.b[1])}`;
  return t === 0
    ? `The query is at the start of its path, ${shape}.`
    : `The query is at t = ${coord(t)} on its path, ${shape}.`;
}

/** The sphere point in words: its angles, its texture coordinates and the value there. */
export function describeSphere(
  sphere: SphereModel,
  p: { x: number; y: number; z: number },
  normalize: boolean,
  ask = false,
): string {
  const at = `(${short(p.x)}, ${short(p.y)}, ${short(p.z)})`;
  if (ask) return `The sphere point ${at}; its angles and texture coordinates are hidden until you reveal.`;
  if (!sphere.ok) return `The sphere point ${at} gives no texture coordinates: ${sphere.message}`;
  const deg = (a: number) => `${short((a * 180) / Math.PI)}°`;
  const angles = `azimuth φ ${deg(sphere.phi)}, polar angle θ ${deg(sphere.theta)}${sphere.pole ? ' (a pole: φ taken as 0)' : ''}`;
  const uv = normalize
    ? `texture coordinates (u, v) = (φ/2π, θ/π) = ${pair(sphere.normalized.u, sphere.normalized.v)}, bilinear ${short(sphere.normalized.bil.value)}`
    : `not normalized: (φ, θ) = ${pair(sphere.phi, sphere.theta)} in radians used as (u, v), bilinear ${short(sphere.raw.bil.value)}`;
  return `The sphere point ${at}: ${angles}; ${uv}.`;
}

/** Everything the main figure needs described. */
export interface TextureFigureState {
  /** From {@link textureName}. */
  name: string;
  opts: LookupOptions;
  frame: Frame;
  path: QueryPath;
  /** Why the query was changed before the lookup (the model's addressingNotes). */
  notes: readonly string[];
  /** The node chosen in the cell editor, with its value (null when not editing). */
  editing: { i: number; j: number; value: number } | null;
  /** The sphere part's sentence (from {@link describeSphere}). */
  sphere: string;
  /** Ask first (`ask=1`, not yet revealed): the setup only, no looked-up value. */
  ask?: boolean;
}

/**
 * The main figure (the grid with the query, its stencil and its path) in words, e.g. "The exam’s
 * 5 × 5 texture, corner nodes, clamp addressing. The query point at u 0.40, v 0.24 lies in cell
 * (1, 0); bilinear 17.8 from 17, 18 above and 22, 23 below …; nearest 18, the node (2, 1) at
 * (0.50, 0.25). The query is at the start of its path, … The sphere point …"
 */
export function describeTexture(s: TextureFigureState): string {
  const name = s.name.charAt(0).toUpperCase() + s.name.slice(1);
  if (s.ask)
    return [
      `${name}, ${conventions(s.opts)}.`,
      `The query point at u ${coord(s.frame.u)}, v ${coord(s.frame.v)}; the values looked up there are hidden until you reveal.`,
      describePath(s.path, s.frame.t),
      s.sphere,
    ].join(' ');
  const parts = [
    `${name}, ${conventions(s.opts)}.`,
    describeLookup(s.frame.lookup, s.frame.u, s.frame.v),
    ...s.notes,
    describePath(s.path, s.frame.t),
  ];
  if (s.editing)
    parts.push(
      `Editing cells: node (${s.editing.i}, ${s.editing.j}) chosen, value ${short(s.editing.value)}.`,
    );
  parts.push(s.sphere);
  return parts.join(' ');
}

/** A point of interest on the value-along-the-path plot (for its audio trace and table). */
export interface PathEvent {
  x: number;
  kind: 'kink';
  label: string;
}

/** Where the path crosses a cell border, in order: a kink, a jump (addressing) or a smooth crossing. */
export function pathEvents(profile: PathProfile): PathEvent[] {
  return profile.borders.map((b) => ({
    x: b.t,
    kind: 'kink',
    label: b.jump
      ? 'crosses a cell border: the value jumps (addressing)'
      : b.kink
        ? 'crosses a cell border: a kink, the slope changes'
        : 'crosses a cell border: no kink, the values continue linearly',
  }));
}

const plural = (n: number, one: string, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;

/** The value-along-the-path plot's structure: its borders, kinks, jumps and nearest's steps. */
export function describePathStructure(profile: PathProfile): string {
  const kinks = profile.borders.filter((b) => b.kink).length;
  const jumps = profile.borders.filter((b) => b.jump).length;
  return (
    `Bilinear is continuous${jumps ? ` except ${plural(jumps, 'jump')} from the addressing` : ''}, ` +
    `crossing ${plural(profile.borders.length, 'cell border')}${
      profile.borders.length
        ? ` at t = ${profile.borders.map((b) => coord(b.t)).join(', ')}, ${kinks} with a kink`
        : ''
    }. Nearest is a step function with ${plural(profile.nearSwitches.length, 'step')}.`
  );
}

/** Where the marker is on the plot: "Now at t = 0.30: nearest 17, bilinear 15.32." */
export function describePathNow(t: number, near: number, bil: number): string {
  return `Now at t = ${coord(t)}: nearest ${short(near)}, bilinear ${short(bil)}.`;
}

/** Nearest and bilinear at n + 1 evenly spaced positions on the path (what the audio traces play). */
export function pathSamples(
  grid: TextureGrid,
  opts: LookupOptions,
  path: QueryPath,
  n = 40,
): { ts: number[]; near: number[]; bil: number[] } {
  const ts: number[] = [];
  const near: number[] = [];
  const bil: number[] = [];
  for (let k = 0; k <= n; k++) {
    const f = frameAt(grid, opts, path, k / n);
    ts.push(f.t);
    near.push(f.lookup.near.value);
    bil.push(f.lookup.bil.value);
  }
  return { ts, near, bil };
}

/** Where nearest's value steps, as events of its trace. */
export function nearestEvents(profile: PathProfile): PathEvent[] {
  return profile.nearSwitches.map((t, k) => ({
    x: t,
    kind: 'kink',
    label: `nearest steps to ${short(profile.near[k + 1]?.value ?? NaN)}`,
  }));
}

/**
 * The plot's data as table rows: t, nearest, bilinear and what happens there, at the samples and
 * at every cell border and nearest step (in order of t).
 */
export function pathTableRows(
  grid: TextureGrid,
  opts: LookupOptions,
  path: QueryPath,
  profile: PathProfile,
  n = 20,
): string[][] {
  const marks = new Map<number, string[]>();
  const mark = (t: number, what: string) => marks.set(t, [...(marks.get(t) ?? []), what]);
  for (let k = 0; k <= n; k++) marks.set(k / n, marks.get(k / n) ?? []);
  for (const e of pathEvents(profile)) mark(e.x, e.label);
  for (const e of nearestEvents(profile)) mark(e.x, e.label);
  return [...marks.keys()]
    .sort((a, b) => a - b)
    .map((t) => {
      const l = frameAt(grid, opts, path, t).lookup;
      return [short(t), short(l.near.value), short(l.bil.value), marks.get(t)!.join('; ')];
    });
}

/** A reconstruction image in words: its filter, its value range, the query's cross and the creases. */
export function describeReconstruction(
  filter: 'nearest' | 'bilinear',
  range: { min: number; max: number },
  qu: number,
  qv: number,
  creased: number,
): string {
  return (
    `The texture reconstructed with ${filter} filtering over [0, 1]², values from ${short(range.min)} to ${short(range.max)}` +
    (filter === 'nearest'
      ? ', piecewise constant'
      : `, continuous, with ${plural(creased, 'creased piece')} of node line dashed`) +
    `; the cross marks the query at ${pair(qu, qv)}.`
  );
}

/** The grid's values as table rows, top row (largest v) first: [v, values…]. */
export function gridTableRows(grid: TextureGrid, opts: LookupOptions): string[][] {
  const rows: string[][] = [];
  for (let j = grid.height - 1; j >= 0; j--) {
    const row = [short(nodeCoord(j, grid.height, opts.align))];
    for (let i = 0; i < grid.width; i++) row.push(short(grid.values[j * grid.width + i]));
    rows.push(row);
  }
  return rows;
}

/** The column headings of {@link gridTableRows}: "v \ u", then each column's u. */
export function gridTableColumns(grid: TextureGrid, opts: LookupOptions): string[] {
  return [
    'v \\ u',
    ...Array.from({ length: grid.width }, (_, i) => `u ${short(nodeCoord(i, grid.width, opts.align))}`),
  ];
}
