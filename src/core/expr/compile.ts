/**
 * Whitelist check and compilation of a parsed mathjs expression tree into a plain JavaScript closure
 * tree. No `eval`, no `new Function`, and no mathjs evaluation per sample: each node becomes one small
 * closure, constants are folded at compile time.
 *
 * Why a typed expression cannot freeze the page: the accepted language has no loops, recursion,
 * assignments, function definitions or calls to anything but a fixed list of Math functions, so one
 * evaluation visits each node once and its cost is bounded by the number of nodes; the source is
 * limited to {@link MAX_EXPRESSION_LENGTH} characters and the tree to {@link MAX_EXPRESSION_DEPTH}
 * levels, which bounds that number. Evaluating it a million times is then as predictable as any
 * other kernel (and the scenes do it in batches or in a worker).
 */
import type { MathNode } from 'mathjs';

/** Longest accepted source text, in characters. */
export const MAX_EXPRESSION_LENGTH = 400;
/** Deepest accepted tree (nesting of operators, functions and parentheses). */
export const MAX_EXPRESSION_DEPTH = 64;
/** At most this many variables (the compiled closure takes them positionally). */
export const MAX_EXPRESSION_VARIABLES = 4;

/** A compiled expression of up to four positional variables. */
export type CompiledFn = (...vars: number[]) => number;
type Fn4 = (a: number, b: number, c: number, d: number) => number;

/** Symbol aliases accepted in the source, mapped to their canonical names. */
export const SYMBOL_ALIASES: Readonly<Record<string, string>> = {
  θ: 'theta',
  ϑ: 'theta',
  φ: 'phi',
  ϕ: 'phi',
  π: 'pi',
  τ: 'tau',
};

/** Named constants accepted in expressions. */
export const EXPRESSION_CONSTANTS: Readonly<Record<string, number>> = {
  pi: Math.PI,
  e: Math.E,
  tau: 2 * Math.PI,
};

type MathFn = (...a: number[]) => number;
/** Whitelisted functions: name → [implementation, min arity, max arity]. Real-valued (Math) semantics. */
export const EXPRESSION_FUNCTIONS: Readonly<Record<string, readonly [MathFn, number, number]>> = {
  sin: [Math.sin, 1, 1],
  cos: [Math.cos, 1, 1],
  tan: [Math.tan, 1, 1],
  sec: [(x: number) => 1 / Math.cos(x), 1, 1],
  csc: [(x: number) => 1 / Math.sin(x), 1, 1],
  cot: [(x: number) => 1 / Math.tan(x), 1, 1],
  asin: [Math.asin, 1, 1],
  acos: [Math.acos, 1, 1],
  atan: [Math.atan, 1, 1],
  atan2: [Math.atan2, 2, 2],
  sinh: [Math.sinh, 1, 1],
  cosh: [Math.cosh, 1, 1],
  tanh: [Math.tanh, 1, 1],
  exp: [Math.exp, 1, 1],
  log: [(x: number, b?: number) => (b === undefined ? Math.log(x) : Math.log(x) / Math.log(b)), 1, 2],
  log1p: [Math.log1p, 1, 1],
  expm1: [Math.expm1, 1, 1],
  sqrt: [Math.sqrt, 1, 1],
  cbrt: [Math.cbrt, 1, 1],
  abs: [Math.abs, 1, 1],
  min: [Math.min, 1, 16],
  max: [Math.max, 1, 16],
  pow: [Math.pow, 2, 2],
  floor: [Math.floor, 1, 1],
  ceil: [Math.ceil, 1, 1],
  sign: [Math.sign, 1, 1],
};

const BINARY: Readonly<Record<string, (a: number, b: number) => number>> = {
  add: (a, b) => a + b,
  subtract: (a, b) => a - b,
  multiply: (a, b) => a * b,
  divide: (a, b) => a / b,
  pow: Math.pow,
};

/** Thrown by {@link checkAndCompile} with a message meant for the person who typed the expression. */
export class ExpressionError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'ExpressionError';
  }
}

interface NodeLike {
  type: string;
  [k: string]: unknown;
}

type Compiled = { fn: Fn4; constant: boolean; value?: number; varIndex?: number };

/**
 * Check a parsed tree against the whitelist and compile it. Throws {@link ExpressionError}.
 * Accepted: numeric constants; the given variables (with aliases θ→theta, φ→phi); constants pi, e,
 * tau; + − * / ^ and unary ±; parentheses; the functions of {@link EXPRESSION_FUNCTIONS}.
 * Rejected: assignments, function definitions, matrices, strings, booleans, ranges, accessors,
 * objects, conditionals, relational and other operators, several statements, unknown names.
 */
