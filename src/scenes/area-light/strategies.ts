/** The three sampling strategies of #/area-light, in the order of their random streams, and their names. */
import type { LightStrategy } from '../../core/lights';

export const STRATEGIES: readonly LightStrategy[] = ['area', 'solid-angle', 'cosine'];
export const STRATEGY_SHORT: Record<LightStrategy, string> = {
  area: 'area (key)',
  'solid-angle': 'solid angle',
  cosine: 'cosine',
};
export const STRATEGY_LABEL: Record<LightStrategy, string> = {
  area: 'uniform area (the key)',
  'solid-angle': 'solid angle (spherical rectangle)',
  cosine: 'cosine hemisphere',
};
