import { useEffect } from 'react';
import type { ShellFlags } from '../kit/shell';
import { LESSONS, MISCONCEPTIONS, presetHref } from './lessons';
import { RouteNotice } from '../ui/RouteNotice';
import './guide.css';

/** Scroll to a section (the hash holds the route, so in-page anchors are buttons). */
function jump(id: string) {
  const el = document.getElementById(id);
  if (!el) return;
  el.scrollIntoView({ block: 'start' });
  el.focus({ preventScroll: true });
}

/** `#/guide`: lesson plans per exam question, misconceptions per scene, embedding, printing, offline. */
export default function Guide({ flags, query = '' }: { flags: ShellFlags; query?: string }) {
  useEffect(() => {
    document.title = 'Teacher’s guide — Render Math Lab';
  }, []);
  const home = flags.present ? '#/?present=1' : '#/';
  return (
    <main id="main" className="page guide" tabIndex={-1}>
      <div className="scene-header">
        <h1>Teacher’s guide</h1>
        <a className="back-link" href={home}>
          ← All scenes
        </a>
      </div>
      <RouteNotice flags={flags} query={query} />
      <p className="guide-lead">
        For each exam question, a lesson plan: three to five links that open a scene in a telling
        configuration, with a question to put to the class at each step. A link that asks first opens with the
        results hidden, on its part and with its animation at the start, under its question: press{' '}
        <strong>Reveal</strong> (or <kbd>v</kbd>) once the class has answered. Every number the class sees is
        computed live in the browser from the link’s parameters, so a link opens the same picture on every
        student’s screen.{' '}
        {flags.present
          ? 'The links keep classroom mode.'
          : 'Open this guide with present=1 and the links open in classroom mode.'}
      </p>
      <nav aria-label="Sections of the guide" className="guide-toc">
        <ul>
          {LESSONS.map((l) => (
            <li key={l.id}>
              <button type="button" className="link-button" onClick={() => jump(`guide-${l.id}`)}>
                {l.question}: {l.title}
              </button>
            </li>
          ))}
          <li>
            <button type="button" className="link-button" onClick={() => jump('guide-misconceptions')}>
              Misconceptions, scene by scene
            </button>
          </li>
          <li>
            <button type="button" className="link-button" onClick={() => jump('guide-embed')}>
              Embed, print and go offline
            </button>
          </li>
        </ul>
      </nav>

      {LESSONS.map((l) => (
        <section
          key={l.id}
          id={`guide-${l.id}`}
          tabIndex={-1}
          className="guide-lesson"
          aria-labelledby={`guide-${l.id}-h`}
        >
          <h2 id={`guide-${l.id}-h`}>
            <span className="question-tag">{l.question}</span> {l.title}
          </h2>
          <p>
            <a href={`#/deck?q=${l.id.slice(1)}${flags.present ? '&present=1' : ''}`}>
              Play {l.question} as a deck
            </a>
            : these steps as slides, each asking step held until you reveal it.
          </p>
          <ol className="guide-presets">
            {l.presets.map((p) => (
              <li key={presetHref(p)} data-testid="guide-preset">
                <h3>
                  <a href={presetHref(p, flags.present)}>{p.title}</a>
                </h3>
                <p className="guide-link-text">
                  <code>{presetHref(p)}</code>
                </p>
                <p>{p.shows}</p>
                <p className="guide-ask">
                  <strong>Ask:</strong> {p.ask}
                </p>
              </li>
            ))}
          </ol>
        </section>
      ))}

      <section id="guide-misconceptions" tabIndex={-1} aria-labelledby="guide-misc-h">
        <h2 id="guide-misc-h">Misconceptions, scene by scene</h2>
        <p>Each scene is built to make these visible; the presets above show most of them.</p>
        {MISCONCEPTIONS.map((m) => (
          <div key={m.route} className="guide-misc">
            <h3>
              <a href={`#${m.route}${flags.present ? '?present=1' : ''}`}>{m.title}</a>
            </h3>
            <ul>
              {m.items.map((it) => (
                <li key={it}>{it}</li>
              ))}
            </ul>
          </div>
        ))}
      </section>

      <section id="guide-embed" tabIndex={-1} aria-labelledby="guide-embed-h">
        <h2 id="guide-embed-h">Embed, print and go offline</h2>
        <h3>Embed a scene in a course page</h3>
        <p>
          Set the scene up (outside classroom mode), then press <strong>Copy embed code</strong>: it gives an{' '}
          <code>&lt;iframe&gt;</code> with an id and a short script that resizes it to the scene’s content
          (the scene posts only its height and its id). Paste both into the course page (Moodle, Canvas and
          most LMSs accept them in an HTML block). Add <code>origin=https://your-lms.example.edu</code> to the
          iframe’s link so that the scene talks only to your course page.
        </p>
        <p>
          A course page can also drive the scene: read its parameters, set them (checked exactly like a
          link’s), hear about every change a student makes and every practice verdict, and play, pause or seek
          an animation. The README’s “Host-page API” section lists the messages, and{' '}
          <code>examples/host.html</code> in the source is a working page to copy from.
        </p>
        <h3>Show it in the lecture hall</h3>
        <p>
          Add <code>present=1</code> to any link (or open this guide with it): the stage view, with larger
          type and keyboard shortcuts (press <kbd>?</kbd>). The scene’s figure, its key readouts and its
          animation’s controls fill the first screen; the other controls fold into a drawer (the{' '}
          <strong>Controls</strong> button, or <kbd>c</kbd>), and <strong>Fullscreen</strong> shows the figure
          alone (<kbd>Esc</kbd> leaves). Add <code>ask=1</code> to hide the results until you press{' '}
          <strong>Reveal</strong> (or <kbd>v</kbd>).
        </p>
        <p>
          The <strong>QR code</strong> button beside Copy link shows the current configuration as a large code
          that students scan to get the same scene on their phones. Copy link and the QR code give the
          students’ link, without classroom mode and with nothing hidden; check{' '}
          <strong>Keep classroom mode</strong> to share your own view instead. On phones and tablets a 3D view
          starts when the student taps <strong>Show the 3D view</strong> (it is the heaviest part of a page on
          a phone, and until then swipes over it scroll the page); every number and plot works without it.
        </p>
        <h3>Print</h3>
        <p>
          Print this guide as a handout with your browser’s Print command: the links are printed with their
          addresses. A scene prints as it is on screen, in its current configuration; the link in the address
          bar (or a QR code) brings it back.
        </p>
        <h3>Go offline</h3>
        <p>
          After one visit, the app works with no network: every scene, including those not yet opened, comes
          from the browser’s cache. Browsers that offer it can <strong>install</strong> the app (the install
          icon in the address bar). When a new version is published, a small notice offers to reload; until
          then the version you have keeps working, whole.
        </p>
        <p>
          For a lecture hall with no network at all, or an LMS that takes files rather than links, build the{' '}
          <strong>single-file copy</strong> (<code>npm run build:single</code>): one HTML file with every
          scene inside, which opens by double-click from a USB stick or as an uploaded LMS file.
        </p>
      </section>
    </main>
  );
}
