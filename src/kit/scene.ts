/**
 * The contract between the shell and a scene. A scene module (src/scenes/<id>/index.ts) exports
 * `schema` (its URL parameters) and a default React component receiving {@link SceneProps}.
 */
import type { ComponentType } from 'react';
import type { ParamProblem, ParamSchema, ParamValues } from './params';

export interface SceneMode {
  /** `embed=1`: scene only, compact header, no site chrome. */
  embed: boolean;
  /** `present=1`: classroom mode, large type, keyboard shortcuts. */
  present: boolean;
  /**
   * `ask=1`, not yet revealed: show the setup (the figure with its inputs), hide the results (with
   * `<Revealed>` from src/ui/ask.tsx) and hold the animation at its start until this turns false.
   */
  ask: boolean;
  theme: 'light' | 'dark';
}

export interface SceneProps<S extends ParamSchema = ParamSchema> {
  /** Parsed, validated and clamped parameters (defaults where the URL had none or garbage). */
  params: ParamValues<S>;
  /** Merge a patch into the parameters; the shell writes them to the URL with replaceState. */
  setParams: (patch: Partial<ParamValues<S>>) => void;
  mode: SceneMode;
}

export interface SceneModule<S extends ParamSchema = ParamSchema> {
  schema: S;
  default: ComponentType<SceneProps<S>>;
  /**
   * Optional: the values this scene would not use as given although the URL parser accepts them
   * (it shows "using … instead" and computes with a fallback), one problem per parameter, from the
   * same model code the scene runs. The host API refuses a `set` that would add one.
   */
  checkValues?: SceneCheck<S>;
}

/** See {@link SceneModule.checkValues}. */
export type SceneCheck<S extends ParamSchema = ParamSchema> = (
  values: ParamValues<S>,
) => ParamProblem[] | Promise<ParamProblem[]>;
