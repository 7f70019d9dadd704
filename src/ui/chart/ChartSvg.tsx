/**
 * A laid-out chart (./model) drawn as one SVG, 1 user unit = 1 CSS px: grid, marks clipped to the
 * plot area, axes with their labels and titles, the legend, the colour bar, and the pointer's
 * readout and zoom box. Colours arrive resolved (no var()), so the SVG also stands alone when
 * saved as an image. Stateless: ../Plot.tsx owns the pointer, the zoom and the size.
 */
import { Fragment, memo, useId, type ReactNode, type Ref } from 'react';
import { coordText } from '../chartScale';
import { markerPath, type Rect, type Stroke, type Swatch } from './marks';
import type { ChartModel } from './model';

export interface ChartColors {
  fg: string;
  muted: string;
  grid: string;
  bg: string;
  /** A colour as drawn (var(--…) resolved). */
  paint: (c: string) => string;
}

export interface Readout {
  x: number;
  y: number;
  color: string;
  lines: string[];
}

const f = (v: number) => coordText(v, 1);

/** Text with <sub>…</sub> / <sup>…</sup> set as lowered / raised smaller spans. */
export function RichText({ text }: { text: string }): ReactNode {
  const parts = text.split(/(<su[bp]>.*?<\/su[bp]>)/g).filter(Boolean);
  if (parts.length === 1 && !/^<su[bp]>/.test(parts[0])) return text;
  return parts.map((p, k) => {
    const m = /^<(su[bp])>(.*)<\/su[bp]>$/.exec(p);
    if (!m) return <Fragment key={k}>{p}</Fragment>;
    return (
      <tspan key={k} baselineShift={m[1] === 'sub' ? 'sub' : 'super'} fontSize="75%">
        {m[2]}
      </tspan>
    );
  });
}

function strokeProps(s: Stroke, paint: (c: string) => string) {
  return { stroke: paint(s.color), strokeWidth: s.width, strokeDasharray: s.dash };
}

function SwatchMark({ s, x, y, paint }: { s: Swatch; x: number; y: number; paint: (c: string) => string }) {
  return (
    <>
      {s.box ? (
        <rect x={x + 4} y={y - 6} width={22} height={12} fill={paint(s.box.color)} opacity={s.box.opacity} />
      ) : null}
      {s.line ? <path d={`M${f(x)} ${f(y)}h30`} fill="none" {...strokeProps(s.line, paint)} /> : null}
      {s.marker ? (
        <path
          d={markerPath(s.marker.symbol, x + 15, y, Math.min(s.marker.size, 12))}
          fill={s.marker.fill === 'none' ? 'none' : paint(s.marker.fill)}
          {...(s.marker.stroke ? strokeProps(s.marker.stroke, paint) : {})}
        />
      ) : null}
    </>
  );
}

export interface ChartSvgProps {
  model: ChartModel;
  colors: ChartColors;
  /** Font sizes (px) of tick labels, of a log axis's 2s and 5s, and of titles and the legend. */
  tick: number;
  minorTick: number;
  font: number;
  readout?: Readout | null;
  /** The zoom box being dragged, or null. */
  zoomBox?: Rect | null;
  svgRef?: Ref<SVGSVGElement>;
}

export function ChartSvg({ model, colors, tick, minorTick, font, readout, zoomBox, svgRef }: ChartSvgProps) {
  const { width: W, height: H } = model;
  return (
    <svg
      ref={svgRef}
      className="chart"
      width={W}
      height={H}
      viewBox={`0 0 ${W} ${H}`}
      aria-hidden="true"
      fontSize={font}
      fill={colors.fg}
    >
      <ChartBody model={model} colors={colors} tick={tick} minorTick={minorTick} font={font} />
      {zoomBox ? (
        <rect
          className="chart-zoombox"
          {...zoomBox}
          fill={colors.muted}
          fillOpacity={0.15}
          stroke={colors.muted}
          strokeDasharray="4 3"
        />
      ) : null}
      {readout ? <ReadoutLabel r={readout} model={model} colors={colors} font={font} /> : null}
    </svg>
  );
}

/**
 * Everything but the readout and the zoom box: drawn again only for a new model, colours or font
 * sizes, not as the pointer moves.
 */
