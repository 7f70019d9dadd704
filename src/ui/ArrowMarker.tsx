/**
 * An SVG arrowhead `<marker>` (put it in the figure's `<defs>`; lines refer to it by
 * `markerEnd="url(#id)"`). It points along the line at its end and backwards at its start
 * (orient auto-start-reverse). The head is filled with `currentColor` unless `headClassName` styles it.
 */
export function ArrowMarker({
  id,
  size = 6,
  refX = 9,
  headClassName,
}: {
  id: string;
  /** width and height of the head, in the line's stroke widths */
  size?: number;
  /** where along the head (0 … 10) the line's end point sits */
  refX?: number;
  headClassName?: string;
}) {
  return (
    <marker
      id={id}
      viewBox="0 0 10 10"
      refX={refX}
      refY="5"
      markerWidth={size}
      markerHeight={size}
      orient="auto-start-reverse"
    >
      <path
        d="M0,0 L10,5 L0,10 z"
        className={headClassName}
        fill={headClassName ? undefined : 'currentColor'}
      />
    </marker>
  );
}
