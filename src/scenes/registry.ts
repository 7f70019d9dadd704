/**
 * The scene registry: one lazy loader per scene. `import.meta.glob` makes each
 * `src/scenes/<id>/index.ts` its own chunk, loaded only when the scene is opened; a catalogue scene
 * whose folder has no index.ts yet shows as "not built yet". What each scene is (title, parts,
 * exam configuration) is in the catalogue, src/kit/catalogue.ts.
 */
import type { SceneModule } from '../kit/scene';

const loaders = import.meta.glob<SceneModule>('./*/index.ts');

/** The scene modules loaded so far, by id. */
const loaded = new Map<string, SceneModule>();

/** The lazy loader of a scene, or null if the scene has not been built yet. */
export function sceneLoader(id: string): (() => Promise<SceneModule>) | null {
  const load = loaders[`./${id}/index.ts`] as (() => Promise<SceneModule>) | undefined;
  if (!load) return null;
  return () =>
    load().then((mod) => {
      loaded.set(id, mod);
      return mod;
    });
}

/**
 * The scene's module if it has been loaded already (through sceneLoader), else undefined: a host
 * that finds it here renders the scene in its first render, without a "Loading the scene…" step.
 */
export function loadedScene(id: string): SceneModule | undefined {
  return loaded.get(id);
}
