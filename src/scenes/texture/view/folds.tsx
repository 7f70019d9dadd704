/**
 * The page's folded parts: each a <Fold> (closed until opened, remembered in the link's `open=`)
 * whose content is a lazy chunk, loaded only when the fold is first opened. The exam's parts, their
 * answers and the grid figure are never folded; these are what goes beyond them.
 *
 * - `path`: the path's shape and end, and the value along the path (./AlongPath);
 * - `edit`: editing the texture's values node by node (./FigureParts' CellEditor, on the page);
 * - `whole`: the whole texture under both filters, and where bilinear creases (./Explore);
 * - `seam`: the sphere's seam and poles (./Explore).
 */
import { lazy, type ComponentProps } from 'react';
import { Fold } from '../../../ui/Fold';
import { CellEditor } from './FigureParts';

const AlongPath = lazy(() => import('./AlongPath').then((m) => ({ default: m.AlongPath })));
const ReconstructionPanel = lazy(() => import('./Explore').then((m) => ({ default: m.ReconstructionPanel })));
const SeamPanel = lazy(() => import('./Explore').then((m) => ({ default: m.SeamPanel })));

/** The fold of the path's shape, its end and the value along it. */
export function PathFold(props: ComponentProps<typeof AlongPath>) {
  return (
    <Fold
      name="path"
      summary="The query’s path: its shape and end, and the value along it (plot, table, sound)"
      className="tx-fold"
    >
      <AlongPath {...props} />
    </Fold>
  );
}

/**
 * The fold of the cell editor (small: not a chunk of its own). While it is closed the grid is not
 * in editing mode, whatever the editor's switch says (the scene asks `useFoldOpen(EDIT_FOLD)`).
 */
export const EDIT_FOLD = 'edit';

export function EditFold(props: ComponentProps<typeof CellEditor>) {
  return (
    <Fold name={EDIT_FOLD} summary="Edit the texture’s values, node by node" className="tx-fold">
      <CellEditor {...props} />
    </Fold>
  );
}

/** The fold of the whole texture, reconstructed under both filters. */
export function WholeTextureFold(props: ComponentProps<typeof ReconstructionPanel>) {
  return (
    <Fold
      name="whole"
      summary="The whole texture under nearest and bilinear, and where bilinear creases"
      className="tx-fold"
    >
      <ReconstructionPanel {...props} />
    </Fold>
  );
}

/** The fold of the sphere's seam and poles. */
export function SeamFold(props: ComponentProps<typeof SeamPanel>) {
  return (
    <Fold
      name="seam"
      summary="The sphere’s seam and poles, and the sphere point’s bilinear steps"
      className="tx-fold"
    >
      <SeamPanel {...props} />
    </Fold>
  );
}
