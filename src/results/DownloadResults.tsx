/** "Download my results" on the practice pages: the learner's checks as a results file. */
import { useEffect, useState } from 'react';
import { RECORD_CHANGED, loadAttempts, loadName, resultsFile, saveName, startRecording } from './record';

startRecording();

function fileName(student: string): string {
  const who = student
    .trim()
    .replace(/[^\p{L}\p{N}_-]+/gu, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 40);
  return `render-math-lab-results${who ? `-${who}` : ''}-${new Date().toISOString().slice(0, 10)}.json`;
}

function recordedText(n: number): string {
  return `${n} check${n === 1 ? '' : 's'} recorded in this browser; your teacher collates the files at #/results.`;
}

export function DownloadResults() {
  const [name, setName] = useState(() => loadName());
  const [status, setStatus] = useState('');
  const [, setVersion] = useState(0);
  // a reset, a check or another tab changed the log or the name: show what is kept now
  useEffect(() => {
    const onChange = () => {
      setName(loadName());
      setStatus('');
      setVersion((n) => n + 1);
    };
    window.addEventListener(RECORD_CHANGED, onChange);
    return () => window.removeEventListener(RECORD_CHANGED, onChange);
  }, []);
  const download = () => {
    const file = resultsFile(name);
    const blob = new Blob([JSON.stringify(file, null, 1)], { type: 'application/json' });
    const url = URL.createObjectURL(blob);
    const a = document.createElement('a');
    a.href = url;
    a.download = fileName(name);
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
    setStatus(
      `${file.attempts.length} check${file.attempts.length === 1 ? '' : 's'} saved to ${a.download}.`,
    );
  };
  return (
    <div className="download-results" data-testid="download-results" style={{ margin: '0.75rem 0' }}>
      <label>
        Your name{' '}
        <input
          type="text"
          value={name}
          size={16}
          maxLength={80}
          autoComplete="name"
          onChange={(e) => {
            setName(e.target.value);
            saveName(e.target.value);
          }}
        />
      </label>{' '}
      <button type="button" onClick={download} data-testid="download-results-button">
        Download my results
      </button>{' '}
      <span role="status" className="muted">
        {status || recordedText(loadAttempts().length)}
      </span>
    </div>
  );
}