export function checkAndCompile(tree: MathNode, variables: readonly string[]): CompiledFn {
  if (variables.length > MAX_EXPRESSION_VARIABLES) {
    throw new ExpressionError(`at most ${MAX_EXPRESSION_VARIABLES} variables are supported`);
  }
  const c = compileNode(tree as unknown as NodeLike, variables, 0);
  return c.fn as CompiledFn;
}

function describeVars(variables: readonly string[]): string {
  return variables.length ? `use ${variables.join(', ')}` : 'this expression takes no variables';
}

function canonicalName(name: string): string {
  return Object.hasOwn(SYMBOL_ALIASES, name) ? SYMBOL_ALIASES[name] : name;
}

const KIND_NAMES: Readonly<Record<string, string>> = {
  AssignmentNode: 'assignments (=) are not allowed',
  FunctionAssignmentNode: 'defining functions is not allowed',
  ArrayNode: 'matrices and lists ([…]) are not allowed',
  AccessorNode: 'property access and indexing (x.y, x[i]) are not allowed',
  IndexNode: 'indexing is not allowed',
  RangeNode: 'ranges (a:b) are not allowed',
  ObjectNode: 'objects ({…}) are not allowed',
  ConditionalNode: 'conditionals (a ? b : c) are not allowed',
  RelationalNode: 'comparisons are not allowed',
  BlockNode: 'only one expression is allowed (no ; or line breaks)',
};

function constantFn(v: number): Compiled {
  return { fn: () => v, constant: true, value: v };
}

// Specialized closures. Each function literal below is its own piece of code, so the engine can
// inline the Math call it makes; a single generic `g(f(…))` closure shared by every node would
// make every call site megamorphic (measured ~2–4× slower on typical pdfs).
const UNARY_MAKERS: Readonly<Record<string, (f: Fn4) => Fn4>> = {
  sin: (f) => (x, y, z, w) => Math.sin(f(x, y, z, w)),
  cos: (f) => (x, y, z, w) => Math.cos(f(x, y, z, w)),
  tan: (f) => (x, y, z, w) => Math.tan(f(x, y, z, w)),
  sec: (f) => (x, y, z, w) => 1 / Math.cos(f(x, y, z, w)),
  csc: (f) => (x, y, z, w) => 1 / Math.sin(f(x, y, z, w)),
  cot: (f) => (x, y, z, w) => 1 / Math.tan(f(x, y, z, w)),
  asin: (f) => (x, y, z, w) => Math.asin(f(x, y, z, w)),
  acos: (f) => (x, y, z, w) => Math.acos(f(x, y, z, w)),
  atan: (f) => (x, y, z, w) => Math.atan(f(x, y, z, w)),
  sinh: (f) => (x, y, z, w) => Math.sinh(f(x, y, z, w)),
  cosh: (f) => (x, y, z, w) => Math.cosh(f(x, y, z, w)),
  tanh: (f) => (x, y, z, w) => Math.tanh(f(x, y, z, w)),
  exp: (f) => (x, y, z, w) => Math.exp(f(x, y, z, w)),
  log: (f) => (x, y, z, w) => Math.log(f(x, y, z, w)),
  log1p: (f) => (x, y, z, w) => Math.log1p(f(x, y, z, w)),
  expm1: (f) => (x, y, z, w) => Math.expm1(f(x, y, z, w)),
  sqrt: (f) => (x, y, z, w) => Math.sqrt(f(x, y, z, w)),
  cbrt: (f) => (x, y, z, w) => Math.cbrt(f(x, y, z, w)),
  abs: (f) => (x, y, z, w) => Math.abs(f(x, y, z, w)),
  floor: (f) => (x, y, z, w) => Math.floor(f(x, y, z, w)),
  ceil: (f) => (x, y, z, w) => Math.ceil(f(x, y, z, w)),
  sign: (f) => (x, y, z, w) => Math.sign(f(x, y, z, w)),
};

