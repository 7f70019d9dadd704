/**
 * A variant's marking state kept across reloads and tabs (localStorage, key
 * `rml:practice-sessions`, per learner: ./learnerScope.ts): per part the attempts, wrong attempts,
 * hint and whether its answer was shown; per answer the best mark and the text last counted. So an
 * answer shown stays forfeited after a reload, attempts keep counting, and the best mark is kept.
 *
 * Every write is a merge with what is stored (another tab may have checked the same variant): counts
 * take the larger, a shown answer stays shown, a hint stays taken, the best mark the larger. What
 * is stored is checked against the variant, and anything unreadable is ignored.
 */
import type { Variant } from './model';
import { newSession, type AnswerProgress, type PartProgress, type Session } from './session';
import { scopedKey } from './learnerScope';
import { SESSIONS_KEY } from './sessionKey';

const MAX_VARIANTS = 300;
const MAX_COUNT = 10_000;
const MAX_TEXT = 4000;

type StoredPart = [attempts: number, wrong: number, hint: 0 | 1, revealed: 0 | 1 | 2];
type StoredAnswer = [best: number, counted: string | null];
interface StoredSession {
  t: number;
  p: Record<string, StoredPart>;
  a: Record<string, StoredAnswer>;
}

const REVEALED: PartProgress['revealed'][] = [null, 'asked', 'attempts'];

function variantKey(v: Pick<Variant, 'question' | 'seed'>): string {
  return `${v.question}:${v.seed}`;
}

function readAll(): Record<string, StoredSession> {
  try {
    const raw = window.localStorage.getItem(scopedKey(SESSIONS_KEY));
    const d = raw ? (JSON.parse(raw) as unknown) : null;
    if (!d || typeof d !== 'object' || Array.isArray(d)) return {};
    const out: Record<string, StoredSession> = Object.create(null) as Record<string, StoredSession>;
    for (const [k, e] of Object.entries(d as Record<string, unknown>))
      if (/^q[1-6]:\d{1,10}$/.test(k) && e && typeof e === 'object') out[k] = e as StoredSession;
    return out;
  } catch {
    return {};
  }
}

const count = (x: unknown): number =>
  Number.isInteger(x) && (x as number) >= 0 ? Math.min(x as number, MAX_COUNT) : 0;

/** The stored state of `v` as a Session (absent or unreadable parts start afresh). */
function fromStored(v: Variant, e: StoredSession | undefined): Session {
  const s = newSession(v);
  if (!e) return s;
  const parts = e.p && typeof e.p === 'object' ? e.p : {};
  const answers = e.a && typeof e.a === 'object' ? e.a : {};
  for (const p of v.parts) {
    const sp = Object.hasOwn(parts, p.id) ? parts[p.id] : null;
    if (Array.isArray(sp)) {
      const attempts = count(sp[0]);
      s.parts[p.id] = {
        attempts,
        wrong: Math.min(count(sp[1]), attempts),
        hint: sp[2] === 1,
        revealed: REVEALED[sp[3] === 1 || sp[3] === 2 ? sp[3] : 0],
      };
    }
    for (const a of p.answers) {
      const sa = Object.hasOwn(answers, a.name) ? answers[a.name] : null;
      if (!Array.isArray(sa)) continue;
      const best = typeof sa[0] === 'number' && sa[0] >= 0 && sa[0] <= 1 ? sa[0] : 0;
      const counted = typeof sa[1] === 'string' && sa[1].length <= MAX_TEXT ? sa[1] : null;
      s.answers[a.name] = { best, last: 0, counted, verdict: null };
    }
  }
  return s;
}

function toStored(s: Session): StoredSession {
  const p: Record<string, StoredPart> = {};
  for (const [id, x] of Object.entries(s.parts))
    p[id] = [x.attempts, x.wrong, x.hint ? 1 : 0, REVEALED.indexOf(x.revealed) as 0 | 1 | 2];
  const a: Record<string, StoredAnswer> = {};
  for (const [name, x] of Object.entries(s.answers))
    a[name] = [x.best, x.counted !== null && x.counted.length <= MAX_TEXT ? x.counted : null];
  return { t: Date.now(), p, a };
}

/**
 * `mine` (this page's) merged with `theirs` (stored by this or another tab): the larger counts, a
 * shown answer and a taken hint stay so, the larger best mark; this page's verdicts and last marks.
 */
export function mergeSessions(mine: Session, theirs: Session): Session {
  const parts: Record<string, PartProgress> = {};
  for (const [id, m] of Object.entries(mine.parts)) {
    const t = theirs.parts[id];
    parts[id] = t
      ? {
          attempts: Math.max(m.attempts, t.attempts),
          wrong: Math.max(m.wrong, t.wrong),
          hint: m.hint || t.hint,
          revealed: m.revealed ?? t.revealed,
        }
      : m;
  }
  const answers: Record<string, AnswerProgress> = {};
  for (const [name, m] of Object.entries(mine.answers)) {
    const t = theirs.answers[name];
    answers[name] = t ? { ...m, best: Math.max(m.best, t.best), counted: m.counted ?? t.counted } : m;
  }
  return { parts, answers };
}

/** The variant's marking state as kept (a new session when none is kept or it is unreadable). */
export function loadSession(v: Variant): Session {
  return fromStored(v, readAll()[variantKey(v)]);
}

/** This page's session merged with the kept one (what a Check must start from). */
export function withStored(v: Variant, s: Session): Session {
  return mergeSessions(s, loadSession(v));
}

/** Keep `s` for `v`, merged with what is kept; returns the merged session. */
export function saveSession(v: Variant, s: Session): Session {
  const all = readAll();
  const k = variantKey(v);
  const merged = mergeSessions(s, fromStored(v, all[k]));
  all[k] = toStored(merged);
  const keys = Object.keys(all);
  if (keys.length > MAX_VARIANTS) {
    keys.sort((x, y) => (Number(all[x].t) || 0) - (Number(all[y].t) || 0));
    for (const old of keys.slice(0, keys.length - MAX_VARIANTS)) delete all[old];
  }
  try {
    window.localStorage.setItem(scopedKey(SESSIONS_KEY), JSON.stringify(all));
  } catch {
    /* storage unavailable: the state lives in the page */
  }
  return merged;
}
