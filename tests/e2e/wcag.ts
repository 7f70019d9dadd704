/**
 * In-page checks of WCAG 2.2 criteria axe does not test: target size (2.5.8), reflow (1.4.10),
 * text spacing (1.4.12), focus not obscured (2.4.11). Each returns the offending elements, described.
 */
import type { Page } from '@playwright/test';

/** The interactive elements a pointer can hit. */
export const TARGETS =
  'a[href], button, input:not([type="hidden"]), select, textarea, summary, [role="button"], [role="slider"], [role="checkbox"], [role="tab"], [tabindex="0"]';

/**
 * 2.5.8 Target Size (Minimum): every visible target is at least 24 × 24 CSS px, or a 24 px circle
 * centred on it meets no other target (the spacing exception), or it is a link inside a line of
 * text (the inline exception). Returns the targets that fail.
 */
export function smallTargets(page: Page): Promise<string[]> {
  return page.evaluate((sel) => {
    const describe = (el: Element) => {
      const id = el.getAttribute('data-testid') ?? el.id;
      const text = (el.getAttribute('aria-label') ?? el.textContent ?? '').trim().slice(0, 40);
      const type = el.getAttribute('type');
      return `${el.tagName.toLowerCase()}${type ? `[type=${type}]` : ''}${id ? `#${id}` : ''} "${text}"`;
    };
    const visible = (el: Element) => {
      const r = el.getBoundingClientRect();
      if (r.width === 0 || r.height === 0) return false;
      const cs = getComputedStyle(el);
      if (cs.visibility === 'hidden' || cs.opacity === '0') return false;
      // visually hidden (sr-only) and clipped-away elements are no pointer target
      if (r.width <= 1 && r.height <= 1) return false;
      if (el.closest('[aria-hidden="true"], [inert], .plot-tools, .sr-only')) return false;
      return true;
    };
    /** A link in a run of text: its parent has other text on the same line. */
    const inline = (el: Element) => {
      if (el.tagName !== 'A') return false;
      if (getComputedStyle(el).display !== 'inline') return false;
      const p = el.parentElement;
      if (!p) return false;
      const own = (el.textContent ?? '').trim().length;
      return (p.textContent ?? '').trim().length > own + 2;
    };
    const els = [...document.querySelectorAll(sel)].filter(visible);
    // a label wrapping a checkbox makes the label's box the target
    const rectOf = (el: Element) => {
      const lab = (el as HTMLInputElement).labels?.[0];
      const r = el.getBoundingClientRect();
      const box = el instanceof HTMLInputElement && (el.type === 'checkbox' || el.type === 'radio');
      if (box && lab && lab.contains(el)) {
        const l = lab.getBoundingClientRect();
        return l.width * l.height > r.width * r.height ? l : r;
      }
      return r;
    };
    const rects = els.map(rectOf);
    const small = els
      .map((el, i) => ({ el, r: rects[i]! }))
      .filter(({ r }) => r.width < 23.5 || r.height < 23.5);
    const bad: string[] = [];
    for (const { el, r } of small) {
      if (inline(el)) continue;
      const cx = r.left + r.width / 2;
      const cy = r.top + r.height / 2;
      const hit = els.some((o, j) => {
        if (o === el || o.contains(el) || el.contains(o)) return false;
        const q = rects[j]!;
        // distance from the circle's centre to the other target's box (or, for another small
        // target, to its own circle: both circles must be apart)
        const dx = Math.max(q.left - cx, 0, cx - q.right);
        const dy = Math.max(q.top - cy, 0, cy - q.bottom);
        const oSmall = q.width < 23.5 || q.height < 23.5;
        if (oSmall) {
          const ox = q.left + q.width / 2;
          const oy = q.top + q.height / 2;
          return Math.hypot(ox - cx, oy - cy) < 24;
        }
        return Math.hypot(dx, dy) < 12;
      });
      if (hit) bad.push(`${describe(el)} ${Math.round(r.width)}×${Math.round(r.height)}`);
    }
    return bad;
  }, TARGETS);
}

