/**
 * The one shape of a refusal: everything in the core (and the scenes' models) that can refuse its
 * input returns `{ ok: true, … }` or a `Failure` — `kind` says why in a word a program can branch
 * on, `message` says it in a sentence for the page. Extra fields (e.g. where it failed) may follow.
 */
export interface Failure<K extends string = string> {
  readonly ok: false;
  readonly kind: K;
  readonly message: string;
}

export function fail<K extends string>(kind: K, message: string): Failure<K> {
  return { ok: false, kind, message };
}