const ChartBody = memo(function ChartBody({
  model,
  colors,
  tick,
  minorTick,
  font,
}: Pick<ChartSvgProps, 'model' | 'colors' | 'tick' | 'minorTick' | 'font'>) {
  const clip = `chart-${useId().replace(/[^\w-]/g, '')}`;
  const { plot, x, y } = model;
  const { paint } = colors;
  const bottom = plot.y + plot.h;
  const right = plot.x + plot.w;
  return (
    <>
      <defs>
        <clipPath id={clip}>
          <rect x={plot.x} y={plot.y} width={plot.w} height={plot.h} />
        </clipPath>
        {model.colorbar ? (
          <linearGradient id={`${clip}-bar`} x1="0" y1="1" x2="0" y2="0">
            {model.colorbar.stops.map((s) => (
              <stop key={s.t} offset={s.t} stopColor={s.color} />
            ))}
          </linearGradient>
        ) : null}
      </defs>
      <g className="chart-grid" stroke={colors.grid} strokeWidth={1}>
        {y.ticks
          .filter((t) => !t.minor)
          .map((t) => (
            <path key={`y${t.px}`} d={`M${f(plot.x)} ${f(t.px)}H${f(right)}`} />
          ))}
        {x.ticks
          .filter((t) => !t.minor)
          .map((t) => (
            <path key={`x${t.px}`} d={`M${f(t.px)} ${f(plot.y)}V${f(bottom)}`} />
          ))}
      </g>
      <g clipPath={`url(#${clip})`}>
        {model.marks.map((m, k) => {
          switch (m.kind) {
            case 'cells':
              return (
                <g key={k} className="chart-cells">
                  {m.cells.map((c, j) => (
                    <rect key={j} x={f(c.x)} y={f(c.y)} width={f(c.w)} height={f(c.h)} fill={c.color} />
                  ))}
                </g>
              );
            case 'area':
              return (
                <path key={k} className="chart-area" d={m.d} fill={paint(m.color)} opacity={m.opacity} />
              );
            case 'line':
              return (
                <path
                  key={k}
                  className="chart-line"
                  d={m.d}
                  fill="none"
                  opacity={m.opacity}
                  strokeLinejoin="round"
                  {...strokeProps(m, paint)}
                />
              );
            case 'markers':
              return (
                <path
                  key={k}
                  className="chart-markers"
                  d={m.d}
                  fill={m.fill === 'none' ? 'none' : paint(m.fill)}
                  opacity={m.opacity}
                  {...(m.stroke ? strokeProps(m.stroke, paint) : {})}
                />
              );
          }
        })}
        {model.shapes.map((s, k) => (
          <path key={`s${k}`} className="chart-shape" d={s.d} fill="none" {...strokeProps(s, paint)} />
        ))}
      </g>
      <path
        className="chart-frame"
        d={`M${f(plot.x)} ${f(plot.y)}V${f(bottom)}H${f(right)}`}
        fill="none"
        stroke={colors.grid}
        strokeWidth={1}
      />
      <g className="chart-xticks" textAnchor="middle" fontSize={tick}>
        {x.ticks.map((t) => (
          <text key={t.px} x={f(t.px)} y={f(bottom + tick + 4)} fontSize={t.minor ? minorTick : undefined}>
            {t.label}
          </text>
        ))}
      </g>
      <g className="chart-yticks" textAnchor="end" fontSize={tick}>
        {y.ticks.map((t) => (
          <text
            key={t.px}
            x={f(plot.x - 6)}
            y={f(t.px + tick * 0.35)}
            fontSize={t.minor ? minorTick : undefined}
          >
            {t.label}
          </text>
        ))}
      </g>
      {model.xTitle ? (
        <text
          className="chart-xtitle"
          x={f(plot.x + plot.w / 2)}
          y={f(bottom + tick + 8 + font * 1.1)}
          textAnchor="middle"
        >
          <RichText text={model.xTitle} />
        </text>
      ) : null}
      {model.yTitle ? (
        <text
          className="chart-ytitle"
          x={0}
          y={0}
          textAnchor="middle"
          transform={`translate(${f(font * 0.95)} ${f(plot.y + plot.h / 2)}) rotate(-90)`}
        >
          <RichText text={model.yTitle} />
        </text>
      ) : null}
      {model.title ? (
        <text
          className="chart-title"
          x={f(model.title.x)}
          y={f(model.title.y)}
          textAnchor="middle"
          fontSize={font * 1.1}
        >
          <RichText text={model.title.text} />
        </text>
      ) : null}
      {model.legend.items.length ? (
        <g className="chart-legend">
          {model.legend.box ? <rect {...model.legend.box} fill={colors.bg} opacity={0.85} rx={3} /> : null}
          {model.legend.items.map((it, k) => (
            <g key={k}>
              <SwatchMark s={it.swatch} x={it.x} y={it.y} paint={paint} />
              <text x={f(it.x + 36)} y={f(it.y + font * 0.35)}>
                <RichText text={it.text} />
              </text>
            </g>
          ))}
        </g>
      ) : null}
      {model.colorbar ? (
        <g className="chart-colorbar" fontSize={tick}>
          <rect {...model.colorbar.r} fill={`url(#${clip}-bar)`} />
          {model.colorbar.ticks.map((t) => (
            <text key={t.px} x={f(model.colorbar!.r.x + model.colorbar!.r.w + 4)} y={f(t.px + tick * 0.35)}>
              {t.label}
            </text>
          ))}
        </g>
      ) : null}
    </>
  );
});

/** The readout: a ring on the point and its lines in a box beside it, kept inside the plot. */
function ReadoutLabel({
  r,
  model,
  colors,
  font,
}: {
  r: Readout;
  model: ChartModel;
  colors: ChartColors;
  font: number;
}) {
  const lineH = Math.ceil(font * 1.25);
  const chars = Math.max(...r.lines.map((l) => l.length));
  const w = Math.min(model.width - 8, chars * font * 0.56 + 14);
  const h = r.lines.length * lineH + 8;
  const { plot } = model;
  let bx = r.x + 12;
  if (bx + w > plot.x + plot.w) bx = r.x - 12 - w;
  bx = Math.max(2, bx);
  let by = r.y - h - 10;
  if (by < 2) by = r.y + 12;
  return (
    <g className="chart-readout" pointerEvents="none">
      <circle cx={f(r.x)} cy={f(r.y)} r={6} fill="none" stroke={colors.paint(r.color)} strokeWidth={2} />
      <rect
        x={f(bx)}
        y={f(by)}
        width={f(w)}
        height={h}
        rx={3}
        fill={colors.bg}
        stroke={colors.paint(r.color)}
      />
      {r.lines.map((l, k) => (
        <text key={k} x={f(bx + 7)} y={f(by + 4 + lineH * (k + 0.8))}>
          {l}
        </text>
      ))}
    </g>
  );
}
