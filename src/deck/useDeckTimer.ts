/** The lecture's clock: time since the deck was opened, which the lecturer may pause and restart. */
import { useCallback, useEffect, useState } from 'react';

/** `s` seconds as m:ss, or h:mm:ss from an hour on. */
export function clockText(s: number): string {
  const t = Math.max(0, Math.floor(s));
  const h = Math.floor(t / 3600);
  const m = Math.floor((t % 3600) / 60);
  const ss = String(t % 60).padStart(2, '0');
  return h > 0 ? `${h}:${String(m).padStart(2, '0')}:${ss}` : `${m}:${ss}`;
}

export function useDeckTimer(): {
  seconds: number;
  running: boolean;
  toggle: () => void;
  restart: () => void;
} {
  // elapsed time before the current run, and when the current run started (null: paused)
  const [banked, setBanked] = useState(0);
  const [since, setSince] = useState<number | null>(() => Date.now());
  const [now, setNow] = useState(() => Date.now());
  useEffect(() => {
    if (since === null) return;
    const id = window.setInterval(() => setNow(Date.now()), 1000);
    return () => window.clearInterval(id);
  }, [since]);
  const seconds = (banked + (since === null ? 0 : Math.max(0, now - since))) / 1000;
  const toggle = useCallback(() => {
    const t = Date.now();
    setNow(t);
    if (since === null) setSince(t);
    else {
      setBanked((b) => b + (t - since));
      setSince(null);
    }
  }, [since]);
  const restart = useCallback(() => {
    const t = Date.now();
    setBanked(0);
    setNow(t);
    setSince((s) => (s === null ? null : t));
  }, []);
  return { seconds, running: since !== null, toggle, restart };
}
