/**
 * LaTeX for a whitelisted expression tree, rendered from the AST in one pass (linear in the number
 * of nodes). mathjs's own `toTex` renders each function argument more than once, so its cost doubles
 * with every level of nesting (`exp(exp(…exp(x)…))` at 60 levels never finishes); this renderer
 * visits every node exactly once and adds a bounded number of characters per node.
 *
 * It accepts only the node kinds that {@link checkAndCompile} accepts; call it after compiling.
 */
import { SYMBOL_ALIASES } from './compile';

interface NodeLike {
  type: string;
  [k: string]: unknown;
}

const SYMBOL_TEX = new Map<string, string>([
  ['theta', '\\theta'],
  ['phi', '\\phi'],
  ['pi', '\\pi'],
  ['tau', '\\tau'],
  ['e', 'e'],
]);

/** Functions rendered as an operator name followed by a parenthesised argument list. */
const FUNCTION_TEX = new Map<string, string>([
  ['sin', '\\sin'],
  ['cos', '\\cos'],
  ['tan', '\\tan'],
  ['sec', '\\sec'],
  ['csc', '\\csc'],
  ['cot', '\\cot'],
  ['asin', '\\arcsin'],
  ['acos', '\\arccos'],
  ['atan', '\\arctan'],
  ['atan2', '\\operatorname{atan2}'],
  ['sinh', '\\sinh'],
  ['cosh', '\\cosh'],
  ['tanh', '\\tanh'],
  ['exp', '\\exp'],
  ['log1p', '\\operatorname{log1p}'],
  ['expm1', '\\operatorname{expm1}'],
  ['min', '\\min'],
  ['max', '\\max'],
  ['sign', '\\operatorname{sign}'],
]);

/** Binding strength of the operators, higher binds tighter (as mathjs parses them). */
const PRECEDENCE = new Map<string, number>([
  ['add', 1],
  ['subtract', 1],
  ['multiply', 2],
  ['divide', 2],
  ['unaryMinus', 3],
  ['unaryPlus', 3],
  ['pow', 4],
]);

function escapeText(s: string): string {
  return s.replace(/[\\{}$&#^_%~]/g, ' ');
}

function numberTex(v: unknown): string {
  if (typeof v !== 'number') return `\\text{${escapeText(String(v))}}`;
  const s = String(v);
  const m = /^(-?[\d.]+)e([+-]?)(\d+)$/.exec(s);
  if (m) return `${m[1]}\\cdot 10^{${m[2] === '-' ? '-' : ''}${m[3]}}`;
  return s;
}

function symbolTex(raw: string): string {
  const name = Object.hasOwn(SYMBOL_ALIASES, raw) ? SYMBOL_ALIASES[raw] : raw;
  const t = SYMBOL_TEX.get(name);
  if (t !== undefined) return t;
  if (/^[A-Za-z]$/.test(name)) return name;
  return `\\mathrm{${escapeText(name).replace(/ /g, '')}}`;
}

function precedenceOf(node: NodeLike): number {
  if (node.type === 'OperatorNode') return PRECEDENCE.get(String(node.fn)) ?? 5;
  return 5; // atoms, calls, parentheses
}

/** Unwrap a ParenthesisNode where the layout itself groups (fraction parts, exponents, arguments). */
function unwrap(node: NodeLike): NodeLike {
  let n = node;
  while (n.type === 'ParenthesisNode') n = n.content as NodeLike;
  return n;
}

/** Render `node`; parenthesise it when it binds looser than `minPrec`. */
function child(node: NodeLike, minPrec: number): string {
  const s = render(node);
  return precedenceOf(node) < minPrec ? `\\left(${s}\\right)` : s;
}

function render(node: NodeLike): string {
  switch (node.type) {
    case 'ConstantNode':
      return numberTex(node.value);
    case 'SymbolNode':
      return symbolTex(String(node.name));
    case 'ParenthesisNode':
      return `\\left(${render(node.content as NodeLike)}\\right)`;
    case 'OperatorNode': {
      const fn = String(node.fn);
      const args = node.args as NodeLike[];
      if (args.length === 1) {
        const sign = fn === 'unaryMinus' ? '-' : '+';
        return `${sign}${child(args[0], 3)}`;
      }
      const [a, b] = args as [NodeLike, NodeLike];
      switch (fn) {
        case 'add':
          return `${child(a, 1)}+${child(b, 2)}`;
        case 'subtract':
          return `${child(a, 1)}-${child(b, 2)}`;
        case 'multiply':
          return node.implicit ? `${child(a, 2)}\\,${child(b, 3)}` : `${child(a, 2)}\\cdot ${child(b, 3)}`;
        case 'divide':
          return `\\frac{${render(unwrap(a))}}{${render(unwrap(b))}}`;
        case 'pow': {
          // a base that is itself an operator (or a power) needs visible parentheses
          const base =
            precedenceOf(a) <= 4 && a.type === 'OperatorNode' ? `\\left(${render(a)}\\right)` : render(a);
          return `{${base}}^{${render(unwrap(b))}}`;
        }
        default:
          return `${child(a, 5)}\\mathbin{${escapeText(String(node.op))}}${child(b, 5)}`;
      }
    }
    case 'FunctionNode': {
      const name = String((node.fn as NodeLike).name);
      const args = (node.args as NodeLike[]).map(unwrap);
      const list = () => args.map(render).join(',\\,');
      switch (name) {
        case 'sqrt':
          return `\\sqrt{${list()}}`;
        case 'cbrt':
          return `\\sqrt[3]{${list()}}`;
        case 'abs':
          return `\\left|${list()}\\right|`;
        case 'floor':
          return `\\left\\lfloor ${list()}\\right\\rfloor`;
        case 'ceil':
          return `\\left\\lceil ${list()}\\right\\rceil`;
        case 'pow':
          return args.length === 2
            ? `{\\left(${render(args[0])}\\right)}^{${render(args[1])}}`
            : `\\operatorname{pow}\\left(${list()}\\right)`;
        case 'log':
          return args.length === 2
            ? `\\log_{${render(args[1])}}\\left(${render(args[0])}\\right)`
            : `\\ln\\left(${list()}\\right)`;
        default: {
          const op = FUNCTION_TEX.get(name) ?? `\\mathrm{${escapeText(name).replace(/ /g, '')}}`;
          return `${op}\\left(${list()}\\right)`;
        }
      }
    }
    default:
      return `\\text{${escapeText(String(node.type))}}`;
  }
}

/** LaTeX for a (whitelisted) parsed expression tree, in time linear in its size. */
export function treeToTex(tree: unknown): string {
  return render(tree as NodeLike);
}