/** 1.4.10 Reflow: nothing scrolls sideways at this width (wide figures scroll inside their box). */
export function sidewaysOverflow(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const w = document.documentElement.clientWidth;
    if (document.documentElement.scrollWidth <= w + 1) return [];
    const out: string[] = [];
    for (const el of document.querySelectorAll('body *')) {
      const r = el.getBoundingClientRect();
      if (r.right <= w + 1 || r.width === 0) continue;
      // inside a box that scrolls or clips itself: fine
      let p = el.parentElement;
      let clipped = false;
      while (p && p !== document.body) {
        const o = getComputedStyle(p).overflowX;
        if (o === 'auto' || o === 'scroll' || o === 'hidden' || o === 'clip') {
          clipped = true;
          break;
        }
        p = p.parentElement;
      }
      if (!clipped)
        out.push(`${el.tagName.toLowerCase()}.${[...el.classList].join('.')} right=${Math.round(r.right)}`);
      if (out.length > 8) break;
    }
    return out.length ? out : [`the page is ${document.documentElement.scrollWidth} px wide at ${w}`];
  });
}

/** The text-spacing bookmarklet's style (WCAG 1.4.12's metrics), applied to the page. */
export async function applyTextSpacing(page: Page): Promise<void> {
  await page.addStyleTag({
    content:
      '* { line-height: 1.5 !important; letter-spacing: 0.12em !important; word-spacing: 0.16em !important; } p { margin-bottom: 2em !important; }',
  });
}

/** Text cut off by its box after text spacing: elements whose content overflows a clipping box. */
export function clippedText(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const out: string[] = [];
    for (const el of document.querySelectorAll<HTMLElement>('main *, header *')) {
      if (!el.childNodes.length || el.closest('svg, .katex, canvas, .sr-only')) continue;
      const hasText = [...el.childNodes].some((n) => n.nodeType === 3 && (n.textContent ?? '').trim());
      if (!hasText) continue;
      const cs = getComputedStyle(el);
      const clipsX = cs.overflowX === 'hidden' || cs.overflowX === 'clip';
      const clipsY = cs.overflowY === 'hidden' || cs.overflowY === 'clip';
      if (
        (clipsX && el.scrollWidth > el.clientWidth + 1) ||
        (clipsY && el.scrollHeight > el.clientHeight + 1)
      )
        out.push(
          `${el.tagName.toLowerCase()}.${[...el.classList].join('.')} "${(el.textContent ?? '').trim().slice(0, 30)}"`,
        );
      if (out.length > 10) break;
    }
    return out;
  });
}

/**
 * 2.4.11 Focus Not Obscured: the focused element is not entirely hidden by something fixed or
 * sticky above it, in the page as drawn. Returns why, or null.
 *
 * It looks once the next frame is drawn: a focus move scrolls against the layout of the moment, in
 * which a formula block off screen (`content-visibility: auto`) still has its placeholder height;
 * the frame that draws it gives the real height, and what a reader sees is that frame, not the
 * moment between. (A task queued from a frame callback runs after that frame's layout and paint.)
 */
