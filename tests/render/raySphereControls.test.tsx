/**
 * #/ray-sphere's controls as the page opens (react-dom/server: no link, so every fold is closed):
 * only the readouts' method is a control in view; the typed values and the settings beyond the
 * exam are folds whose fields are not rendered at all. On the classroom stage's drawer every
 * control is there, unfolded.
 */
import { describe, expect, it } from 'vitest';
import { renderToStaticMarkup } from 'react-dom/server';
import { parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/ray-sphere/params';
import { checkInputs } from '../../src/scenes/ray-sphere/inputs';
import { makeSweep } from '../../src/scenes/ray-sphere/sweep';
import { Q5Controls } from '../../src/scenes/ray-sphere/exam/Q5Controls';
import { activePresetOf } from '../../src/scenes/ray-sphere/exam/Q5Presets';

function controls(staged: boolean): string {
  const p = parseParams(schema, '').values;
  const sweep = makeSweep(checkInputs(p), p.sweep, p.extent);
  const noop = () => {};
  return renderToStaticMarkup(
    <Q5Controls
      {...{
        o: p.o,
        d: p.d,
        c: p.c,
        r: p.r,
        method: p.method,
        precision: p.precision,
        sweep,
        extent: p.extent,
      }}
      edit={noop}
      setParams={noop}
      active={activePresetOf(p)}
      staged={staged}
    />,
  );
}

/** The test ids of the fields, selects and buttons in the markup. */
const controlIds = (html: string) =>
  [...html.matchAll(/<(?:input|select|button)\b[^>]*data-testid="([^"]+)"/g)].map((m) => m[1]);

describe('ray-sphere controls', () => {
  it('on the page: the method in view, the typed values and the settings closed folds with nothing inside', () => {
    const html = controls(false);
    expect(controlIds(html)).toEqual(['method']);
    for (const name of ['values', 'more']) {
      const fold = html.match(new RegExp(`<details[^>]*data-fold="${name}"[^>]*>([\\s\\S]*?)</details>`));
      expect(fold, name).not.toBeNull();
      expect(fold![0]).not.toMatch(/<details[^>]*\bopen/);
      expect(fold![1]).toMatch(/^<summary[^>]*>[^<]+<\/summary>$/);
    }
  });

  it('in the classroom drawer: every control, unfolded', () => {
    const ids = controlIds(controls(true));
    for (const id of ['sweep-mode', 'sweep-extent', 'preset-two-hits', 'preset-far', 'method', 'precision'])
      expect(ids, id).toContain(id);
    for (const v of ['o', 'd', 'c'])
      for (const a of ['x', 'y', 'z']) expect(ids).toContain(`input-${v}-${a}`);
    expect(ids).toContain('input-r');
    expect(controls(true)).not.toContain('data-fold=');
  });
});
