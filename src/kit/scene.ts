/**
 * The contract between the shell and a scene. A scene module (src/scenes/<id>/index.ts) exports
 * `schema` (its URL parameters) and a default React component receiving {@link SceneProps}.
 */
import type { ComponentType } from 'react';
import type { ParamSchema, ParamValues } from './params';

export interface SceneMode {
  /** `embed=1`: scene only, compact header, no site chrome. */
  embed: boolean;
  /** `present=1`: classroom mode, large type, keyboard shortcuts. */
  present: boolean;
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
}
