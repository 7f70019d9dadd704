/**
 * URL parameter schemas: each scene declares its parameters; the shell parses, validates and clamps
 * them and reports every parameter it could not use (by name) in a role="status" notice.
 */
import { fail, type Failure } from '../core/failure';
import { formatPlain } from '../core/format';
import type { Vec3 } from '../core/vec3';

export type ParamSpec =
  | { kind: 'number'; default: number; min?: number; max?: number; integer?: boolean; label?: string }
  | {
      kind: 'enum';
      default: string;
      values: readonly string[];
      aliases?: Readonly<Record<string, string>>;
      label?: string;
    }
  | {
      kind: 'string';
      default: string;
      maxLength?: number;
      label?: string;
      /**
       * Marks a typed math expression in these variables: in the link a literal `+` stays a plus (a
       * hand-written `f=(x+3)^2` means plus, not the form-encoded space), and the shell writes a new
       * value to the URL only once it has compiled.
       */
      expression?: readonly string[];
    }
  | { kind: 'bool'; default: boolean; label?: string }
  | { kind: 'vec3'; default: Vec3; min?: number; max?: number; label?: string }
  | {
      kind: 'list';
      default: readonly number[] | null;
      maxItems: number;
      minItems?: number;
      min?: number;
      max?: number;
      label?: string;
    };

export type ParamSchema = Readonly<Record<string, ParamSpec>>;

type ValueOf<P extends ParamSpec> = P extends { kind: 'number' }
  ? number
  : P extends { kind: 'enum'; values: readonly (infer V)[] }
    ? V
    : P extends { kind: 'string' }
      ? string
      : P extends { kind: 'bool' }
        ? boolean
        : P extends { kind: 'vec3' }
          ? [number, number, number]
          : P extends { kind: 'list'; default: null }
            ? number[] | null
            : P extends { kind: 'list' }
              ? number[] | null
              : never;

export type ParamValues<S extends ParamSchema> = { -readonly [K in keyof S]: ValueOf<S[K]> };

/** One parameter the shell could not use as given, with what it did instead. */
export interface ParamProblem {
  name: string;
  message: string;
}

export interface ParsedParams<S extends ParamSchema> {
  values: ParamValues<S>;
  problems: ParamProblem[];
}

/** The shell's own flags, read by ./shell parseShellFlags (every page takes them). */
export const SHELL_FLAG_NAMES = [
  'embed',
  'present',
  'ask',
  'theme',
  'part',
  'open',
  'origin',
  'a11y',
] as const;

/** Parameters owned by the shell itself, not by any scene: its flags and the fuzzer's (app/fuzz). */
export const SHELL_PARAMS = [...SHELL_FLAG_NAMES, 'fuzz', 'fuzzn', 'fuzzseed'] as const;

/** Longest raw value the parser looks at; longer ones are rejected, not truncated. */
export const MAX_RAW_LENGTH = 4000;

const NUMBER_RE = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

/** Strict number parsing: plain decimal/scientific only (no hex, no '', no 'Infinity'); finite only. */
export function parseNumber(raw: string): number | null {
  const s = raw.trim();
  if (s.length === 0 || s.length > 64 || !NUMBER_RE.test(s)) return null;
  const x = Number(s);
  return Number.isFinite(x) ? x : null;
}

/** Split a comma list of numbers; null if any element is not a finite number. */
function parseNumberList(raw: string): number[] | null {
  const parts = raw.split(',');
  const out: number[] = [];
  for (const p of parts) {
    const x = parseNumber(p);
    if (x === null) return null;
    out.push(x);
  }
  return out;
}

function clamp(x: number, min: number | undefined, max: number | undefined): number {
  if (min !== undefined && x < min) return min;
  if (max !== undefined && x > max) return max;
  return x;
}

function rangeText(min: number | undefined, max: number | undefined): string {
  if (min !== undefined && max !== undefined) return `[${formatPlain(min)}, ${formatPlain(max)}]`;
  if (min !== undefined) return `≥ ${formatPlain(min)}`;
  return `≤ ${formatPlain(max!)}`;
}

