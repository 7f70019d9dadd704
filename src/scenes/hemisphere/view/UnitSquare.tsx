/**
 * The unit square of (ξ₁, ξ₂): the first points of the chosen set and the 8 × 8 grid whose image
 * the 3D view draws on the hemisphere, in the same colours. Redrawn only when the inputs change.
 */
import { formatCount } from '../../../ui/format';
import { useEffect, useRef } from 'react';
import { fillSequence2D, type SequenceKind } from '../../../core/random';
import { nextTask, runChunked } from '../../../ui/chunked';
import { xiColor } from './colors';

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
    const W = Math.round(size * dpr);
    const H = W;
    // Everything coloured goes straight into the pixels (grid segments and points, one colour each):
    // a stroke and a colour string per segment and per point was tens of ms of a phone's load
    // (issue 15). Two short tasks: the grid and the first half of the points, then the rest.
    const img = new ImageData(W, H);
    const px = img.data;
    const rgb = new Uint8Array(3);
    const fill = (x0: number, x1: number, y0: number, y1: number) => {
      const xa = Math.max(0, Math.round(x0 * dpr));
      const xb = Math.min(W, Math.round(x1 * dpr));
      const ya = Math.max(0, Math.round(y0 * dpr));
      const yb = Math.min(H, Math.round(y1 * dpr));
      for (let y = ya; y < yb; y++) {
        for (let x = xa, k = (y * W + xa) * 4; x < xb; x++, k += 4) {
          px[k] = rgb[0]!;
          px[k + 1] = rgb[1]!;
          px[k + 2] = rgb[2]!;
          px[k + 3] = 255;
        }
      }
    };
    const drawGrid = () => {
      // the 8 × 8 grid in the warp colours, 1.5 px wide, each line in 16 segments
      const half = 0.75;
      for (let l = 0; l <= 8; l++) {
        const f = l / 8;
        for (let q = 0; q < 16; q++) {
          const t0 = q / 16;
          const t1 = (q + 1) / 16;
          xiColor(f, (t0 + t1) / 2, rgb);
          fill(X(f) - half, X(f) + half, Y(t1), Y(t0));
          xiColor((t0 + t1) / 2, f, rgb);
          fill(X(t0), X(t1), Y(f) - half, Y(f) + half);
        }
      }
    };
    const u = new Float64Array(2 * shown);
    const r = shown > 1000 ? 1.2 : 2;
    const drawPoints = (from: number, to: number) => {
      if (from === 0) fillSequence2D(kind, seed, n, u, 0, shown, 0);
      for (let i = from; i < to; i++) {
        const a = u[2 * i]!;
        const b = u[2 * i + 1]!;
        xiColor(a, b, rgb);
        fill(X(a) - r, X(a) + r, Y(b) - r, Y(b) + r);
      }
    };
    const finish = () => {
      c.width = W; // (clears the canvas)
      c.height = H;
      g.putImageData(img, 0, 0);
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
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
    let alive = true;
    const mid = shown >> 1;
    const cancel = runChunked(() => {
      drawGrid();
      drawPoints(0, mid);
      nextTask(() => {
        if (!alive) return;
        drawPoints(mid, shown);
        finish();
      });
    });
    return () => {
      alive = false;
      cancel();
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