/** Unary functions applied directly to the first or second variable (the common cos(θ), e^φ cases). */
const UNARY_ON_VAR: Readonly<Record<string, readonly [Fn4, Fn4]>> = {
  sin: [(x) => Math.sin(x), (_x, y) => Math.sin(y)],
  cos: [(x) => Math.cos(x), (_x, y) => Math.cos(y)],
  exp: [(x) => Math.exp(x), (_x, y) => Math.exp(y)],
  sqrt: [(x) => Math.sqrt(x), (_x, y) => Math.sqrt(y)],
  log: [(x) => Math.log(x), (_x, y) => Math.log(y)],
  tan: [(x) => Math.tan(x), (_x, y) => Math.tan(y)],
  abs: [(x) => Math.abs(x), (_x, y) => Math.abs(y)],
};

function binary(op: string, l: Compiled, r: Compiled): Fn4 {
  const f = l.fn;
  const g = r.fn;
  if (l.value !== undefined) {
    const c = l.value;
    switch (op) {
      case 'add':
        return (x, y, z, w) => c + g(x, y, z, w);
      case 'subtract':
        return (x, y, z, w) => c - g(x, y, z, w);
      case 'multiply':
        return (x, y, z, w) => c * g(x, y, z, w);
      case 'divide':
        return (x, y, z, w) => c / g(x, y, z, w);
      default:
        if (c === Math.E) return (x, y, z, w) => Math.exp(g(x, y, z, w));
        return (x, y, z, w) => Math.pow(c, g(x, y, z, w));
    }
  }
  if (r.value !== undefined) {
    const c = r.value;
    switch (op) {
      case 'add':
        return (x, y, z, w) => f(x, y, z, w) + c;
      case 'subtract':
        return (x, y, z, w) => f(x, y, z, w) - c;
      case 'multiply':
        return (x, y, z, w) => f(x, y, z, w) * c;
      case 'divide':
        return (x, y, z, w) => f(x, y, z, w) / c;
      default:
        if (c === 2) {
          return (x, y, z, w) => {
            const v = f(x, y, z, w);
            return v * v;
          };
        }
        return (x, y, z, w) => Math.pow(f(x, y, z, w), c);
    }
  }
  switch (op) {
    case 'add':
      return (x, y, z, w) => f(x, y, z, w) + g(x, y, z, w);
    case 'subtract':
      return (x, y, z, w) => f(x, y, z, w) - g(x, y, z, w);
    case 'multiply':
      return (x, y, z, w) => f(x, y, z, w) * g(x, y, z, w);
    case 'divide':
      return (x, y, z, w) => f(x, y, z, w) / g(x, y, z, w);
    default:
      return (x, y, z, w) => Math.pow(f(x, y, z, w), g(x, y, z, w));
  }
}

