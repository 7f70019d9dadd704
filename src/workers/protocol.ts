/** Messages between {@link runWorkerTask} and {@link exposeTasks}. */
export type ToWorker = { id: number; method: string; args: unknown };
export type FromWorker =
  | { id: number; type: 'progress'; fraction: number; partial?: unknown }
  | { id: number; type: 'result'; value: unknown }
  | { id: number; type: 'error'; message: string };

/** Typed-array buffers inside a value (one level of objects/arrays deep, plus the value itself). */
export function collectTransferables(value: unknown, out: Transferable[] = [], depth = 0): Transferable[] {
  if (value === null || typeof value !== 'object' || depth > 3) return out;
  if (ArrayBuffer.isView(value)) {
    const buf = value.buffer;
    if (buf instanceof ArrayBuffer && !out.includes(buf)) out.push(buf);
    return out;
  }
  if (value instanceof ArrayBuffer) {
    if (!out.includes(value)) out.push(value);
    return out;
  }
  const items = Array.isArray(value) ? value : Object.values(value as Record<string, unknown>);
  for (const v of items) collectTransferables(v, out, depth + 1);
  return out;
}