function short(raw: string): string {
  const s = raw.length > 24 ? `${raw.slice(0, 24)}…` : raw;
  return JSON.stringify(s);
}

/** One parameter's reading: the value (with a note when it was adjusted), or the one failure shape. */
type Parsed = { ok: true; value: unknown; problem?: string } | Failure<'invalid'>;

function parseOne(spec: ParamSpec, raw: string): Parsed {
  if (raw.length > MAX_RAW_LENGTH) return fail('invalid', `is too long (${raw.length} characters)`);
  switch (spec.kind) {
    case 'number': {
      const x = parseNumber(raw);
      if (x === null) return fail('invalid', `${short(raw)} is not a finite number`);
      // a non-zero number too small for a double (1e-400) reads as 0: say so, not silently
      if (
        x === 0 &&
        /[1-9]/.test(raw.replace(/e.*$/i, '')) &&
        (spec.min ?? -Infinity) <= 0 &&
        (spec.max ?? Infinity) >= 0
      )
        return {
          ok: true,
          value: 0,
          problem: `${short(raw)} is smaller than the smallest double (it rounds to 0); using 0`,
        };
      let v = spec.integer ? Math.round(x) : x;
      const c = clamp(v, spec.min, spec.max);
      if (c !== v)
        return {
          ok: true,
          value: c,
          problem: `${short(raw)} is outside ${rangeText(spec.min, spec.max)}; using ${formatPlain(c)}`,
        };
      v = c;
      if (spec.integer && v !== x)
        return {
          ok: true,
          value: v,
          problem: `${short(raw)} is not a whole number; using ${formatPlain(v)}`,
        };
      return { ok: true, value: v };
    }
    case 'enum': {
      const s = raw.trim();
      // own keys only: 'toString', '__proto__', 'constructor' … are not aliases
      const canonical = spec.values.includes(s)
        ? s
        : spec.aliases && Object.hasOwn(spec.aliases, s)
          ? spec.aliases[s]
          : undefined;
      if (canonical === undefined) {
        return fail('invalid', `${short(raw)} is not one of ${spec.values.join(', ')}`);
      }
      return { ok: true, value: canonical };
    }
    case 'string': {
      const max = spec.maxLength ?? 400;
      if (raw.length > max) return fail('invalid', `is longer than ${max} characters`);
      return { ok: true, value: raw };
    }
    case 'bool': {
      const s = raw.trim().toLowerCase();
      if (s === '1' || s === 'true' || s === 'yes' || s === 'on') return { ok: true, value: true };
      if (s === '0' || s === 'false' || s === 'no' || s === 'off') return { ok: true, value: false };
      return fail('invalid', `${short(raw)} is not 0 or 1`);
    }
    case 'vec3': {
      const xs = parseNumberList(raw);
      if (xs === null || xs.length !== 3) return fail('invalid', `${short(raw)} is not three numbers x,y,z`);
      const c = xs.map((x) => clamp(x, spec.min, spec.max)) as [number, number, number];
      if (c.some((x, i) => x !== xs[i])) {
        return {
          ok: true,
          value: c,
          problem: `has a component outside ${rangeText(spec.min, spec.max)}; using ${c.join(',')}`,
        };
      }
      return { ok: true, value: c };
    }
    case 'list': {
      if (raw.trim() === '') return { ok: true, value: spec.default === null ? null : [...spec.default] };
      const count = raw.split(',').length;
      if (count > spec.maxItems)
        return fail('invalid', `has ${count} items; at most ${spec.maxItems} are allowed`);
      const xs = parseNumberList(raw);
      if (xs === null) return fail('invalid', `${short(raw)} is not a comma-separated list of numbers`);
      if (spec.minItems !== undefined && xs.length < spec.minItems) {
        return fail('invalid', `needs at least ${spec.minItems} numbers`);
      }
      const c = xs.map((x) => clamp(x, spec.min, spec.max));
      if (c.some((x, i) => x !== xs[i])) {
        return {
          ok: true,
          value: c,
          problem: `has values outside ${rangeText(spec.min, spec.max)}; they were clamped`,
        };
      }
      return { ok: true, value: c };
    }
  }
}

