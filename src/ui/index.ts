export {
  Readout,
  LiveReadout,
  readoutValue,
  readoutText,
  writeReadout,
  formatNumber,
  type ReadoutProps,
} from './Readout';
export { NumberField, Slider, Select, Toggle, ExprField, Panel, Notice, SceneLayout } from './controls';
export { Revealed, type RevealedProps } from './ask';
export { usePresent, isPresent } from './pageKeys';
export { keepTextParenthesesTogether } from './texBreaks';
export { MathTex, loadKatex, preloadMath } from './MathTex';
export { runChunked, nextTask } from './chunked';
export { Plot, type PlotTrace, type PlotLayout } from './Plot';
export type { Dash, LegendSpec, LineStyle, MarkerStyle, MarkerSymbol } from './chart/types';
export { useShortcuts, type ShortcutHandlers } from './shortcuts';
export { useSeenOnce, observeVisibility, touchOnly } from './useInView';
export {
  useTimeline,
  useTimelineFrame,
  useCoarsePosition,
  prefersReducedMotion,
  TEXT_HZ,
  type Timeline,
  type TimelineOptions,
  type TimelineListener,
} from './timeline';
export { TimelineTransport, type TimelineTransportProps } from './TimelineTransport';
export {
  AnimationDriver,
  createAnimationStore,
  createThrottle,
  heldPosition,
  lastValue,
  useAnimationDriver,
  useAnimFrame,
  useHeldWhile,
  usePlaying,
  useStillT,
  useThrottled,
  textGate,
  type AnimationDriverProps,
  type AnimationStore,
} from './animation';
export { ExamQuestion, ExamPart, Derivation, LiveAnswer, KeyNote, ExploreFurther } from './exam';
export { QuestionNav, questionHref } from './QuestionNav';
export { Deferred, useSectionWidth } from './Deferred';
export { useCompiled, type Compiled, type CompileOutcome } from './useCompiled';
export { announce, onAnnounce, recentAnnouncements, ANNOUNCE_GAP_MS, type Announcement } from './announce';
export { DescribedFigure, DESCRIBE_SETTLE_MS, type DescribedFigureProps } from './describe';
export { summarizeSeries, superscriptExponent, type SummaryOptions } from './summary';
export { ShowAsTable, type ShowAsTableProps } from './DataTable';
export { AudioTrace, type AudioTraceProps, type TraceEvent, type TraceEventKind } from './audioTrace';
export { SERIES, STRATEGY_COLOR, resolveColor } from './palette';
