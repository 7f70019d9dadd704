/**
 * A route's page as its own lazy chunk. A chunk (or its stylesheet) that cannot be loaded on a page
 * of a replaced build reloads the page onto the new build (./staleBuild.ts); when that does not
 * help (offline, or the reload already happened) the route says what happened and offers a reload,
 * instead of leaving the page blank.
 */
import { lazy, type ComponentType } from 'react';
import { importOrReload } from './staleBuild';

function LoadFailed({ what }: { what: string }) {
  return (
    <main id="main" className="page" tabIndex={-1}>
      <p role="alert" className="notice notice-error" data-testid="route-load-failed">
        {what} could not be loaded: the site may have been updated since this page was opened, or the
        connection is down. Check the connection and{' '}
        <button type="button" className="link-button" onClick={() => window.location.reload()}>
          reload
        </button>
        .
      </p>
    </main>
  );
}

type Page = { default: ComponentType };

/**
 * The page module `load` gives, or, when it cannot be loaded and no reload onto a newer build
 * follows (`tryLoad`: ./staleBuild.ts), a page that says so: never nothing.
 */
export function loadPage(
  load: () => Promise<{ default: ComponentType<never> }>,
  what: string,
  tryLoad: typeof importOrReload = importOrReload,
): Promise<Page> {
  const failed: ComponentType = () => <LoadFailed what={what} />;
  return tryLoad(load).then(
    (m): Page => ({ default: m.default as unknown as ComponentType }),
    (): Page => ({ default: failed }),
  );
}

/** `React.lazy` of a page module that recovers onto a new build or says it could not load. */
export function lazyPage<C extends ComponentType<never>>(
  load: () => Promise<{ default: C }>,
  what: string,
): C {
  return lazy(() => loadPage(load, what)) as unknown as C;
}
