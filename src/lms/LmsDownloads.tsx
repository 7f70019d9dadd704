/**
 * "For your LMS" on the worksheet page: the same packages as `npm run build:lms` (SCORM 1.2,
 * SCORM 2004, cmi5, Moodle XML, QTI 2.1) for the worksheet's questions, variants and seed, built
 * in this browser when asked (./browserBuild.ts, loaded then).
 */
import { useState } from 'react';
import type { QuestionId } from '../practice/model';
import type { PackageOutputs } from './packages';
import { APP_VERSION } from './version';
import { downloadFile } from '../ui/download';
import { IntInput } from '../ui/IntInput';

/** The files offered, in the order of their buttons. */
const FILES: { name: keyof PackageOutputs; label: string }[] = [
  { name: 'practice-scorm12.zip', label: 'SCORM 1.2 package' },
  { name: 'practice-scorm2004.zip', label: 'SCORM 2004 package' },
  { name: 'practice-cmi5.zip', label: 'cmi5 package' },
  { name: 'questions-moodle.xml', label: 'Moodle XML question bank' },
  { name: 'questions-qti21.zip', label: 'QTI 2.1 question bank' },
];

/** A file's MIME type, by its extension (every package is a zip, the Moodle bank an XML file). */
function mimeType(name: string): string {
  return name.endsWith('.xml') ? 'application/xml' : 'application/zip';
}

export function LmsDownloads({
  questions,
  variants,
  seed,
}: {
  questions: QuestionId[];
  variants: number;
  seed: number;
}) {
  const [mastery, setMastery] = useState(80);
  const [status, setStatus] = useState('');
  const [busy, setBusy] = useState(false);
  const get = async (name: keyof PackageOutputs) => {
    setBusy(true);
    setStatus('Preparing…');
    try {
      const { buildInBrowser } = await import('./browserBuild');
      const out = await buildInBrowser(
        { questions, variants, seed, mastery: mastery / 100, version: APP_VERSION },
        setStatus,
      );
      const data = out[name];
      downloadFile(name, data as BlobPart, mimeType(name));
      setStatus(`${name}: ${(data.length / 1e6).toFixed(2)} MB.`);
    } catch (e) {
      setStatus(
        `The package could not be built (${e instanceof Error ? e.message : String(e)}). Use npm run build:lms instead.`,
      );
    } finally {
      setBusy(false);
    }
  };
  return (
    <section className="panel lms-downloads" aria-labelledby="lms-title" data-testid="lms-downloads">
      <h2 id="lms-title">For your LMS</h2>
      <p className="muted">
        These questions ({questions.map((q) => q.toUpperCase()).join(', ')}; {variants} variant
        {variants === 1 ? '' : 's'} each from seed {seed}) as packages: in a SCORM or cmi5 package each
        learner gets their own variant and the score reaches the gradebook; the question banks import into a
        quiz. Built in this browser, nothing is uploaded.
      </p>
      <p>
        <label>
          Pass mark <IntInput min={1} max={100} value={mastery} fallback={80} onChange={setMastery} /> %
        </label>
      </p>
      <p className="lms-buttons" style={{ display: 'flex', flexWrap: 'wrap', gap: '0.5rem' }}>
        {FILES.map((f) => (
          <button
            key={f.name}
            type="button"
            disabled={busy}
            onClick={() => void get(f.name)}
            data-testid={`lms-build-${f.name}`}
          >
            {f.label}
          </button>
        ))}
      </p>
      <p role="status" data-testid="lms-build-status">
        {status}
      </p>
    </section>
  );
}
