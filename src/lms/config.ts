/**
 * How a launch page tells the app it runs inside an LMS package: a `<meta name="rml-lms">` whose
 * content is the package's configuration as JSON (packages.ts writes it, the app's entry and the
 * LMS runtime read it). A meta rather than an inline script: the app's Content-Security-Policy
 * runs no inline script but the ones its build hashed (scripts/csp.ts). Tiny and import-free, as
 * the entry reads it.
 */
import type { QuestionId } from '../practice/model';

export type LmsKind = 'scorm12' | 'scorm2004' | 'cmi5';

/** What the launch page declares (read by src/lms/launch.ts). */
export interface LmsConfig {
  kind: LmsKind;
  questions: QuestionId[];
  /** Package seed: mixed into every learner's variant seeds. */
  seed: number;
  /** Scaled score (0–1) at which the learner passes, unless the LMS says otherwise. */
  mastery: number;
  /** The app's version (recorded in results). */
  version: string;
}

export const LMS_META = 'rml-lms';

/** The meta tag declaring `config` (its JSON escaped for an attribute). */
export function lmsConfigMeta(config: LmsConfig): string {
  const json = JSON.stringify(config).replace(
    /[&"<>]/g,
    (c) => ({ '&': '&amp;', '"': '&quot;', '<': '&lt;', '>': '&gt;' })[c] as string,
  );
  return `<meta name="${LMS_META}" content="${json}" />`;
}

/** The configuration the launch page declares (unchecked), or null outside a package. */
export function declaredLmsConfig(): unknown {
  const meta = document.querySelector<HTMLMetaElement>(`meta[name="${LMS_META}"]`);
  if (!meta) return null;
  try {
    return JSON.parse(meta.content) as unknown;
  } catch {
    return null;
  }
}
