/**
 * The second half of a host's `set` check, after the URL parser's (hostApi validateSet): values the
 * parser accepts but the page would not use as given. A typed expression must compile (a link never
 * carries one that does not), and the scene's own model check (SceneModule.checkValues) must not
 * report a new fallback for the values after the change.
 */
import type { ParamProblem, ParamSchema, ParamValues } from '../kit/params';
import type { SceneCheck } from '../kit/scene';

const key = (p: ParamProblem) => `${p.name}\u0000${p.message}`;

export async function refusedValues(
  schema: ParamSchema,
  current: ParamValues<ParamSchema>,
  patch: Record<string, unknown>,
  check?: SceneCheck,
): Promise<ParamProblem[]> {
  const problems: ParamProblem[] = [];
  for (const [name, value] of Object.entries(patch)) {
    const spec = schema[name];
    if (!spec || spec.kind !== 'string' || !spec.expression || typeof value !== 'string') continue;
    if (value === spec.default) continue;
    try {
      const { compileExpression } = await import('../core/expr');
      const r = await compileExpression(value, spec.expression);
      if (!r.ok) problems.push({ name, message: `does not compile: ${r.message}` });
    } catch (e) {
      problems.push({
        name,
        message: `could not be checked (${e instanceof Error ? e.message : String(e)})`,
      });
    }
  }
  if (problems.length || !check) return problems;
  const next = { ...current, ...patch } as ParamValues<ParamSchema>;
  try {
    const before = new Set((await check(current)).map(key));
    for (const p of await check(next)) if (!before.has(key(p))) problems.push(p);
  } catch (e) {
    problems.push({
      name: 'params',
      message: `could not be checked by the scene (${e instanceof Error ? e.message : String(e)})`,
    });
  }
  return problems;
}
