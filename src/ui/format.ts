/** The views' door to the one number formatter, src/core/format.ts. */
export {
  formatCount,
  formatNumber,
  formatPlain,
  formatSignificant,
  type ExponentStyle,
} from '../core/format';
