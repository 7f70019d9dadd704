/**
 * What the render lab computes with, from its URL parameters: the scene spec that crosses to the
 * workers, the camera, the estimator's options, the image size and the inspected pixel, with a
 * named problem for every value it would not use as given (and the safe value it uses instead).
 */
import { biasApplies } from '../../core/render/bias';
import type { ParamProblem } from '../../kit/params';
import { examGrid, parseGrid } from '../../core/texture/grid';
import type { TraceOptions } from '../../core/render/pathTrace';
import { defaultView, type RenderSpec, type View } from '../../core/render/scene';
import type { Vec3 } from '../../core/vec3';
import type { RenderParams } from './params';

export interface RenderModel {
  spec: RenderSpec;
  view: View;
  trace: TraceOptions;
  /** Image side (the image is res × res). */
  res: number;
  spp: number;
  seed: number;
  /** The inspected pixel (column, row from the top left), or null for none. */
  px: readonly [number, number] | null;
  pn: number;
  /** The renderer the link asks for (the page may fall back to the CPU: ./gpu/fallback). */
  renderer: 'gpu' | 'cpu';
  /** Samples per pixel the run goes to now: spp while playing; with play=0, t (at most spp). */
  target: number;
  problems: ParamProblem[];
}

const vec = (xs: readonly number[]): Vec3 => [xs[0], xs[1], xs[2]];

/** The camera: the preset's view, with each of eye, look and fov the link gives in its place. */
function viewOf(p: RenderParams, problems: ParamProblem[]): View {
  const preset = defaultView(p.scene);
  const eye = p.eye ? vec(p.eye) : preset.eye;
  let look = p.look ? vec(p.look) : preset.look;
  if (eye[0] === look[0] && eye[1] === look[1] && eye[2] === look[2]) {
    look = eye === preset.eye ? [eye[0], eye[1] + 1, eye[2]] : preset.look;
    problems.push({
      name: 'look',
      message: `is the eye itself, so the camera has no direction; looking at ${look.join(',')} instead`,
    });
  }
  return { eye, look, fov: p.fov ? p.fov[0] : preset.fov };
}

/** The inspected pixel, inside the image and whole (rounded and clamped, with a problem if it was not). */
function pixelOf(p: RenderParams, problems: ParamProblem[]): readonly [number, number] | null {
  if (!p.px) return null;
  const max = p.res - 1;
  const clamp = (x: number) => Math.min(max, Math.max(0, Math.round(x)));
  const px = [clamp(p.px[0]), clamp(p.px[1])] as const;
  if (px[0] !== p.px[0] || px[1] !== p.px[1])
    problems.push({
      name: 'px',
      message: `${p.px.join(',')} is not a pixel of the ${p.res} × ${p.res} image (whole numbers 0 … ${max}); using ${px.join(',')}`,
    });
  return px;
}

/** Where the run holds: spp while playing; paused, at t samples per pixel, clamped to spp (with a problem). */
export function targetOf(p: RenderParams, problems: ParamProblem[]): number {
  if (p.play) return p.spp;
  if (p.t > p.spp)
    problems.push({
      name: 't',
      message: `${p.t} samples per pixel is more than spp=${p.spp}; holding at ${p.spp}`,
    });
  return Math.min(p.t, p.spp);
}

export function buildRenderModel(p: RenderParams): RenderModel {
  const problems: ParamProblem[] = [];
  const parsed = parseGrid(p.grid);
  if (!parsed.ok) problems.push({ name: 'grid', message: `${parsed.message} Using the exam’s 5 × 5 grid.` });
  const grid = parsed.ok ? parsed.grid : examGrid();
  if (!biasApplies(p.bias, p.strategy) && p.bias !== 'none')
    problems.push({
      name: 'bias',
      message: `${p.bias} changes only area sampling (strategy=area); with ${p.strategy} the estimator is the correct one.`,
    });
  const ls: readonly [number, number] = p.ls && p.ls.length === 2 ? [p.ls[0], p.ls[1]] : [1, 1];
  const spec: RenderSpec = {
    scene: p.scene,
    exam: { rho: p.rho, lc: p.lc, ls, tilt: p.tilt, L: p.L, c: p.c, r: p.r, grid, filter: p.filter },
  };
  return {
    spec,
    view: viewOf(p, problems),
    trace: { strategy: p.strategy, bounces: p.bounces, bias: p.bias },
    res: p.res,
    spp: p.spp,
    seed: p.seed,
    px: pixelOf(p, problems),
    pn: p.pn,
    renderer: p.renderer,
    target: targetOf(p, problems),
    problems,
  };
}
