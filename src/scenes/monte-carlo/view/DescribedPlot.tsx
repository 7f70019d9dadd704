/**
 * A Plot (src/ui/Plot.tsx) with its heading, its accessible name and description, and its data
 * as a "Show as table" under it. The fixed words come from ./plotText by the plot's id; `words`
 * are the ones that follow the data (./plotWords: the description, the table with a column per
 * series and, where it depends on the data, the caption). Test ids `${id}-plot` and `${id}-table`.
 */
import { Plot, ShowAsTable, type PlotTrace } from '../../../ui';
import { PLOT_TEXT, type PlotId, type PlotText } from './plotText';
import { Heading } from './plotStyle';

export interface PlotWords {
  description: string;
  table: { columns: string[]; rows: number[][] };
  caption?: string;
}

export function DescribedPlot({
  id,
  data,
  height,
  words,
}: {
  id: PlotId;
  data: PlotTrace[];
  height: number;
  words: PlotWords;
}) {
  const { heading, caption, ...plot }: PlotText = PLOT_TEXT[id];
  const { columns, rows } = words.table;
  return (
    <>
      {heading ? <Heading>{heading}</Heading> : null}
      <Plot {...plot} data={data} height={height} description={words.description} testId={`${id}-plot`} />
      <ShowAsTable
        caption={words.caption ?? caption ?? ''}
        columns={columns}
        rows={rows}
        testId={`${id}-table`}
      />
    </>
  );
}
