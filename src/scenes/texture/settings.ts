/**
 * The scene's settings beyond the exam's question (where the values sit, the v-flip, the
 * addressing, the texture), in words: what the folded settings panel says it is set to while
 * closed, so a reader sees that a link changed them without opening it.
 */
import type { ParamValues } from '../../kit/params';
import type { TextureSchema } from './params';

type Settings = Pick<ParamValues<TextureSchema>, 'align' | 'vflip' | 'wrap' | 'preset' | 'size' | 'seed'>;

const WRAP_NAMES = { clamp: 'clamp to edge', repeat: 'repeat', mirror: 'mirrored repeat' } as const;
const PRESET_NAMES = { checker: 'checkerboard', gradient: 'gradient', random: 'random' } as const;

/**
 * "the exam’s" when every setting is the exam's, else each one that differs, e.g. "texel centres,
 * repeat, checkerboard 8 × 8". `isExam`: whether the grid given as text is the exam's.
 */
export function settingsInUse(s: Settings, isExam: boolean): string {
  const out: string[] = [];
  if (s.align === 'center') out.push('texel centres');
  if (s.vflip) out.push('v flipped');
  if (s.wrap !== 'clamp') out.push(WRAP_NAMES[s.wrap]);
  if (s.preset !== 'grid')
    out.push(
      `${PRESET_NAMES[s.preset]} ${s.size} × ${s.size}${s.preset === 'random' ? ` (seed ${s.seed})` : ''}`,
    );
  else if (!isExam) out.push('a grid of your own');
  return out.length ? out.join(', ') : 'the exam’s';
}
