/**
 * "The opened page's first screen is up": the scene host marks it once the scene's chunk has
 * rendered (or failed to load). Work that is no part of the first screen (registering the service
 * worker) waits for it.
 */
let mark: () => void = () => undefined;
const shown = new Promise<void>((resolve) => {
  mark = resolve;
});

export function markFirstScreen(): void {
  mark();
}

/** Resolves when the first screen is marked, or after `maxMs` at the latest. */
export function firstScreen(maxMs: number): Promise<void> {
  return Promise.race([shown, new Promise<void>((r) => setTimeout(r, maxMs))]);
}
