/**
 * Comparing a render with its reference the way researchers do: a wipe (the reference left of the
 * split, the render right of it; the slider moves the split) and a loupe (the pixel under the
 * pointer, or moved by the arrow keys when the image has focus: its 8-bit sRGB values in both
 * images and its FLIP error, with the 9 × 9 pixels around it magnified). The FLIP error map beside
 * it is the false-colour view.
 */
import { useEffect, useId, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { formatNumber } from './format';
import { paintRgba } from './imageMeasure';

/** Side of the loupe's window, in image pixels. */
const LOUPE = 9;

export interface CompareProps {
  width: number;
  height: number;
  reference: Uint8ClampedArray;
  render: Uint8ClampedArray;
  /** Each pixel's FLIP error (null while it is computed). */
  errors: Float32Array | null;
}

/** The wipe's pixels: reference for columns < split, render from split on. */
export function wipePixels(p: CompareProps, split: number, out = new Uint8ClampedArray(p.reference.length)) {
  const { width, height } = p;
  for (let j = 0; j < height; j++)
    for (let i = 0; i < width; i++) {
      const o = 4 * (j * width + i);
      const src = i < split ? p.reference : p.render;
      out[o] = src[o];
      out[o + 1] = src[o + 1];
      out[o + 2] = src[o + 2];
      out[o + 3] = 255;
    }
  return out;
}

/** The loupe's window of side LOUPE around (i, j), clamped inside the image; pixels outside stay black. */
export function loupePixels(src: Uint8ClampedArray, width: number, height: number, i: number, j: number) {
  const out = new Uint8ClampedArray(4 * LOUPE * LOUPE);
  const h = (LOUPE - 1) / 2;
  for (let y = 0; y < LOUPE; y++)
    for (let x = 0; x < LOUPE; x++) {
      const si = i - h + x,
        sj = j - h + y;
      const o = 4 * (y * LOUPE + x);
      out[o + 3] = 255;
      if (si < 0 || sj < 0 || si >= width || sj >= height) continue;
      const s = 4 * (sj * width + si);
      out[o] = src[s];
      out[o + 1] = src[s + 1];
      out[o + 2] = src[s + 2];
    }
  return out;
}

const rgb = (src: Uint8ClampedArray, k: number) =>
  src[4 * k] === src[4 * k + 1] && src[4 * k] === src[4 * k + 2]
    ? String(src[4 * k])
    : `${src[4 * k]}, ${src[4 * k + 1]}, ${src[4 * k + 2]}`;

export function ImageCompare(p: CompareProps) {
  const { width: w, height: h } = p;
  const [split, setSplit] = useState(Math.round(w / 2));
  const [at, setAt] = useState<[number, number]>([Math.floor(w / 2), Math.floor(h / 2)]);
  const wipe = useRef<HTMLCanvasElement>(null);
  const lRef = useRef<HTMLCanvasElement>(null);
  const lRender = useRef<HTMLCanvasElement>(null);
  const sliderId = useId();
  useEffect(() => paintRgba(wipe.current, wipePixels(p, split), w, h), [p, split, w, h]);
  useEffect(() => {
    paintRgba(lRef.current, loupePixels(p.reference, w, h, at[0], at[1]), LOUPE, LOUPE);
    paintRgba(lRender.current, loupePixels(p.render, w, h, at[0], at[1]), LOUPE, LOUPE);
  }, [p, at, w, h]);
  const k = at[1] * w + at[0];
  const move = (e: PointerEvent<HTMLCanvasElement>) => {
    const box = e.currentTarget.getBoundingClientRect();
    const i = Math.floor(((e.clientX - box.left) / box.width) * w);
    const j = Math.floor(((e.clientY - box.top) / box.height) * h);
    if (i >= 0 && j >= 0 && i < w && j < h) setAt([i, j]);
  };
  const key = (e: KeyboardEvent<HTMLCanvasElement>) => {
    const step = e.shiftKey ? 8 : 1;
    const d: Record<string, [number, number]> = {
      ArrowLeft: [-step, 0],
      ArrowRight: [step, 0],
      ArrowUp: [0, -step],
      ArrowDown: [0, step],
    };
    const m = d[e.key];
    if (!m) return;
    e.preventDefault();
    setAt(([i, j]) => [Math.min(w - 1, Math.max(0, i + m[0])), Math.min(h - 1, Math.max(0, j + m[1]))]);
  };
  return (
    <div className="compare" data-testid="measure-compare">
      <figure className="compare-wipe">
        <div className="compare-box">
          <canvas
            ref={wipe}
            width={w}
            height={h}
            className="measure-canvas compare-canvas"
            tabIndex={0}
            role="img"
            aria-label={`Wipe: the reference left of column ${split}, the render right of it. Arrow keys move the loupe (Shift: 8 pixels).`}
            data-testid="compare-wipe"
            onPointerMove={move}
            onPointerDown={move}
            onKeyDown={key}
          />
          <span className="compare-split" style={{ left: `${(100 * split) / w}%` }} aria-hidden="true" />
          <span
            className="compare-mark"
            style={{ left: `${(100 * (at[0] + 0.5)) / w}%`, top: `${(100 * (at[1] + 0.5)) / h}%` }}
            aria-hidden="true"
          />
        </div>
        <figcaption>
          <label htmlFor={sliderId}>Wipe: reference ← → render</label>
          <input
            id={sliderId}
            type="range"
            min={0}
            max={w}
            step={1}
            value={split}
            data-testid="compare-split"
            onChange={(e) => setSplit(Number(e.currentTarget.value))}
          />
        </figcaption>
      </figure>
      <figure className="compare-loupe">
        <div className="compare-loupe-pair">
          <span aria-hidden="true">
            <canvas ref={lRef} width={LOUPE} height={LOUPE} className="compare-loupe-canvas" />
            reference
          </span>
          <span aria-hidden="true">
            <canvas ref={lRender} width={LOUPE} height={LOUPE} className="compare-loupe-canvas" />
            render
          </span>
        </div>
        <figcaption aria-live="polite" data-testid="compare-loupe" data-pixel={`${at[0]},${at[1]}`}>
          Loupe at pixel ({at[0]}, {at[1]}), ×{LOUPE} pixels: reference {rgb(p.reference, k)}, render{' '}
          {rgb(p.render, k)} (8-bit sRGB); FLIP {p.errors ? formatNumber(p.errors[k], 3) : '(computing)'}
        </figcaption>
      </figure>
    </div>
  );
}