export function focusObscured(page: Page): Promise<string | null> {
  return page.evaluate(async () => {
    await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
    const el = document.activeElement;
    if (!el || el === document.body) return null;
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) return null;
    const pts: [number, number][] = [
      [r.left + r.width / 2, r.top + r.height / 2],
      [r.left + 2, r.top + 2],
      [r.right - 2, r.bottom - 2],
      [r.left + 2, r.bottom - 2],
      [r.right - 2, r.top + 2],
    ];
    let hidden = 0;
    let by = '';
    for (const [x, y] of pts) {
      if (x < 0 || y < 0 || x >= innerWidth || y >= innerHeight) {
        hidden++;
        by = 'off screen';
        continue;
      }
      const top = document.elementFromPoint(x, y);
      if (!top || top === el || el.contains(top) || top.contains(el)) continue;
      // covered: by something positioned fixed or sticky?
      let p: Element | null = top;
      while (p && p !== document.body) {
        const pos = getComputedStyle(p).position;
        if (pos === 'fixed' || pos === 'sticky') {
          hidden++;
          by = `${p.tagName.toLowerCase()}.${[...p.classList].join('.')}`;
          break;
        }
        p = p.parentElement;
      }
    }
    if (hidden < pts.length) return null;
    const name = (el.getAttribute('data-testid') ?? el.textContent ?? '').trim().slice(0, 30);
    return `${el.tagName.toLowerCase()} "${name}" hidden by ${by} (top ${Math.round(r.top)} px of ${innerHeight}, scrollY ${Math.round(scrollY)})`;
  });
}

/**
 * 1.4.11 / 2.4.7: the focused element shows a focus indicator (an outline of at least 2 px, or a
 * box shadow) whose colour keeps 3 : 1 against the background behind it. Returns why not, or null.
 */
export function weakFocusRing(page: Page): Promise<string | null> {
  return page.evaluate(() => {
    const el = document.activeElement as HTMLElement | null;
    if (!el || el === document.body || !el.matches(':focus-visible')) return null;
    const cs = getComputedStyle(el);
    const name = `${el.tagName.toLowerCase()}${el.dataset.testid ? `#${el.dataset.testid}` : ''}.${[...el.classList].join('.')}`;
    const rgb = (s: string) => {
      const m = /rgba?\(([^)]+)\)/.exec(s);
      if (!m) return null;
      const p = m[1]!
        .split(/[ ,/]+/)
        .filter(Boolean)
        .map(Number);
      return { c: [p[0]! / 255, p[1]! / 255, p[2]! / 255], a: p[3] ?? 1 };
    };
    const lum = (c: number[]) => {
      const l = c.map((v) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4));
      return 0.2126 * l[0]! + 0.7152 * l[1]! + 0.0722 * l[2]!;
    };
    // the background behind the ring: the first ancestor (outside the element) with an opaque one
    let bg: number[] = [1, 1, 1];
    for (let p = el.parentElement; p; p = p.parentElement) {
      const b = rgb(getComputedStyle(p).backgroundColor);
      if (b && b.a > 0.5) {
        bg = b.c;
        break;
      }
      if (p === document.documentElement) {
        const body = rgb(getComputedStyle(document.body).backgroundColor);
        if (body && body.a > 0.5) bg = body.c;
      }
    }
    const ow = parseFloat(cs.outlineWidth) || 0;
    if (cs.outlineStyle !== 'none' && ow >= 2) {
      const o = rgb(cs.outlineColor);
      if (!o) return null;
      const a = lum(o.c);
      const b = lum(bg);
      const ratio = (Math.max(a, b) + 0.05) / (Math.min(a, b) + 0.05);
      return ratio >= 3
        ? null
        : `${name}: focus outline ${cs.outlineColor} is ${ratio.toFixed(2)}:1 on its background`;
    }
    if (cs.boxShadow && cs.boxShadow !== 'none') return null;
    // an SVG handle draws its own ring: a part stroked in the focus colour, at least 2 px wide
    if (el instanceof SVGElement) {
      const probe = document.createElement('span');
      probe.style.color = 'var(--focus)';
      document.body.appendChild(probe);
      const focus = getComputedStyle(probe).color;
      probe.remove();
      const ring = [...el.querySelectorAll('*')].some((p) => {
        const ps = getComputedStyle(p);
        return ps.stroke === focus && (parseFloat(ps.strokeWidth) || 0) >= 2;
      });
      if (ring) return null;
    }
    return `${name}: no visible focus indicator (outline ${cs.outlineStyle} ${cs.outlineWidth})`;
  });
}
