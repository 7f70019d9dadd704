/**
 * The order of a scene's parameter changes. A scene's values change from two sides: the address (a
 * typed or pasted link, back and forward: a hashchange) and the page itself (a control, a host's
 * `set`: a patch, whose URL is rewritten once its expressions have compiled). The scene renders
 * them as transitions, later and in slices, so the shell keeps the latest values asked for here,
 * ahead of the render: a patch builds on the address that came before it even when that address is
 * not on screen yet, and a URL write still pending for a patch is dropped once a newer change came
 * (it would replace a newer address in the history). Whatever the interleaving, the last change
 * wins.
 */
export interface ParamChanges<V> {
  /** The latest values asked for. */
  current(): V;
  /** The address changed: its values replace the current ones. */
  fromAddress(values: V): V;
  /**
   * A patch of the current values; returns the new values and `latest`, true while no change came
   * after this one (the URL may then be written for it).
   */
  patch(patch: Partial<V>): { values: V; latest: () => boolean };
}

export function paramChanges<V extends object>(initial: V): ParamChanges<V> {
  let values = initial;
  let serial = 0;
  return {
    current: () => values,
    fromAddress(next) {
      serial++;
      values = next;
      return values;
    },
    patch(p) {
      const mine = ++serial;
      values = { ...values, ...p };
      return { values, latest: () => mine === serial };
    },
  };
}
