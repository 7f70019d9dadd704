/**
 * The whole texture reconstructed with nearest and with bilinear filtering, side by side and
 * magnified, with the query marker. Canvases redraw only when the grid or the conventions change.
 */
import { memo, useEffect, useRef } from 'react';
import type { Filter } from '../../../core/texture';
import { textureImage } from '../textureImage';
import type { Crease } from '../creases';
import type { ShownTexture } from '../model';
import { useSeenOnce } from '../../../ui';
import { describeReconstruction } from './describe';
import './marks.css';
import './Reconstruction.css';

const RES = 256;

const FilterCanvas = memo(function FilterCanvas({
  grid,
  opts,
  range,
  filter,
}: ShownTexture & { filter: Filter }) {
  const ref = useRef<HTMLCanvasElement>(null);
  // Drawn once the figure comes near the screen (RES² lookups per filter: not first-screen work).
  const seen = useSeenOnce(ref);
  useEffect(() => {
    if (!seen) return;
    const c = ref.current;
    const g = c?.getContext('2d');
    if (!c || !g) return;
    const img = textureImage(grid, { ...opts, vflip: false }, filter, RES, RES, range);
    g.putImageData(new ImageData(img as Uint8ClampedArray<ArrayBuffer>, RES, RES), 0, 0);
  }, [seen, grid, opts, range, filter]);
  return (
    <canvas
      ref={ref}
      width={RES}
      height={RES}
      className={`tx-recon-canvas ${filter}`}
      data-testid={`recon-${filter}`}
      aria-hidden="true"
    />
  );
});

export const Reconstruction = memo(function Reconstruction({
  grid,
  opts,
  range,
  qu,
  qv,
  creases,
  drawRef,
}: ShownTexture & {
  /** The drawn query in the texture frame, [0, 1]². */
  qu: number;
  qv: number;
  /** Creases of the bilinear image (texture frame), drawn over it. */
  creases: Crease[];
  /** Set to a function that moves the query's crosses directly (per animation frame). */
  drawRef?: { current: ((qu: number, qv: number) => void) | null };
}) {
  const box = useRef<HTMLDivElement>(null);
  if (drawRef) {
    drawRef.current = (u, v) => {
      const tr = `translate(${u * 100} ${(1 - v) * 100})`;
      box.current?.querySelectorAll('.tx-query').forEach((g) => g.setAttribute('transform', tr));
    };
  }
  return (
    <div className="tx-recon" ref={box}>
      {(['nearest', 'bilinear'] as const).map((f) => (
        <figure key={f} className="tx-recon-fig">
          <div
            className="tx-recon-box"
            role="img"
            aria-label={describeReconstruction(f, range, qu, qv, creases.length)}
          >
            <FilterCanvas grid={grid} opts={opts} range={range} filter={f} />
            <svg viewBox="0 0 100 100" className="tx-recon-svg" aria-hidden="true">
              {f === 'bilinear'
                ? creases.map((c, k) =>
                    c.axis === 'u' ? (
                      <line
                        key={k}
                        x1={c.at * 100}
                        x2={c.at * 100}
                        y1={(1 - c.from) * 100}
                        y2={(1 - c.to) * 100}
                        className="tx-crease"
                      />
                    ) : (
                      <line
                        key={k}
                        y1={(1 - c.at) * 100}
                        y2={(1 - c.at) * 100}
                        x1={c.from * 100}
                        x2={c.to * 100}
                        className="tx-crease"
                      />
                    ),
                  )
                : null}
              <g className="tx-query small" transform={`translate(${qu * 100} ${(1 - qv) * 100})`}>
                <circle r={2.2} />
                <line x1={-5} x2={5} y1={0} y2={0} />
                <line y1={-5} y2={5} x1={0} x2={0} />
              </g>
            </svg>
          </div>
          <figcaption>
            {f === 'nearest'
              ? 'Nearest: piecewise constant, blocky'
              : 'Bilinear: continuous; dashed: its creases'}
          </figcaption>
        </figure>
      ))}
    </div>
  );
});
