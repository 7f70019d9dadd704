/**
 * Whether a page runs the built-in fuzzer (./fuzz.ts), a test tool that presses every button with
 * hostile input. It may run only in the development server or in a build made for testing
 * (`VITE_RML_FUZZ=1`, npm run e2e:fuzz), and there only when the route asks for it
 * (`#/…?fuzz=1`, with `seed` or `fuzzseed`, and `fuzzn` for a number of actions). In a build for
 * readers no link can start it: it would press "Reset progress" and write into their results log.
 */

/** The build flags the decision reads (Vite's import.meta.env). */
export interface BuildFlags {
  DEV: boolean;
  VITE_RML_FUZZ?: string;
}

export interface FuzzRequest {
  seed: number;
  /** Actions before it stops by itself (null: until Stop is pressed). */
  limit: number | null;
}

/** Whether this build may run the fuzzer at all. */
export function fuzzBuild(flags: BuildFlags): boolean {
  return flags.DEV === true || flags.VITE_RML_FUZZ === '1';
}

/** The fuzz run a page of this build at `hash` asks for, or null (none asked, or not allowed). */
export function fuzzRequest(flags: BuildFlags, hash: string): FuzzRequest | null {
  if (!fuzzBuild(flags)) return null;
  const q = hash.indexOf('?');
  if (q < 0) return null;
  const sp = new URLSearchParams(hash.slice(q + 1));
  if (sp.get('fuzz') !== '1') return null;
  const int = (v: string | null) => (v !== null && /^\d{1,10}$/.test(v) ? Number(v) : null);
  const limit = int(sp.get('fuzzn'));
  return {
    seed: int(sp.get('fuzzseed')) ?? int(sp.get('seed')) ?? 1,
    limit: limit && limit > 0 ? limit : null,
  };
}