function compileNode(node: NodeLike, variables: readonly string[], depth: number): Compiled {
  if (depth > MAX_EXPRESSION_DEPTH)
    throw new ExpressionError(
      `the expression is nested too deeply (more than ${MAX_EXPRESSION_DEPTH} levels)`,
    );
  switch (node.type) {
    case 'ConstantNode': {
      const v = node.value;
      if (v === undefined)
        throw new ExpressionError('the expression is empty (everything after # is a comment)');
      if (typeof v !== 'number') {
        throw new ExpressionError(
          typeof v === 'string'
            ? 'text strings are not allowed'
            : `the constant '${String(v)}' is not a number`,
        );
      }
      if (!Number.isFinite(v))
        throw new ExpressionError(
          `a number in the expression is ${Number.isNaN(v) ? 'NaN' : 'infinite or too large'} (numbers must be finite)`,
        );
      return constantFn(v);
    }
    case 'SymbolNode': {
      const raw = String(node.name);
      const name = canonicalName(raw);
      const k = variables.indexOf(name);
      if (k >= 0) return { fn: argGetter(k), constant: false, varIndex: k };
      if (Object.prototype.hasOwnProperty.call(EXPRESSION_CONSTANTS, name))
        return constantFn(EXPRESSION_CONSTANTS[name]);
      throw new ExpressionError(`unknown symbol '${raw}' — ${describeVars(variables)}`);
    }
    case 'ParenthesisNode':
      return compileNode(node.content as NodeLike, variables, depth + 1);
    case 'OperatorNode': {
      const fnName = String(node.fn);
      // A left-associative chain (1 + 1 + … + 1, a * b * c) is flat to the reader: its left operand
      // of the same operator does not count as a level of nesting.
      const args = (node.args as NodeLike[]).map((a, i) =>
        compileNode(
          a,
          variables,
          i === 0 &&
            a.type === 'OperatorNode' &&
            sameFamily(String(a.fn), fnName) &&
            (node.args as NodeLike[]).length === 2
            ? depth
            : depth + 1,
        ),
      );
      if (args.length === 1 && (fnName === 'unaryMinus' || fnName === 'unaryPlus')) {
        const a = args[0];
        if (fnName === 'unaryPlus') return a;
        const f = a.fn;
        return fold({ fn: (x, y, z, w) => -f(x, y, z, w), constant: a.constant });
      }
      if (Object.prototype.hasOwnProperty.call(BINARY, fnName) && args.length === 2) {
        const fn = binary(fnName, args[0], args[1]);
        return fold({ fn, constant: args[0].constant && args[1].constant });
      }
      throw new ExpressionError(`the operator '${String(node.op)}' is not allowed (use + − * / ^)`);
    }
    case 'FunctionNode': {
      const fnNode = node.fn as NodeLike;
      if (fnNode.type !== 'SymbolNode')
        throw new ExpressionError('only calls of named functions like sin(x) are allowed');
      const raw = String(fnNode.name);
      const entry = Object.prototype.hasOwnProperty.call(EXPRESSION_FUNCTIONS, raw)
        ? EXPRESSION_FUNCTIONS[raw]
        : undefined;
      if (!entry) throw new ExpressionError(`function '${raw}' is not allowed`);
      const [impl, lo, hi] = entry;
      const argNodes = node.args as NodeLike[];
      if (argNodes.length < lo || argNodes.length > hi) {
        const want = lo === hi ? `${lo}` : `${lo} to ${hi}`;
        throw new ExpressionError(
          `function '${raw}' takes ${want} argument${hi === 1 ? '' : 's'}, got ${argNodes.length}`,
        );
      }
      const args = argNodes.map((a) => compileNode(a, variables, depth + 1));
      const constant = args.every((a) => a.constant);
      const fs = args.map((a) => a.fn);
      let fn: Fn4;
      if (fs.length === 1) {
        const onVar = Object.hasOwn(UNARY_ON_VAR, raw) ? UNARY_ON_VAR[raw] : undefined;
        const k = args[0].varIndex;
        const make = Object.hasOwn(UNARY_MAKERS, raw) ? UNARY_MAKERS[raw] : undefined;
        if (onVar && (k === 0 || k === 1)) fn = onVar[k];
        else if (make) fn = make(fs[0]);
        else {
          const f0 = fs[0];
          const g = impl as (a: number) => number;
          fn = (x, y, z, w) => g(f0(x, y, z, w));
        }
      } else if (fs.length === 2) {
        const f = fs[0];
        const h = fs[1];
        const g = impl as (a: number, b: number) => number;
        fn = (x, y, z, w) => g(f(x, y, z, w), h(x, y, z, w));
      } else {
        const buf = new Array<number>(fs.length);
        fn = (x, y, z, w) => {
          for (let i = 0; i < fs.length; i++) buf[i] = fs[i](x, y, z, w);
          return impl(...buf);
        };
      }
      return fold({ fn, constant });
    }
    default: {
      const msg = Object.hasOwn(KIND_NAMES, node.type) ? KIND_NAMES[node.type] : undefined;
      throw new ExpressionError(msg ?? `this kind of expression (${node.type}) is not allowed`);
    }
  }
}

const FAMILY: Readonly<Record<string, number>> = { add: 1, subtract: 1, multiply: 2, divide: 2 };
function sameFamily(a: string, b: string): boolean {
  return Object.hasOwn(FAMILY, a) && FAMILY[a] === FAMILY[b];
}

function fold(c: Compiled): Compiled {
  return c.constant ? constantFn(c.fn(0, 0, 0, 0)) : c;
}

function argGetter(k: number): Fn4 {
  switch (k) {
    case 0:
      return (x) => x;
    case 1:
      return (_x, y) => y;
    case 2:
      return (_x, _y, z) => z;
    default:
      return (_x, _y, _z, w) => w;
  }
}

/** Replace alias symbols (θ, φ, π, τ) by their canonical names in a parsed tree (returns a new tree). */
export function canonicalizeTree(tree: MathNode): MathNode {
  return tree.transform((n) => {
    const node = n as unknown as NodeLike;
    if (node.type === 'SymbolNode') {
      const name = String(node.name);
      const canon = Object.hasOwn(SYMBOL_ALIASES, name) ? SYMBOL_ALIASES[name] : undefined;
      if (canon) {
        const copy = n.clone() as unknown as { name: string };
        copy.name = canon;
        return copy as unknown as MathNode;
      }
    }
    return n;
  });
}
