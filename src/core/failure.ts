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

/**
 * A Failure carried by an exception, where a refusal has to cross a `throw` (a worker job, a
 * promise): the worker protocol sends `kind` and `message` across, and the page's side rejects with
 * a FailureError again, so the view branches on the same `kind` the core chose.
 */
export class FailureError extends Error implements Failure {
  readonly ok = false;
  constructor(
    readonly kind: string,
    message: string,
  ) {
    super(message);
    this.name = 'FailureError';
  }
}

/** Throws a Failure (see FailureError). */
export function raise(f: Failure): never {
  throw new FailureError(f.kind, f.message);
}

/** Any thrown value as a Failure (`kind` 'internal' for an exception that is not one). */
export function asFailure(err: unknown): Failure {
  if (err instanceof FailureError) return fail(err.kind, err.message);
  return fail('internal', err instanceof Error ? err.message : String(err));
}
