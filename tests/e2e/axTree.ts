/**
 * What a screen reader receives, read from Chromium's accessibility tree over CDP
 * (Accessibility.getPartialAXTree): an element's computed role, name and description.
 */
import type { Page } from '@playwright/test';

export interface AxNode {
  role: string;
  name: string;
  description: string;
  ignored: boolean;
}

interface RawAxNode {
  ignored?: boolean;
  role?: { value?: unknown };
  name?: { value?: unknown };
  description?: { value?: unknown };
}

/** The accessibility node of the first element matching `selector` (null: no such element). */
export async function axNodeOf(page: Page, selector: string): Promise<AxNode | null> {
  const cdp = await page.context().newCDPSession(page);
  try {
    await cdp.send('DOM.enable');
    await cdp.send('Accessibility.enable');
    const { root } = await cdp.send('DOM.getDocument', { depth: 0 });
    const { nodeId } = await cdp.send('DOM.querySelector', { nodeId: root.nodeId, selector });
    if (!nodeId) return null;
    const { nodes } = (await cdp.send('Accessibility.getPartialAXTree', {
      nodeId,
      fetchRelatives: false,
    })) as { nodes: RawAxNode[] };
    const n = nodes[0];
    if (!n) return null;
    const s = (v: unknown) => (typeof v === 'string' ? v : v === undefined ? '' : String(v));
    return {
      role: s(n.role?.value),
      name: s(n.name?.value),
      description: s(n.description?.value),
      ignored: !!n.ignored,
    };
  } finally {
    await cdp.detach();
  }
}

/** Every node of the full tree that is not ignored, as role and name (for searches). */
export async function axTree(page: Page): Promise<{ role: string; name: string; description: string }[]> {
  const cdp = await page.context().newCDPSession(page);
  try {
    await cdp.send('Accessibility.enable');
    const { nodes } = (await cdp.send('Accessibility.getFullAXTree')) as { nodes: RawAxNode[] };
    const s = (v: unknown) => (typeof v === 'string' ? v : v === undefined ? '' : String(v));
    return nodes
      .filter((n) => !n.ignored)
      .map((n) => ({ role: s(n.role?.value), name: s(n.name?.value), description: s(n.description?.value) }));
  } finally {
    await cdp.detach();
  }
}
