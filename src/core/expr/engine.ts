/**
 * The lazily loaded half of the expression module: a minimal mathjs instance that can only parse
 * (built with `create({ parseDependencies })`, not `all`, so its chunk stays small). Nothing here
 * evaluates: parsed trees are checked and compiled by `compile.ts`.
 * Import this only through `loadExpressionEngine()` (index.ts), never statically.
 * Source: mathjs custom bundling, https://mathjs.org/docs/custom_bundling.html
 */
import { create, parseDependencies, type MathNode } from 'mathjs/number';

const math = create({ parseDependencies }, { number: 'number' });

/** Parse mathjs syntax into an expression tree; throws mathjs's SyntaxError (with `.char`) on bad input. */
export function parseToTree(src: string): MathNode {
  return math.parse(src);
}

export type { MathNode };
