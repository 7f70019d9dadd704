/** A group of readouts described by data, in the scene's readout grid. */
import { Readout, type ReadoutProps } from '../../../ui';

export function ReadoutList({ items, className }: { items: readonly ReadoutProps[]; className?: string }) {
  return (
    <div className={className ? `al-readouts ${className}` : 'al-readouts'}>
      {items.map((r) => (
        <Readout key={r.id} {...r} />
      ))}
    </div>
  );
}
