/**
 * The unit square of (ξ₁, ξ₂): the first points of the chosen set and the 8 × 8 grid whose image
 * the 3D view draws on the hemisphere, in the same colours. Redrawn only when the inputs change.
 */
import { formatCount } from '../../../ui/format';
import { useEffect, useRef } from 'react';
import { fillSequence2D, type SequenceKind } from '../../../core/random';
import { runChunked } from '../../../ui/chunked';
import { xiColor, xiCss } from './colors';

const MAX_SHOWN = 4096;

export function UnitSquare({ kind, seed, n, size = 220 }: { kind: SequenceKind; seed: number; n: number; size?: number }) {
  const canvas = useRef<HTMLCanvasElement>(null);
  const shown = Math.min(n, MAX_SHOWN);
  useEffect(() => {
    const c = canvas.current;
    const g = c?.getContext('2d', { willReadFrequently: true });
    if (!c || !g) return;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const pad = 22;
    const s = size - 2 * pad;
    const fg = getComputedStyle(document.documentElement).getPropertyValue('--fg').trim() || '#222';
    const X = (a: number) => pad + a * s;
    const Y = (b: number) => pad + (1 - b) * s;
    // Drawn in two short tasks (the grid's 288 coloured strokes, then the points), each well under
    // a long task on a phone (issue 15).
    const drawGrid = () => {
      c.width = size * dpr; // (clears the canvas)
      c.height = size * dpr;
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
      // grid lines in the warp colours
      g.lineWidth = 1.5;
      for (let l = 0; l <= 8; l++) {
        const f = l / 8;
        for (let q = 0; q < 16; q++) {
          const t0 = q / 16;
          const t1 = (q + 1) / 16;
          g.strokeStyle = xiCss(f, (t0 + t1) / 2);
          g.beginPath();
          g.moveTo(X(f), Y(t0));
          g.lineTo(X(f), Y(t1));
          g.stroke();
          g.strokeStyle = xiCss((t0 + t1) / 2, f);
          g.beginPath();
          g.moveTo(X(t0), Y(f));
          g.lineTo(X(t1), Y(f));
          g.stroke();
        }
      }
    };
    const drawPoints = () => {
      const u = new Float64Array(2 * shown);
      fillSequence2D(kind, seed, n, u, 0, shown, 0);
      const r = shown > 1000 ? 1.2 : 2;
      // The points go straight into the pixels (one colour per point): a fillStyle string per point
      // for thousands of points was tens of ms of the page's load on a phone (issue 15).
      const W = c.width;
      const H = c.height;
      const img = g.getImageData(0, 0, W, H);
      const px = img.data;
      const rgb = new Uint8Array(3);
      for (let i = 0; i < shown; i++) {
        const a = u[2 * i]!;
        const b = u[2 * i + 1]!;
        xiColor(a, b, rgb);
        const x0 = Math.max(0, Math.round((X(a) - r) * dpr));
        const x1 = Math.min(W, Math.round((X(a) + r) * dpr));
        const y0 = Math.max(0, Math.round((Y(b) - r) * dpr));
        const y1 = Math.min(H, Math.round((Y(b) + r) * dpr));
        for (let y = y0; y < y1; y++) {
          for (let x = x0, k = (y * W + x0) * 4; x < x1; x++, k += 4) {
            px[k] = rgb[0]!;
            px[k + 1] = rgb[1]!;
            px[k + 2] = rgb[2]!;
            px[k + 3] = 255;
          }
        }
      }
      g.putImageData(img, 0, 0);
      g.strokeStyle = fg;
      g.lineWidth = 1;
      g.strokeRect(X(0), Y(1), s, s);
      // the first sample, which the 3D view and the worked example track
      if (shown > 0) {
        g.lineWidth = 2;
        g.beginPath();
        g.arc(X(u[0]!), Y(u[1]!), 6, 0, 2 * Math.PI);
        g.stroke();
      }
      g.fillStyle = fg;
      g.font = '12px sans-serif';
      g.fillText('ξ₁ →', X(1) - 30, Y(0) + 16);
      g.fillText('0', X(0) - 4, Y(0) + 16);
      g.fillText('1', X(1) - 4, Y(0) + 16);
      g.save();
      g.translate(X(0) - 8, Y(0.5));
      g.rotate(-Math.PI / 2);
      g.fillText('ξ₂ →', 0, 0);
      g.restore();
    };
    const cancelGrid = runChunked(drawGrid);
    const cancelPoints = runChunked(drawPoints);
    return () => {
      cancelGrid();
      cancelPoints();
    };
  }, [kind, seed, n, shown, size]);
  return (
    <figure className="hemi-square">
      <canvas
        ref={canvas}
        style={{ width: size, height: size }}
        role="img"
        aria-label={`The unit square of (ξ₁, ξ₂) with the first ${shown} points of the ${kind} set and the grid whose image is drawn on the hemisphere`}
      />
      <figcaption>
        (ξ₁, ξ₂): first {formatCount(shown)} {kind} points; each colour lands where the same colour appears on the hemisphere; the ringed point is the first sample.
      </figcaption>
    </figure>
  );
}
