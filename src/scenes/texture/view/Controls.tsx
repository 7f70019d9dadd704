/**
 * The scene's control panels: the query (what the exam's figure needs), and folded under it the
 * conventions and the texture's values (the exam's by default; the fold's summary says which are
 * in use).
 */
import { memo, useState } from 'react';
import type { SceneProps } from '../../../kit/scene';
import { EXAM_GRID_TEXT, parseGrid, type TextureGrid } from '../../../core/texture';
import { Panel, Select } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { bindControls } from '../../../ui/paramControls';
import { gridTextIfFits } from '../model';
import { settingsInUse } from '../settings';
import { GRID_TEXT_MAX, schema, type Preset, type TextureSchema } from '../params';
import './Controls.css';

type PresetChoice = 'exam' | 'custom' | Exclude<Preset, 'grid'>;

const PRESET_OPTIONS: { value: PresetChoice; label: string }[] = [
  { value: 'exam', label: 'The exam’s 5 × 5 grid' },
  { value: 'checker', label: 'Checkerboard' },
  { value: 'gradient', label: 'Gradient' },
  { value: 'random', label: 'Random (seeded)' },
];
const CUSTOM_OPTION: { value: PresetChoice; label: string } = {
  value: 'custom',
  label: 'Custom (grid text)',
};

const ALIGN_OPTIONS = [
  { value: 'corner', label: 'Corner nodes (exam)' },
  { value: 'center', label: 'Texel centres (GPU)' },
] as const;
const WRAP_OPTIONS = [
  { value: 'clamp', label: 'Clamp to edge' },
  { value: 'repeat', label: 'Repeat' },
  { value: 'mirror', label: 'Mirrored repeat' },
] as const;

type Props = Pick<SceneProps<TextureSchema>, 'params' | 'setParams'> & {
  grid: TextureGrid;
  /** Whether the grid is the exam's. */
  isExam: boolean;
  /** Called before the texture's values change (the cell being edited no longer applies). */
  onTexture: () => void;
};

export const Controls = memo(function Controls({ params, setParams, grid, isExam, onTexture }: Props) {
  const presetChoice: PresetChoice = params.preset === 'grid' ? (isExam ? 'exam' : 'custom') : params.preset;
  const presetOptions = presetChoice === 'custom' ? [...PRESET_OPTIONS, CUSTOM_OPTION] : PRESET_OPTIONS;
  const c = bindControls(schema, params, setParams);
  return (
    <>
      <Panel title="Query point and path" className="tx-panel-query">
        {(['u', 'v'] as const).map((k) =>
          c.slider(k, `${k} (the query at t = 0)`, { min: -2, max: 3, step: 0.001, testId: `${k}-slider` }),
        )}
        <p className="tx-small">
          Or click / drag on the grid; with the grid focused, arrow keys move the query (Shift: by 0.1).
        </p>
      </Panel>
      <Fold
        name="settings"
        className="tx-settings"
        summary={`Conventions and texture: ${settingsInUse(params, isExam)}`}
      >
        <Panel title="Conventions" className="tx-panel-conventions">
          {c.select('align', 'Where the values sit', ALIGN_OPTIONS, { testId: 'align-select' })}
          {c.toggle('vflip', 'Flip v: v′ = 1 − v (the key accepts it)', { testId: 'vflip-toggle' })}
          {c.select('wrap', 'Addressing outside [0, 1]', WRAP_OPTIONS, { testId: 'wrap-select' })}
        </Panel>
        <Panel title="Texture" className="tx-panel-texture">
          <Select
            label="Values"
            value={presetChoice}
            options={presetOptions}
            onChange={(x) => {
              onTexture();
              if (x === 'exam') setParams({ preset: 'grid', grid: EXAM_GRID_TEXT });
              else if (x !== 'custom') setParams({ preset: x });
            }}
            testId="preset-select"
          />
          {params.preset !== 'grid' ? (
            <>
              {c.number('size', 'Size N (N × N, 2 to 64)', { testId: 'size-field' })}
              {params.preset === 'random' ? (
                <button type="button" onClick={() => setParams({ seed: (params.seed + 1) % 4294967296 })}>
                  New random values (seed {params.seed + 1})
                </button>
              ) : null}
            </>
          ) : null}
          <GridText
            key={params.grid + params.preset}
            text={params.preset === 'grid' ? params.grid : (gridTextIfFits(grid) ?? '')}
            onApply={(t) => setParams({ preset: 'grid', grid: t })}
          />
        </Panel>
      </Fold>
    </>
  );
});

/** The grid as text (rows top to bottom); applies only text that parses, else says why. */
function GridText({ text, onApply }: { text: string; onApply: (t: string) => void }) {
  const [draft, setDraft] = useState(text);
  const [error, setError] = useState<string | null>(null);
  const apply = () => {
    const t = draft.trim();
    const r = parseGrid(t);
    if (!r.ok) {
      setError(r.message);
      return;
    }
    if (t.length > GRID_TEXT_MAX) {
      setError(`The text is longer than ${GRID_TEXT_MAX} characters, too long for a link.`);
      return;
    }
    setError(null);
    onApply(t);
  };
  return (
    <div className="field">
      <label className="field-label" htmlFor="tx-grid-text">
        Grid as text (rows top to bottom, “;” between rows, “,” between values)
      </label>
      <textarea
        id="tx-grid-text"
        className="tx-grid-text"
        data-testid="grid-text"
        rows={4}
        spellCheck={false}
        value={draft}
        aria-invalid={error ? true : undefined}
        onChange={(e) => setDraft(e.target.value)}
      />
      <button type="button" onClick={apply} data-testid="grid-apply">
        Use this grid
      </button>
      {error ? (
        <span className="field-error" role="alert" data-testid="grid-text-error">
          {error}
        </span>
      ) : null}
    </div>
  );
}