function cloneDefault(spec: ParamSpec): unknown {
  const d = spec.default;
  return Array.isArray(d) ? [...d] : d;
}

/** The schema's defaults as a fresh values object. */
export function defaultValues<S extends ParamSchema>(schema: S): ParamValues<S> {
  const out: Record<string, unknown> = {};
  for (const [name, spec] of Object.entries(schema)) out[name] = cloneDefault(spec);
  return out as ParamValues<S>;
}

/**
 * Parse a query string (with or without leading '?') against a schema. Never throws. Every
 * parameter that is unknown, malformed, repeated or out of range is reported by name in
 * `problems`, and the value falls back to the default (or the clamped value). Shell parameters
 * (embed, present, theme) are ignored here.
 */
export function parseParams<S extends ParamSchema>(
  schema: S,
  query: string | URLSearchParams,
): ParsedParams<S> {
  const values = defaultValues(schema) as Record<string, unknown>;
  const problems: ParamProblem[] = [];
  let entries: [string, string, string][];
  try {
    entries =
      typeof query === 'string'
        ? splitQuery(query.startsWith('?') ? query.slice(1) : query)
        : [...query].map(([k, v]) => [k, v, v]);
  } catch {
    return {
      values: values as ParamValues<S>,
      problems: [{ name: '(query)', message: 'could not be read' }],
    };
  }
  const seen = new Set<string>();
  let unknownCount = 0;
  for (const [name, formRaw, plusRaw] of entries) {
    if ((SHELL_PARAMS as readonly string[]).includes(name)) continue;
    if (!Object.hasOwn(schema, name)) {
      unknownCount++;
      if (unknownCount <= 5)
        problems.push({
          name: name.length > 24 ? `${name.slice(0, 24)}…` : name,
          message: 'is not a parameter of this scene; ignored',
        });
      continue;
    }
    if (seen.has(name)) {
      problems.push({ name, message: 'is given more than once; using the first' });
      continue;
    }
    seen.add(name);
    const spec = schema[name];
    const isExpr = spec.kind === 'string' && spec.expression !== undefined;
    const raw = isExpr ? plusRaw : formRaw;
    const r = parseOne(spec, raw);
    if (r.ok) {
      values[name] = r.value;
      if (r.problem) problems.push({ name, message: r.problem });
      else if (isExpr && plusRaw !== formRaw) {
        problems.push({
          name,
          message:
            'contains "+", read as a plus sign (not as a space, as web forms would); write %2B for a plus to be unambiguous',
        });
      }
    } else {
      problems.push({ name, message: `${r.message}; using the default ${describeDefault(spec)}` });
    }
  }
  if (unknownCount > 5)
    problems.push({ name: '(others)', message: `${unknownCount - 5} more unknown parameters ignored` });
  return { values: values as ParamValues<S>, problems };
}

/**
 * Split a query into [name, value as a form would read it ('+' = space), value with '+' kept].
 * Percent-escapes are decoded as URLSearchParams does (a broken escape stays literal text).
 */
function splitQuery(query: string): [string, string, string][] {
  const out: [string, string, string][] = [];
  if (query === '') return out;
  for (const piece of query.split('&')) {
    if (piece === '') continue;
    const eq = piece.indexOf('=');
    const rawName = eq >= 0 ? piece.slice(0, eq) : piece;
    const rawValue = eq >= 0 ? piece.slice(eq + 1) : '';
    const name = formDecode(rawName);
    out.push([name, formDecode(rawValue), formDecode(rawValue.replace(/\+/g, '%2B'))]);
  }
  return out;
}

function formDecode(s: string): string {
  return new URLSearchParams(`v=${s.replace(/&/g, '%26')}`).get('v') ?? '';
}

/**
 * Check one value a scene passes to setParams against its spec (the UI can be driven with
 * anything: devtools, a fuzzer, a select whose value was set to a missing option). Returns the
 * value to store (clamped where the parser would clamp), or undefined if it cannot be used.
 */
