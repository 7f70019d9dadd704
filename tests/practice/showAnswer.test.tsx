/** "Show answer" asks first: the button only opens a confirmation; its own "Show answer" reveals. */
import { describe, expect, it, vi } from 'vitest';
import { isValidElement, type ReactElement, type ReactNode } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { RevealPrompt } from '../../src/practice/ShowAnswer';

type Props = { 'data-testid'?: string; onClick?: () => void; children?: ReactNode };

/** The element with this data-testid in a rendered tree (host elements only). */
function byTestId(node: ReactNode, id: string): ReactElement<Props> | null {
  if (Array.isArray(node)) {
    for (const n of node as ReactNode[]) {
      const f = byTestId(n, id);
      if (f) return f;
    }
    return null;
  }
  if (!isValidElement<Props>(node)) return null;
  if (node.props['data-testid'] === id) return node;
  return byTestId(node.props.children, id);
}

function prompt(asking: boolean) {
  const calls = { onAsk: vi.fn(), onCancel: vi.fn(), onConfirm: vi.fn() };
  const tree = RevealPrompt({ partId: 'd', asking, ...calls });
  return { tree, calls };
}

describe('Show answer', () => {
  it('the button asks, it does not reveal', () => {
    const { tree, calls } = prompt(false);
    byTestId(tree, 'show-answer-d')!.props.onClick!();
    expect(calls.onAsk).toHaveBeenCalledTimes(1);
    expect(calls.onConfirm).not.toHaveBeenCalled();
  });

  it('the confirmation names the cost, and reveals or cancels', () => {
    const { tree, calls } = prompt(true);
    const html = renderToStaticMarkup(tree);
    expect(html).toContain('role="group"');
    expect(html).toMatch(/Show the answer to \(d\)\? This part then earns no more marks\./);
    expect(byTestId(tree, 'show-answer-d')).toBeNull();
    byTestId(tree, 'cancel-show-answer-d')!.props.onClick!();
    expect(calls.onCancel).toHaveBeenCalledTimes(1);
    expect(calls.onConfirm).not.toHaveBeenCalled();
    byTestId(tree, 'confirm-show-answer-d')!.props.onClick!();
    expect(calls.onConfirm).toHaveBeenCalledTimes(1);
  });
});
