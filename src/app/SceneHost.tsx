import { lazy, startTransition, Suspense, useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { flushSync } from 'react-dom';
import { predictPrompt, type PageInfo } from '../kit/catalogue';
import { loadedScene, sceneLoader } from '../scenes/registry';
import type { SceneModule } from '../kit/scene';
import {
  parseParams,
  sanitizePatch,
  serializeParams,
  type ParamProblem,
  type ParamValues,
  type ParamSchema,
} from '../kit/params';
import {
  addressKey,
  dropQueryParam,
  parseHash,
  parseShellFlags,
  shellExtras,
  type ShellFlags,
} from '../kit/shell';
import { useShortcuts } from '../ui/shortcuts';
import { AskPrompt } from '../ui/ask';
import { usePageKey } from '../ui/pageKeys';
import { getOpenFolds } from '../ui/openFolds';
import { QuestionNav } from '../ui/QuestionNav';
import { ParamNotice } from '../ui/RouteNotice';
import { useHostScene } from './hostBridge';
import { paramChanges } from './paramChanges';
import { fullAppHref, linkSafeValues, ShareBar } from './ShareBar';
import { SceneErrorBoundary } from './SceneErrorBoundary';
import { useScrollToPart } from './useScrollToPart';
import { markFirstScreen } from './firstScreen';
import { importOrReload } from '../ui/staleBuild';
import './sceneHost.css';

// The teacher's A11y view (a11y=1): its own chunk, loaded only with the flag.
const A11yView = lazy(() => import('./A11yView'));

interface Props {
  info: PageInfo;
  query: string;
  flags: ShellFlags;
  theme: 'light' | 'dark';
  /**
   * The scene is a slide of a lecture deck (src/deck): no heading, links to other pages or title of
   * its own, and it never writes the address (the deck's); `question`, when given, is what its
   * `ask=1` prompt asks; `onReveal` hears the reveal.
   */
  slide?: { question: string | null; onReveal?: () => void };
}

type LoadState =
  | { kind: 'loading' }
  | { kind: 'missing' }
  | { kind: 'failed'; message: string }
  | { kind: 'ready'; mod: SceneModule };

/** Loads a scene's chunk, parses its URL parameters, and hosts it with the shared chrome. */
export function SceneHost({ info, query, flags, theme, slide }: Props) {
  // The opened page's scene has usually arrived before the first render (main.tsx waits for it):
  // it is then rendered at once, and the page's first paint shows it.
  const [load, setLoad] = useState<LoadState>(() => {
    const mod = loadedScene(info.id);
    return mod ? { kind: 'ready', mod } : { kind: 'loading' };
  });
  const hosted = !!slide;
  useEffect(() => {
    if (!hosted) document.title = `${info.title} — Render Math Lab`;
    const known = loadedScene(info.id);
    if (known) {
      // (its chunk may have come between the first render and now: main.tsx stops waiting at 2.5 s)
      setLoad((prev) => (prev.kind === 'ready' && prev.mod === known ? prev : { kind: 'ready', mod: known }));
      return;
    }
    const loader = sceneLoader(info.id);
    if (!loader) {
      setLoad({ kind: 'missing' });
      return;
    }
    let alive = true;
    // (KaTeX's worker and stylesheet start once the scene's first screen has been painted, with its
    // formulas as plain text for a moment: fetched earlier, they delayed that paint on a phone.)
    // a page of a replaced build reloads onto the new one instead (src/ui/staleBuild.ts)
    importOrReload(loader).then(
      // A transition: React renders the scene's (large) first tree in slices of a few ms that yield
      // to the browser, instead of one long task (Lighthouse: total blocking time on load).
      (mod) => alive && startTransition(() => setLoad({ kind: 'ready', mod })),
      (err) =>
        alive && setLoad({ kind: 'failed', message: err instanceof Error ? err.message : String(err) }),
    );
    return () => {
      alive = false;
    };
  }, [info, hosted]);
  // the first screen is up (or the scene failed): work kept out of it may start (main.tsx)
  useEffect(() => {
    if (load.kind !== 'loading') markFirstScreen();
  }, [load.kind]);

  // a deck's slide sits inside the deck's own <main>
  const Root = hosted ? 'div' : 'main';
  const header = (
    <div className={flags.embed ? 'scene-header compact' : 'scene-header'}>
      <h1>
        <span className="question-tag">{info.questions}</span> {info.title}
      </h1>
      {flags.embed ? (
        <a className="open-full" href={fullAppHref(info, query)} target="_blank" rel="noopener">
          Open in Render Math Lab ↗
        </a>
      ) : (
        <a className="back-link" href={flags.present ? '#/?present=1' : '#/'}>
          ← All scenes
        </a>
      )}
    </div>
  );

  return (
    // Outside embeds the page is at least one screen tall from the first paint, so the footer starts
    // below the fold and does not jump down when the scene's chunk replaces "Loading the scene…"
    // (that jump was a layout shift of ~0.17 on every scene, measured by Lighthouse mobile).
    <Root
      id={hosted ? undefined : 'main'}
      className={`page scene scene-${info.id}${flags.embed || hosted ? '' : ' scene-full'}`}
      tabIndex={-1}
    >
      {hosted ? null : header}
      {flags.a11y ? (
        <Suspense fallback={null}>
          <A11yView />
        </Suspense>
      ) : null}
      {load.kind === 'loading' ? (
        <p className="loading" role="status">
          Loading the scene…
        </p>
      ) : null}
      {load.kind === 'missing' ? (
        <p role="status" className="notice notice-info">
          This scene is not built yet. <a href="#/">Back to the list of scenes</a>.
        </p>
      ) : null}
      {load.kind === 'failed' ? (
        <div role="alert" className="notice notice-error">
          The scene could not be loaded ({load.message}). Check the connection and{' '}
          <button type="button" onClick={() => window.location.reload()}>
            reload
          </button>
          .
        </div>
      ) : null}
      {load.kind === 'ready' ? (
        <LoadedScene mod={load.mod} info={info} query={query} flags={flags} theme={theme} slide={slide} />
      ) : null}
    </Root>
  );
}

function LoadedScene({
  mod,
  info,
  query,
  flags,
  theme,
  slide,
}: {
  mod: SceneModule;
  info: PageInfo;
  query: string;
  flags: ShellFlags;
  theme: 'light' | 'dark';
  slide?: Props['slide'];
}) {
  const hosted = !!slide;
  const schema = mod.schema;
  const parsed = useMemo(() => parseParams(schema, query), [schema, query]);
  const [values, setValues] = useState(parsed.values);
  const partProblem = useMemo<ParamProblem[]>(
    () =>
      flags.part && !info.parts.includes(flags.part)
        ? [
            {
              name: 'part',
              message: `${flags.part} is not on this page (it has ${info.parts.join(', ')}); showing the top`,
            },
          ]
        : [],
    [flags.part, info.parts],
  );
  const [problems, setProblems] = useState<ParamProblem[]>([
    ...flags.problems,
    ...partProblem,
    ...parsed.problems,
  ]);
  // the values the scene opened with: "r" (classroom shortcut) always goes back to them
  const opening = useRef(parsed.values);
  // The address as this page last took it in or wrote it (window.location.hash as the browser
  // holds it): a hashchange to it again is the page's own. A link followed on the page changes the
  // address at once, but its hashchange comes as a later task: a change the page makes in between
  // (a key on a handle, a typed expression whose URL write waited for it to compile) must not
  // write the URL, or it would replace the followed link, and the hashchange, reading the page's
  // own address back, would be ignored. So the URL is written only while it still says what this
  // page last saw, the page's own fold and ask rewrites aside (addressKey); otherwise the coming
  // hashchange takes the link's values.
  const seenAddress = useRef(typeof window === 'undefined' ? '' : window.location.hash);
  // the latest values asked for, ahead of the render that shows them (./paramChanges)
  const [changes] = useState(() => paramChanges(parsed.values));
  // A hashchange on this page (typed or pasted link, back/forward) takes the address's values at
  // once, in the event (our own replaceState does not fire it); the scene re-renders as a
  // transition, in slices that yield (see useHashRoute).
  useEffect(() => {
    const on = () => {
      const { path, query: q } = parseHash(window.location.hash);
      if (path !== info.path || window.location.hash === seenAddress.current) return;
      seenAddress.current = window.location.hash;
      const next = changes.fromAddress(parseParams(schema, q).values);
      startTransition(() => setValues(next));
    };
    window.addEventListener('hashchange', on);
    return () => window.removeEventListener('hashchange', on);
  }, [info.path, schema, changes]);
  // the notice of values the address could not use follows the query the shell renders
  const problemsFor = useRef(query);
  useEffect(() => {
    if (problemsFor.current === query) return;
    problemsFor.current = query;
    startTransition(() => setProblems([...flags.problems, ...partProblem, ...parsed.problems]));
  }, [query, parsed, flags.problems, partProblem]);

  const part = flags.part && info.parts.includes(flags.part) ? flags.part : null;
  // a slide opens at the top, where the deck shows it
  useScrollToPart(part, hosted || (flags.present && flags.ask), query);

  // ask=1: results hidden until revealed (button or `v`); revealing drops `ask` from the URL
  const [asking, setAsking] = useState(flags.ask);
  const askingRef = useRef(asking);
  askingRef.current = asking;
  useEffect(() => setAsking(flags.ask), [flags.ask]);
  useEffect(() => {
    if (hosted) return;
    // a link opened again (its query string unchanged since the shell rewrote the URL) asks again
    const on = () => setAsking(parseShellFlags(parseHash(window.location.hash).query).ask);
    window.addEventListener('hashchange', on);
    return () => window.removeEventListener('hashchange', on);
  }, [hosted]);
  const onReveal = useRef(slide?.onReveal);
  onReveal.current = slide?.onReveal;
  const reveal = useCallback(() => {
    setAsking(false);
    onReveal.current?.();
    if (hosted) return;
    const { path, query: current } = parseHash(window.location.hash);
    const qs = dropQueryParam(current, 'ask');
    try {
      window.history.replaceState(window.history.state, '', `#${path}${qs ? `?${qs}` : ''}`);
    } catch {
      /* some sandboxed iframes forbid it; the state still lives in the page */
    }
  }, [hosted]);
  usePageKey('v', reveal, asking);
  const askText = useAskText(info, query, part, flags.ask, slide?.question ?? null);

  // The values the link carries: typed expressions enter it only once they have compiled (a link
  // must never carry an expression that was not checked; see linkSafeValues).
  const [linkValues, setLinkValues] = useState(values);
  useEffect(() => setLinkValues(parsed.values), [parsed]);
  const setParams = useCallback(
    (patch: Record<string, unknown>) => {
      // only values the schema allows reach the scene and the URL (a select set to a missing
      // option, a NaN from a cleared number field, a key that is not a parameter: dropped)
      const { values: next, latest } = changes.patch(
        sanitizePatch(schema, patch) as ParamValues<ParamSchema>,
      );
      setValues(next);
      void linkSafeValues(schema, next).then((safe) => {
        if (!latest()) return; // a newer change wrote, or will write, the URL
        setLinkValues(safe);
        const qs = serializeParams(
          schema,
          safe,
          shellExtras({ ...flags, ask: askingRef.current, open: getOpenFolds() }),
        );
        const hash = `#${info.path}${qs ? `?${qs}` : ''}`;
        if (hosted) return;
        if (addressKey(window.location.hash) !== addressKey(seenAddress.current)) return;
        try {
          window.history.replaceState(window.history.state, '', hash);
        } catch {
          /* some sandboxed iframes forbid it; the state still lives in the page */
        }
        seenAddress.current = window.location.hash;
      });
    },
    [schema, flags, info.path, changes, hosted],
  );
  // `r`: the opening values. A playing animation pauses first, and where it stopped is rendered
  // before the opening values are: its timeline reads a change of `t` against the position it last
  // wrote, so it then moves to the opening t (a pause and the opening t in one render would leave
  // it where it stopped, t being unchanged since it started playing).
  const reset = useCallback(() => {
    if ((changes.current() as Record<string, unknown>).play === true) {
      flushSync(() => setParams({ play: false }));
      flushSync(() => setParams({}));
    }
    setParams({ ...opening.current });
  }, [setParams, changes]);
  useShortcuts({ reset });

  const getValues = useCallback(() => changes.current(), [changes]);
  useHostScene(
    { id: info.id, route: info.path, schema, getValues, setParams, checkValues: mod.checkValues },
    values,
  );

  const Scene = mod.default;
  return (
    <>
      {problems.length ? (
        <ParamNotice
          problems={problems}
          lead={
            <>
              <strong>Some link parameters could not be used</strong>; the scene uses safe values instead:
            </>
          }
        >
          <button type="button" className="link-button" onClick={() => setProblems([])}>
            Dismiss
          </button>
        </ParamNotice>
      ) : null}
      <ShareBar info={info} schema={schema} values={linkValues} flags={flags} asking={asking} />
      {asking && askText !== null ? <AskPrompt text={askText} onReveal={reveal} /> : null}
      <SceneErrorBoundary resetKey={query}>
        <Scene
          params={values}
          setParams={setParams}
          mode={{ embed: flags.embed, present: flags.present, ask: asking, theme }}
        />
      </SceneErrorBoundary>
      {flags.embed || hosted ? null : <QuestionNav info={info} flags={flags} />}
    </>
  );
}

/** Said when neither the link's guide preset nor the catalogue has a question for this page. */
const GENERIC_PROMPT = 'What will the scene show? Make your prediction, then reveal.';

/**
 * The prediction prompt of an `ask=1` page (null until known): `own` when given (a deck slide's
 * question), else the guide preset's own question when
 * the link is one of its presets, else the catalogue's prompt for the part. The guide's texts load
 * (lazily, apart from the entry) only for ask=1.
 */
function useAskText(
  info: PageInfo,
  query: string,
  part: string | null,
  ask: boolean,
  own: string | null,
): string | null {
  const [preset, setPreset] = useState<{ query: string; text: string | null } | null>(null);
  useEffect(() => {
    if (!ask || own) return;
    let alive = true;
    import('../kit/lessons').then(
      (m) => alive && setPreset({ query, text: m.presetAskFor(info.id, query) }),
      () => alive && setPreset({ query, text: null }),
    );
    return () => {
      alive = false;
    };
  }, [ask, info.id, query, own]);
  if (ask && own) return own;
  if (!ask || !preset || preset.query !== query) return null;
  return preset.text ?? predictPrompt(info, part) ?? GENERIC_PROMPT;
}
