/**
 * Writes to SVG and HTML elements that React rendered but whose numbers change per animation frame
 * (the stencil, the magnified cell, the tap list), each only when it changed.
 */

/** Sets an attribute if it changed (an unchanged write still invalidates style; per frame that adds up). */
export function setAttr(el: Element, a: string, v: number): void {
  const s = String(v);
  if (el.getAttribute(a) !== s) el.setAttribute(a, s);
}

/** Sets an element's text if it changed (the element's children are not React's). */
export function setText(el: Element | undefined | null, text: string): void {
  if (el && el.textContent !== text) el.textContent = text;
}
