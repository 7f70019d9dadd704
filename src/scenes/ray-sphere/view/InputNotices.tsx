/** What the page says when the typed inputs had to be replaced, or overflow even then. */
import type { Failure } from '../../../core/failure';
import { Notice } from '../../../ui';

export function InputNotices({ problems, fatal }: { problems: readonly Failure[]; fatal: string | null }) {
  return (
    <>
      {problems.length ? (
        <Notice kind="error" testId="input-problems">
          <p>
            <strong>These inputs do not describe a ray and a sphere</strong>, so the scene uses safe values:
          </p>
          <ul>
            {problems.map((p) => (
              <li key={p.message} data-kind={p.kind}>
                {p.message}
              </li>
            ))}
          </ul>
        </Notice>
      ) : null}
      {fatal ? (
        <Notice kind="error" testId="input-fatal">
          {fatal} Try smaller numbers, or pick a preset.
        </Notice>
      ) : null}
    </>
  );
}