export function sanitizeValue(spec: ParamSpec, v: unknown): unknown {
  switch (spec.kind) {
    case 'number': {
      if (typeof v !== 'number' || !Number.isFinite(v)) return undefined;
      const x = spec.integer ? Math.round(v) : v;
      return clamp(x, spec.min, spec.max);
    }
    case 'enum':
      return typeof v === 'string' && spec.values.includes(v) ? v : undefined;
    case 'string': {
      if (typeof v !== 'string') return undefined;
      return v.length <= (spec.maxLength ?? 400) ? v : undefined;
    }
    case 'bool':
      return typeof v === 'boolean' ? v : undefined;
    case 'vec3':
      if (!Array.isArray(v) || v.length !== 3 || !v.every((x) => typeof x === 'number' && Number.isFinite(x)))
        return undefined;
      return (v as number[]).map((x) => clamp(x, spec.min, spec.max));
    case 'list':
      if (v === null) return spec.default === null ? null : undefined;
      if (
        !Array.isArray(v) ||
        v.length > spec.maxItems ||
        (spec.minItems !== undefined && v.length < spec.minItems)
      )
        return undefined;
      if (!v.every((x) => typeof x === 'number' && Number.isFinite(x))) return undefined;
      return (v as number[]).map((x) => clamp(x, spec.min, spec.max));
  }
}

/** The own-schema keys of a setParams patch with usable values (others are dropped). */
export function sanitizePatch(schema: ParamSchema, patch: Record<string, unknown>): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(patch)) {
    if (!Object.hasOwn(schema, k)) continue;
    const c = sanitizeValue(schema[k], v);
    if (c !== undefined) out[k] = c;
  }
  return out;
}

function describeDefault(spec: ParamSpec): string {
  const d = spec.default;
  if (d === null) return '(none)';
  if (Array.isArray(d)) return d.join(',');
  if (typeof d === 'boolean') return d ? '1' : '0';
  if (typeof d === 'string') return d === '' ? '(empty)' : short(d);
  return formatPlain(d as number);
}

/** A number in a link: the shortest text that reads back as the same double (not rounded for people). */
function urlNumber(x: number): string {
  return String(x);
}

function encodeValue(spec: ParamSpec, v: unknown): string | null {
  if (v === null || v === undefined) return null;
  switch (spec.kind) {
    case 'bool':
      return v ? '1' : '0';
    case 'vec3':
    case 'list':
      return (v as number[]).map(urlNumber).join(',');
    case 'number':
      return urlNumber(v as number);
    default:
      return String(v);
  }
}

function sameValue(a: unknown, b: unknown): boolean {
  if (Array.isArray(a) && Array.isArray(b)) return a.length === b.length && a.every((x, i) => x === b[i]);
  return a === b;
}

/**
 * Serialise values to a query string (no leading '?'), omitting parameters equal to their
 * default, in schema order. `extra` (e.g. shell flags) is appended as given.
 */
export function serializeParams<S extends ParamSchema>(
  schema: S,
  values: Partial<ParamValues<S>>,
  extra: Record<string, string | undefined> = {},
): string {
  const parts: string[] = [];
  for (const [name, spec] of Object.entries(schema)) {
    const v = (values as Record<string, unknown>)[name];
    if (v === undefined || sameValue(v, spec.default)) continue;
    const enc = encodeValue(spec, v);
    if (enc === null) continue;
    parts.push(`${encodeURIComponent(name)}=${encodeComponent(enc)}`);
  }
  for (const [k, v] of Object.entries(extra)) if (v !== undefined) parts.push(`${k}=${encodeComponent(v)}`);
  return parts.join('&');
}

/** encodeURIComponent, but keeping `,` `;` `(` `)` `*` readable in shared links. */
function encodeComponent(s: string): string {
  return encodeURIComponent(s)
    .replace(/%2C/g, ',')
    .replace(/%3B/g, ';')
    .replace(/%28/g, '(')
    .replace(/%29/g, ')');
}
